#include "plugins/activity/CnnClassifier.h"

#include <QJsonArray>
#include <cmath>

namespace athlos::activity {

namespace {
QJsonArray floats(const std::vector<float>& v) {
    QJsonArray a;
    for (float x : v) a.append(double(x));
    return a;
}
}  // namespace

Expected<CnnClassifier> CnnClassifier::create(const QByteArray& onnx, int channels, int length, int classCount,
                                              std::vector<float> mean, std::vector<float> scale) {
    if (onnx.size() > kMaxOnnxBytes)
        return makeError(QStringLiteral("the ONNX network is %1 MB, above the limit of %2 MB for a window classifier")
                             .arg(double(onnx.size()) / 1e6, 0, 'f', 1)
                             .arg(double(kMaxOnnxBytes) / 1e6, 0, 'f', 0));
    if (onnx.isEmpty()) return makeError(QStringLiteral("the ONNX network is empty"));
    if (channels < 1 || channels > 64) return makeError(QStringLiteral("channels %1: expected 1 to 64").arg(channels));
    if (length < 8 || length > 100000)
        return makeError(QStringLiteral("window length %1 samples: expected 8 to 100000").arg(length));
    if (classCount < 2) return makeError(QStringLiteral("fewer than two classes"));
    if (int(mean.size()) != channels || int(scale.size()) != channels)
        return makeError(QStringLiteral("the normalisation has %1 means and %2 scales for %3 channels")
                             .arg(mean.size())
                             .arg(scale.size())
                             .arg(channels));
    for (std::size_t i = 0; i < mean.size(); ++i)
        if (!std::isfinite(mean[i]) || !std::isfinite(scale[i]) || !(scale[i] > 0))
            return makeError(QStringLiteral("the normalisation of channel %1 is not finite and positive").arg(i));
    CnnClassifier c;
    c.onnx_ = onnx;
    c.channels_ = channels;
    c.length_ = length;
    c.classCount_ = classCount;
    c.mean_ = std::move(mean);
    c.scale_ = std::move(scale);
    c.mutex_ = std::make_shared<std::mutex>();
    try {
        std::vector<uchar> buffer(onnx.begin(), onnx.end());
        c.net_ = std::make_shared<cv::dnn::Net>(cv::dnn::readNetFromONNX(buffer));
        if (c.net_->empty()) return makeError(QStringLiteral("cv::dnn read no layers from the ONNX network"));
        c.net_->setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
        c.net_->setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
    } catch (const cv::Exception& e) {
        return makeError(QStringLiteral("cv::dnn cannot read the ONNX network: %1").arg(QString::fromStdString(e.err)));
    }
    // A probe: two windows (zeros and a ramp) must give two rows of probabilities over classCount classes.
    cv::Mat probe(2, channels * length, CV_32F);
    for (int j = 0; j < probe.cols; ++j) {
        probe.at<float>(0, j) = c.mean_[std::size_t(j / length)];
        probe.at<float>(1, j) = float(j % length) / float(length);
    }
    cv::Mat out;
    if (Status s = c.probabilities(probe, out); !s) return s.error();
    if (out.rows != 2 || out.cols != classCount)
        return makeError(QStringLiteral("the network gives %1 outputs per window for %2 classes")
                             .arg(out.rows ? out.total() / std::size_t(out.rows) : 0)
                             .arg(classCount));
    for (int i = 0; i < out.rows; ++i) {
        double sum = 0;
        for (int k = 0; k < out.cols; ++k) {
            const float p = out.at<float>(i, k);
            if (!std::isfinite(p) || p < -1e-6f)
                return makeError(QStringLiteral("the network's outputs are not probabilities (end it with softmax)"));
            sum += p;
        }
        if (std::abs(sum - 1.0) > 1e-3)
            return makeError(
                QStringLiteral("the network's outputs sum to %1, not 1 (end it with softmax)").arg(sum, 0, 'g', 4));
    }
    return c;
}

Expected<CnnClassifier> CnnClassifier::fromJson(const QByteArray& onnx, const QJsonObject& json, int channels,
                                                int classCount) {
    std::vector<float> mean, scale;
    for (const auto& v : json.value(QStringLiteral("mean")).toArray()) mean.push_back(float(v.toDouble(NAN)));
    for (const auto& v : json.value(QStringLiteral("scale")).toArray()) scale.push_back(float(v.toDouble(NAN)));
    return create(onnx, channels, json.value(QStringLiteral("length")).toInt(), classCount, std::move(mean),
                  std::move(scale));
}

QJsonObject CnnClassifier::toJson() const {
    return {{QStringLiteral("length"), length_},
            {QStringLiteral("channels"), channels_},
            {QStringLiteral("mean"), floats(mean_)},
            {QStringLiteral("scale"), floats(scale_)},
            {QStringLiteral("input_layout"), QStringLiteral("N x C x 1 x L")}};
}

Status CnnClassifier::probabilities(const cv::Mat& windows, cv::Mat& out) const {
    if (windows.cols != channels_ * length_ || windows.type() != CV_32F)
        return makeError(QStringLiteral("windows of %1 values, the network reads %2 × %3")
                             .arg(windows.cols)
                             .arg(channels_)
                             .arg(length_));
    out.create(windows.rows, classCount_, CV_32F);
    if (windows.rows == 0) return {};
    // Batches bound the memory of the intermediate blobs.
    constexpr int kBatch = 256;
    try {
        std::lock_guard lock(*mutex_);
        for (int first = 0; first < windows.rows; first += kBatch) {
            const int n = std::min(kBatch, windows.rows - first);
            const int shape[] = {n, channels_, 1, length_};
            cv::Mat blob(4, shape, CV_32F);
            auto* dst = blob.ptr<float>();
            for (int i = 0; i < n; ++i) {
                const float* src = windows.ptr<float>(first + i);
                for (int ch = 0; ch < channels_; ++ch) {
                    const float m = mean_[std::size_t(ch)], s = scale_[std::size_t(ch)];
                    for (int j = 0; j < length_; ++j, ++dst) *dst = (src[ch * length_ + j] - m) / s;
                }
            }
            net_->setInput(blob);
            cv::Mat y = net_->forward();
            if (y.total() != std::size_t(n) * std::size_t(classCount_))
                return makeError(QStringLiteral("the network gives %1 outputs per window for %2 classes")
                                     .arg(y.total() / std::size_t(n))
                                     .arg(classCount_));
            y.reshape(1, n).copyTo(out.rowRange(first, first + n));
        }
    } catch (const cv::Exception& e) {
        return makeError(QStringLiteral("cv::dnn cannot run the network: %1").arg(QString::fromStdString(e.err)));
    }
    return {};
}

}  // namespace athlos::activity
