#pragma once
// One entry point for all orientation algorithms, used by the `orientation` processor, the
// evaluation tool, tests and benchmarks.
#include "core/util/Expected.h"
#include "plugins/inertial/Baselines.h"
#include "plugins/inertial/OfflineOrientation.h"
#include "plugins/inertial/OrientationFilter.h"

#include <QStringList>
#include <functional>

namespace athlos::inertial {

enum class OrientationAlgorithm { Vqf, Strapdown, Madgwick, Mahony, Kalman };

QStringList orientationAlgorithmNames();  // "vqf", "strapdown", "madgwick", "mahony", "kalman"
Expected<OrientationAlgorithm> parseOrientationAlgorithm(const QString& name);
QString orientationAlgorithmName(OrientationAlgorithm algorithm);

struct OrientationOptions {
    OrientationAlgorithm algorithm = OrientationAlgorithm::Vqf;
    bool useMagnetometer = true;  // 9D; false = 6D (in.mag is ignored)
    OrientationFilter::Params filter;
    // vqf only: estimate from the whole recording (forward–backward smoothing, OfflineOrientation)
    // instead of sample by sample.
    bool offline = false;
    OfflineOrientation::Params offlineParams;  // its .filter is replaced by `filter`
    Madgwick::Params madgwick;
    Mahony::Params mahony;
    QuaternionKalman::Params kalman;
};

// Runs the chosen algorithm over the batch with nominal sampling interval ts (s). `keepGoing` is
// called with the fraction done every chunk; returning false stops early (result then incomplete,
// cancelled = true).
struct OrientationRun {
    OrientationTrack track;
    bool cancelled = false;
};
OrientationRun estimateOrientation(const OrientationOptions& options, const ImuBatch& in, double ts,
                                   const std::function<bool(double)>& keepGoing = {});

}  // namespace athlos::inertial
