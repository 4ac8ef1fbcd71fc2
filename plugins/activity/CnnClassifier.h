#pragma once
// The 1D CNN classifier (seed 000 §5.2, digest §8: the DCNN conv 8×32 → max-pool 4/2 → conv 16×16 →
// max-pool 6/4 → FC 64 → FC 64 → softmax) run from ONNX through OpenCV dnn. The network is trained
// outside Athlos (scripts/train_cnn.py on windows exported by `athlos train --export-windows`) and
// imported with its classes and per-channel normalisation; a project stores the ONNX bytes, which
// only cv::dnn parses (an ONNX graph is data: operators from a fixed set, no code).
//
// Input: N × C × 1 × L (the 1D convolutions are exported as 2D ones with 1 × k kernels, which every
// OpenCV 4.x ONNX importer reads); output N × K class probabilities (the network ends in softmax).
#include "core/util/Expected.h"

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include <QByteArray>
#include <QJsonObject>
#include <memory>
#include <mutex>
#include <vector>

namespace athlos::activity {

class CnnClassifier {
public:
    // The thesis's DCNN is ~100 kB; 32 MiB leaves room for wider variants while refusing anything that
    // is not a small window classifier before cv::dnn sees it.
    static constexpr qsizetype kMaxOnnxBytes = 32LL * 1024 * 1024;

    // Parses and checks the network: size limit, cv::dnn import, one forward pass on a batch of two
    // windows that must give two rows of `classCount` probabilities (finite, summing to 1).
    static Expected<CnnClassifier> create(const QByteArray& onnx, int channels, int length, int classCount,
                                          std::vector<float> mean, std::vector<float> scale);
    // From the "cnn" object of a model description (length, mean, scale).
    static Expected<CnnClassifier> fromJson(const QByteArray& onnx, const QJsonObject& json, int channels,
                                            int classCount);
    QJsonObject toJson() const;

    // windows: N rows of C × L raw floats (rawWindow); normalised here ((x − mean_c) / scale_c).
    // out: N × K CV_32F probabilities.
    Status probabilities(const cv::Mat& windows, cv::Mat& out) const;

    const QByteArray& onnx() const { return onnx_; }
    int channels() const { return channels_; }
    int length() const { return length_; }
    int classCount() const { return classCount_; }

private:
    QByteArray onnx_;
    int channels_ = 0, length_ = 0, classCount_ = 0;
    std::vector<float> mean_, scale_;
    // cv::dnn::Net::forward is not const and not reentrant: one network per classifier, serialised.
    std::shared_ptr<cv::dnn::Net> net_;
    std::shared_ptr<std::mutex> mutex_;
};

}  // namespace athlos::activity
