#include "plugins/positioning/TrackGapBridge.h"

#include "core/math/Angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace athlos::positioning {

TrackGapBridge::TrackGapBridge(TrackConstraintParams constraint, Params params) : field_(constraint), params_(params) {}

int TrackGapBridge::apply(const PositionSamples& in, PositionFilterResult& result) const {
    if (!field_.track() || result.t.size() < 3 || result.outlier.size() != in.t.size()) return 0;
    std::vector<double> accepted;
    for (std::size_t i = 0; i < in.t.size(); ++i)
        if (!result.outlier[i]) accepted.push_back(in.t[i]);
    int bridged = 0;
    for (std::size_t k = 1; k < accepted.size(); ++k) {
        const double tA = accepted[k - 1], tB = accepted[k];
        if (tB - tA < params_.minGap) continue;
        // Output a = last at or before the gap's start, b = first at or after its end.
        const auto after = std::upper_bound(result.t.begin(), result.t.end(), tA);
        if (after == result.t.begin()) continue;
        const std::size_t a = std::size_t(after - result.t.begin()) - 1;
        const std::size_t b = std::size_t(std::lower_bound(result.t.begin(), result.t.end(), tB) - result.t.begin());
        if (b >= result.t.size() || b <= a + 1) continue;
        if (bridge(result, a, b)) ++bridged;
    }
    return bridged;
}

double TrackGapBridge::stretch(double s, double d) const {
    constexpr double h = 0.05;  // m of arc: exact on straights and bends, an average across a joint
    const TrackGeometry& track = *field_.track();
    return (track.pointAt(s + h, d).position - track.pointAt(s - h, d).position).norm() / (2.0 * h);
}

bool TrackGapBridge::bridge(PositionFilterResult& r, std::size_t a, std::size_t b) const {
    const TrackGeometry& track = *field_.track();
    const Kinematics& A = r.states[a];
    const Kinematics& B = r.states[b];
    const TrackQuery qa = track.query({A.x, A.y}), qb = track.query({B.x, B.y});
    auto onTrack = [&](const TrackQuery& q) { return q.d >= field_.lowest() && q.d <= field_.highest(); };
    if (!onTrack(qa) || !onTrack(qb)) return false;
    const double sign = std::abs(math::wrapAngle(A.heading - qa.heading)) > std::numbers::pi / 2 ? -1.0 : 1.0;
    const double T = r.t[b] - r.t[a];
    // End rates in arc length of the reference line (s per second).
    double m0 = std::max(A.speed, 0.0) / stretch(qa.s, qa.d);
    double m1 = std::max(B.speed, 0.0) / stretch(qb.s, qb.d);
    double ds = sign * (qb.s - qa.s);
    const bool closed = track.kind() == TrackGeometry::Kind::Oval || track.polylineParams().closed;
    if (closed) {
        const double lap = track.referenceLength();
        ds = std::fmod(ds, lap);
        if (ds < 0.0) ds += lap;
        ds += lap * std::max(0.0, std::round((0.5 * (m0 + m1) * T - ds) / lap));
    }
    if (!(ds > 0.0)) return false;
    // Fritsch–Carlson: end slopes within the circle of radius 3 (in units of the mean rate) keep s(t) monotone.
    const double mean = ds / T, norm2 = (m0 * m0 + m1 * m1) / (mean * mean);
    if (norm2 > 9.0) {
        const double scale = 3.0 / std::sqrt(norm2);
        m0 *= scale;
        m1 *= scale;
    }
    for (std::size_t k = a + 1; k < b; ++k) {
        const double u = (r.t[k] - r.t[a]) / T, u2 = u * u, u3 = u2 * u;
        // Cubic Hermite basis (s(0) = 0, s(T) = ds, s'(0) = m0, s'(T) = m1) and its derivatives.
        const double s = (u3 - 2 * u2 + u) * T * m0 + (-2 * u3 + 3 * u2) * ds + (u3 - u2) * T * m1;
        const double sDot = (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * ds / T + (3 * u2 - 2 * u) * m1;
        const double sDdot = ((6 * u - 4) * m0 + (-12 * u + 6) * ds / T + (6 * u - 2) * m1) / T;
        const double d = qa.d + u * (qb.d - qa.d);
        const double sTrack = qa.s + sign * s;
        const TrackPoint p = track.pointAt(sTrack, d);
        const double g = stretch(sTrack, d);
        Kinematics& K = r.states[k];
        K.x = p.position.x();
        K.y = p.position.y();
        K.speed = sDot * g;
        K.accel = sDdot * g;
        K.heading = sign > 0 ? p.heading : math::wrapAngle(p.heading + std::numbers::pi);
        K.turnRate = sign * K.speed * p.curvature;
    }
    return true;
}

}  // namespace athlos::positioning
