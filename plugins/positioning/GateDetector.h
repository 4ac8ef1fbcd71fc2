#pragma once
// Gate crossings from the sacrum magnetometer (Fasel thesis §9.2.1, "Body model and relative anchor
// point estimation"): a magnet buried at each gate raises the measured field intensity for a few
// hundredths of a second while the athlete passes it.
//
// Signal. The thesis calibrates the magnetometer so that |B| = 1 far from the magnets and relates
// the field intensity to the sensor–magnet distance with eq. 9.1,
//     |r| = −0.4 |B| + 1.0  (|B| < 1.62),   |r| = −0.062 |B| + 0.452  (else).
// Read literally (|B| = 1 far away) this puts every sample 0.6 m from a magnet and gives |r| = 1 m
// at zero field, so |B| in eq. 9.1 must be the magnet's own contribution in units of the ambient
// field: 0 far away, |r| → 1 m as it vanishes, detectable up to ≈ 0.8 m (|B| ≈ 0.5) as the thesis
// reports. We measure that contribution directly, as the earth-frame anomaly
//     e(t) = |R(t) m(t) − B̄| / |B̄|,   B̄ = component-wise median of R m over the recording,
// which, unlike the norm of the total field, does not depend on the angle between the magnet's
// field and the earth's.
//
// Crossings are the local maxima of e above `threshold` at least `minInterval` apart, timed by a
// parabola through the three samples around the maximum. The turn side is the sign of the
// earth-vertical angular rate at the crossing (thesis: "right" if the rate about the trunk's
// longitudinal axis is negative); the gate lies on the inside of the turn.
#include <vector>

namespace athlos::positioning {

struct GateCrossing {
    double t = 0.0;         // s
    double excess = 0.0;    // peak e (ambient field units)
    double distance = 0.0;  // m, eq. 9.1
    int side = 0;           // +1: gate on the left (left turn), −1: on the right
};

class GateDetector {
public:
    struct Params {
        double threshold = 0.3;    // ambient units; e = 0.3 ↔ |r| = 0.88 m by eq. 9.1 (seen up to ≈ 0.8 m)
        double minInterval = 0.4;  // s between crossings (GS gates are > 1 s apart at 25 m/s)
    };

    explicit GateDetector(Params params) : params_(params) {}

    // t (s), e (see above), yawRate: earth-vertical angular rate (rad/s), all the same length.
    std::vector<GateCrossing> detect(const std::vector<double>& t, const std::vector<double>& e,
                                     const std::vector<double>& yawRate) const;

    // Eq. 9.1: sensor–magnet distance (m) from the magnet's field in ambient units.
    static double distanceFromField(double excess);

private:
    Params params_;
};

}  // namespace athlos::positioning
