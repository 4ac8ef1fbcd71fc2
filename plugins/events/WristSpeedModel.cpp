#include "plugins/events/WristSpeedModel.h"

#include <Eigen/Dense>
#include <opencv2/core.hpp>

#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::events {

namespace {

WristFeatures zScore(const WristFeatures& x, const WristFeatures& mean, const WristFeatures& scale) {
    WristFeatures z{};
    for (int i = 0; i < kWristSpeedFeatures; ++i) z[i] = (x[i] - mean[i]) / scale[i];
    return z;
}

// Least squares v = b0 + b·z with a small ridge on the slopes.
std::array<double, kWristSpeedFeatures + 1> fitLinear(const std::vector<WristFeatures>& z, const std::vector<double>& v,
                                                      const std::vector<int>& rows, double ridge) {
    const auto n = Eigen::Index(rows.size());
    Eigen::MatrixXd a(n, kWristSpeedFeatures + 1);
    Eigen::VectorXd b(n);
    for (Eigen::Index r = 0; r < n; ++r) {
        const auto k = std::size_t(rows[std::size_t(r)]);
        a(r, 0) = 1.0;
        for (int i = 0; i < kWristSpeedFeatures; ++i) a(r, i + 1) = z[k][std::size_t(i)];
        b(r) = v[k];
    }
    Eigen::MatrixXd normal = a.transpose() * a;
    for (int i = 1; i <= kWristSpeedFeatures; ++i) normal(i, i) += ridge * double(n);
    const Eigen::VectorXd x = normal.ldlt().solve(a.transpose() * b);
    std::array<double, kWristSpeedFeatures + 1> out{};
    for (int i = 0; i <= kWristSpeedFeatures; ++i) out[std::size_t(i)] = x(i);
    return out;
}

QJsonArray toArray(const double* v, int n) {
    QJsonArray a;
    for (int i = 0; i < n; ++i) a.append(v[i]);
    return a;
}

bool fromArray(const QJsonValue& value, double* out, int n) {
    const QJsonArray a = value.toArray();
    if (a.size() != n) return false;
    for (int i = 0; i < n; ++i) {
        if (!a[i].isDouble()) return false;
        out[i] = a[i].toDouble();
    }
    return true;
}

}  // namespace

WristFeatures wristSpeedFeatures(const CadenceWindow& window, double pressureLate, double pressureEarly,
                                 double height) {
    return {window.normMax * window.normStd, window.cadence, pressureLate - pressureEarly, height};
}

double interpolateAt(const std::vector<double>& t, const double* y, std::size_t stride, double at) {
    if (t.empty() || !(at >= t.front()) || !(at <= t.back())) return std::numeric_limits<double>::quiet_NaN();
    const auto hi = std::size_t(std::lower_bound(t.begin(), t.end(), at) - t.begin());
    if (hi == 0) return y[0];
    const std::size_t lo = hi - 1;
    const double w = (at - t[lo]) / (t[hi] - t[lo]);
    return (1.0 - w) * y[lo * stride] + w * y[hi * stride];
}

std::vector<WristFeatures> wristSpeedFeatureRows(const std::vector<CadenceWindow>& windows,
                                                 const std::vector<double>& tBaro, const double* pressure,
                                                 std::size_t stride, double height, std::vector<std::size_t>& rows) {
    std::vector<WristFeatures> out;
    rows.clear();
    for (std::size_t k = 0; k < windows.size(); ++k) {
        const CadenceWindow& w = windows[k];
        if (!w.walking || !std::isfinite(w.cadence)) continue;
        // eq. 12.6: x3 = p(t − 0.5) − p(t − 9.5), over nine seconds to reduce the sensor noise.
        const double late = interpolateAt(tBaro, pressure, stride, w.tEnd - 0.5);
        const double early = interpolateAt(tBaro, pressure, stride, w.tEnd - 9.5);
        if (!std::isfinite(late) || !std::isfinite(early)) continue;
        out.push_back(wristSpeedFeatures(w, late, early, height));
        rows.push_back(k);
    }
    return out;
}

