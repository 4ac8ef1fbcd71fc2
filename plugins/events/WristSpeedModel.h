#pragma once
// Walking speed from wrist features (Fasel et al. 2017, thesis ch. 12.2.3, eq. 12.6–12.7): per
// cadence window the features x1 = max(W)·std(W) of the acceleration norm, x2 = cadence, x3 =
// p(t − 0.5) − p(t − 9.5) the barometric pressure change over the last 9 s (t the window's end),
// x4 = the walker's height. The feature space (z-scored) is partitioned by k-means into 16 clusters
// (cv::kmeans, k-means++ seeding); each cluster has its own linear model v = b0 + b·x fitted by
// least squares (Eigen), and a window uses the model of its nearest centroid (eq. 12.7).
#include "plugins/events/WristCadence.h"

#include <QJsonObject>
#include <array>
#include <vector>

namespace athlos::events {

constexpr int kWristSpeedFeatures = 4;
using WristFeatures = std::array<double, kWristSpeedFeatures>;

// Features of one walking window; pressure(t) in Pa (NaN when no barometer sample is near).
WristFeatures wristSpeedFeatures(const CadenceWindow& window, double pressureLate, double pressureEarly, double height);

// Linear interpolation of y(t) at t (t strictly increasing); NaN outside [t.front(), t.back()].
double interpolateAt(const std::vector<double>& t, const double* y, std::size_t stride, double at);

// Features of every walking window (cadence finite): pressure change over [tEnd − 9.5, tEnd − 0.5].
// `rows` receives the index of each window used.
std::vector<WristFeatures> wristSpeedFeatureRows(const std::vector<CadenceWindow>& windows,
                                                 const std::vector<double>& tBaro, const double* pressure,
                                                 std::size_t stride, double height, std::vector<std::size_t>& rows);

struct WristSpeedModelParams {
    int clusters = 16;        // thesis: 16
    int minClusterRows = 12;  // a cluster with fewer training rows uses the global linear model
    double ridge = 1e-3;      // Tikhonov weight (per row) on the slopes, for nearly flat clusters
    unsigned seed = 1;        // k-means++ seeding
};

class WristSpeedModel {
public:
    // Fits the model; rows x with reference speeds v (m/s). Fails when there are fewer rows than
    // 4 per cluster.
    static WristSpeedModel train(const std::vector<WristFeatures>& x, const std::vector<double>& v,
                                 const WristSpeedModelParams& params, QString* error = nullptr);
    bool valid() const { return !centroids_.empty(); }
    double predict(const WristFeatures& x) const;
    int cluster(const WristFeatures& x) const;

    QJsonObject toJson() const;
    static WristSpeedModel fromJson(const QJsonObject& json, QString* error);

    double trainingRmse = 0.0;  // m/s, fit on the training rows
    int trainingRows = 0;

private:
    WristFeatures mean_{}, scale_{};
    std::vector<WristFeatures> centroids_;                           // z-scored
    std::vector<std::array<double, kWristSpeedFeatures + 1>> coef_;  // b0, b1..b4 on z-scored features
};

}  // namespace athlos::events
