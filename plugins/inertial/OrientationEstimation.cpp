#include "plugins/inertial/OrientationEstimation.h"

namespace athlos::inertial {

QStringList orientationAlgorithmNames() {
    return {QStringLiteral("vqf"), QStringLiteral("strapdown"), QStringLiteral("madgwick"), QStringLiteral("mahony"),
            QStringLiteral("kalman")};
}

Expected<OrientationAlgorithm> parseOrientationAlgorithm(const QString& name) {
    const int i = orientationAlgorithmNames().indexOf(name);
    if (i < 0)
        return makeError(QStringLiteral("algorithm: unknown '%1' (use one of %2)")
                             .arg(name, orientationAlgorithmNames().join(QStringLiteral(", "))));
    return static_cast<OrientationAlgorithm>(i);
}

QString orientationAlgorithmName(OrientationAlgorithm algorithm) {
    return orientationAlgorithmNames().at(static_cast<int>(algorithm));
}

namespace {
template <class Filter>
bool runChunked(Filter& filter, const ImuBatch& in, OrientationTrack& out,
                const std::function<bool(double)>& keepGoing) {
    constexpr std::size_t chunk = 1 << 16;
    out.resize(in.rows);
    for (std::size_t b = 0; b < in.rows; b += chunk) {
        if (keepGoing && !keepGoing(static_cast<double>(b) / static_cast<double>(in.rows))) return false;
        runRange(filter, in, out, b, std::min(in.rows, b + chunk));
    }
    return true;
}
}  // namespace

OrientationRun estimateOrientation(const OrientationOptions& o, const ImuBatch& batch, double ts,
                                   const std::function<bool(double)>& keepGoing) {
    ImuBatch in = batch;
    if (!o.useMagnetometer) in.mag = nullptr;
    OrientationRun run;
    bool done = false;
    switch (o.algorithm) {
        case OrientationAlgorithm::Vqf: {
            if (o.offline) {
                OfflineOrientation::Params p = o.offlineParams;
                p.filter = o.filter;
                OfflineOrientation f(ts, p);
                done = f.updateBatch(in, run.track, keepGoing);
                break;
            }
            OrientationFilter f(ts, o.filter);
            done = runChunked(f, in, run.track, keepGoing);
            break;
        }
        case OrientationAlgorithm::Strapdown: {
            Strapdown f(ts);
            done = runChunked(f, in, run.track, keepGoing);
            break;
        }
        case OrientationAlgorithm::Madgwick: {
            Madgwick f(ts, o.madgwick);
            done = runChunked(f, in, run.track, keepGoing);
            break;
        }
        case OrientationAlgorithm::Mahony: {
            Mahony f(ts, o.mahony);
            done = runChunked(f, in, run.track, keepGoing);
            break;
        }
        case OrientationAlgorithm::Kalman: {
            QuaternionKalman f(ts, o.kalman);
            done = runChunked(f, in, run.track, keepGoing);
            break;
        }
    }
    run.cancelled = !done;
    return run;
}

}  // namespace athlos::inertial