WristSpeedModel WristSpeedModel::train(const std::vector<WristFeatures>& x, const std::vector<double>& v,
                                       const WristSpeedModelParams& params, QString* error) {
    WristSpeedModel m;
    const std::size_t n = x.size();
    if (n != v.size() || int(n) < 4 * params.clusters || params.clusters < 1) {
        if (error)
            *error = QStringLiteral("%1 training windows for %2 clusters (at least %3 needed)")
                         .arg(n)
                         .arg(params.clusters)
                         .arg(4 * params.clusters);
        return m;
    }
    for (int i = 0; i < kWristSpeedFeatures; ++i) {
        double s = 0.0, q = 0.0;
        for (const auto& r : x) s += r[std::size_t(i)];
        m.mean_[std::size_t(i)] = s / double(n);
        for (const auto& r : x)
            q += (r[std::size_t(i)] - m.mean_[std::size_t(i)]) * (r[std::size_t(i)] - m.mean_[std::size_t(i)]);
        // A constant feature (one walker's height) keeps scale 1: it then shifts, never divides by 0.
        const double sd = std::sqrt(q / double(n));
        m.scale_[std::size_t(i)] = sd > 1e-9 ? sd : 1.0;
    }
    std::vector<WristFeatures> z(n);
    cv::Mat samples(int(n), kWristSpeedFeatures, CV_32F);
    for (std::size_t k = 0; k < n; ++k) {
        z[k] = zScore(x[k], m.mean_, m.scale_);
        for (int i = 0; i < kWristSpeedFeatures; ++i) samples.at<float>(int(k), i) = float(z[k][std::size_t(i)]);
    }
    cv::Mat labels, centers;
    cv::theRNG().state = params.seed;  // deterministic k-means++ seeding
    cv::kmeans(samples, params.clusters, labels,
               cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 200, 1e-6), 5, cv::KMEANS_PP_CENTERS,
               centers);
    std::vector<int> all(n);
    for (std::size_t k = 0; k < n; ++k) all[k] = int(k);
    const auto global = fitLinear(z, v, all, params.ridge);
    for (int c = 0; c < params.clusters; ++c) {
        WristFeatures centroid{};
        for (int i = 0; i < kWristSpeedFeatures; ++i) centroid[std::size_t(i)] = centers.at<float>(c, i);
        std::vector<int> rows;
        for (std::size_t k = 0; k < n; ++k)
            if (labels.at<int>(int(k)) == c) rows.push_back(int(k));
        m.centroids_.push_back(centroid);
        m.coef_.push_back(int(rows.size()) >= params.minClusterRows ? fitLinear(z, v, rows, params.ridge) : global);
    }
    double sq = 0.0;
    for (std::size_t k = 0; k < n; ++k) sq += std::pow(m.predict(x[k]) - v[k], 2);
    m.trainingRmse = std::sqrt(sq / double(n));
    m.trainingRows = int(n);
    return m;
}

int WristSpeedModel::cluster(const WristFeatures& x) const {
    const WristFeatures z = zScore(x, mean_, scale_);
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < centroids_.size(); ++c) {
        double d = 0.0;
        for (int i = 0; i < kWristSpeedFeatures; ++i)
            d += std::pow(z[std::size_t(i)] - centroids_[c][std::size_t(i)], 2);
        if (d < bestD) {
            bestD = d;
            best = int(c);
        }
    }
    return best;
}

double WristSpeedModel::predict(const WristFeatures& x) const {
    const int c = cluster(x);
    if (c < 0) return std::numeric_limits<double>::quiet_NaN();
    const WristFeatures z = zScore(x, mean_, scale_);
    const auto& b = coef_[std::size_t(c)];
    double v = b[0];
    for (int i = 0; i < kWristSpeedFeatures; ++i) v += b[std::size_t(i) + 1] * z[std::size_t(i)];
    return v;
}

QJsonObject WristSpeedModel::toJson() const {
    QJsonArray centroids, coefficients;
    for (const auto& c : centroids_) centroids.append(toArray(c.data(), kWristSpeedFeatures));
    for (const auto& b : coef_) coefficients.append(toArray(b.data(), kWristSpeedFeatures + 1));
    return QJsonObject{
        {QStringLiteral("features"), QJsonArray{QStringLiteral("max_x_std"), QStringLiteral("cadence"),
                                                QStringLiteral("pressure_change"), QStringLiteral("height")}},
        {QStringLiteral("feature_units"),
         QJsonArray{QStringLiteral("m^2/s^4"), QStringLiteral("steps/min"), QStringLiteral("Pa"), QStringLiteral("m")}},
        {QStringLiteral("mean"), toArray(mean_.data(), kWristSpeedFeatures)},
        {QStringLiteral("scale"), toArray(scale_.data(), kWristSpeedFeatures)},
        {QStringLiteral("centroids"), centroids},
        {QStringLiteral("coefficients"), coefficients},
        {QStringLiteral("training_rmse"), trainingRmse},
        {QStringLiteral("training_rows"), trainingRows}};
}

WristSpeedModel WristSpeedModel::fromJson(const QJsonObject& json, QString* error) {
    WristSpeedModel m;
    auto fail = [&](const QString& what) {
        if (error) *error = what;
        return WristSpeedModel{};
    };
    if (!fromArray(json.value(QStringLiteral("mean")), m.mean_.data(), kWristSpeedFeatures) ||
        !fromArray(json.value(QStringLiteral("scale")), m.scale_.data(), kWristSpeedFeatures))
        return fail(QStringLiteral("'mean' and 'scale' must be arrays of %1 numbers").arg(kWristSpeedFeatures));
    for (double s : m.scale_)
        if (!(s > 0.0) || !std::isfinite(s)) return fail(QStringLiteral("'scale' must be positive"));
    const QJsonArray centroids = json.value(QStringLiteral("centroids")).toArray();
    const QJsonArray coefficients = json.value(QStringLiteral("coefficients")).toArray();
    if (centroids.isEmpty() || centroids.size() != coefficients.size())
        return fail(QStringLiteral("'centroids' and 'coefficients' must be non-empty arrays of the same length"));
    for (qsizetype c = 0; c < centroids.size(); ++c) {
        WristFeatures centroid{};
        std::array<double, kWristSpeedFeatures + 1> b{};
        if (!fromArray(centroids[c], centroid.data(), kWristSpeedFeatures) ||
            !fromArray(coefficients[c], b.data(), kWristSpeedFeatures + 1))
            return fail(QStringLiteral("cluster %1: centroid or coefficients malformed").arg(c));
        m.centroids_.push_back(centroid);
        m.coef_.push_back(b);
    }
    m.trainingRmse = json.value(QStringLiteral("training_rmse")).toDouble();
    m.trainingRows = json.value(QStringLiteral("training_rows")).toInt();
    return m;
}

}  // namespace athlos::events
