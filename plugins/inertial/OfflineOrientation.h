#pragma once
// Offline (smoothing) orientation estimation over a whole recording, after the offline mode of
// Laidig & Seel, "VQF: Highly Accurate IMU Orientation Estimation with Bias Estimation and Magnetic
// Disturbance Rejection", Information Fusion 91, 2023 (Sec. 3.6; written from the paper, not its code).
// Analysis happens after the recording, so every sample may use past and future data:
//  1. bias smoothing: the online filter (OrientationFilter) runs forwards and backwards in time (the
//     backward pass sees the time-reversed, negated gyroscope, so its bias estimate is −b); the two
//     estimates are fused per sample with inverse-variance weights from each pass's Kalman covariance
//     (a two-filter smoother, Fraser & Potter 1969), so the bias at the start of the recording is
//     known as well as at its end;
//  2. orientation passes: the online filter runs forwards and backwards again with the smoothed
//     bias subtracted and bias estimation off; each pass keeps its own magnetic reference field and
//     disturbance detector (a whole-recording reference was tried and made BROAD worse);
//  3. inclination: the bias-corrected gyroscope is integrated (the almost inertial frame I, eq. 4),
//     the accelerometer expressed in I is low-pass filtered forwards and then backwards (the
//     Butterworth of eqs. 5–8 twice: zero phase), and each sample is turned about a horizontal axis
//     so that the filtered vector points up (eq. 9); heading is untouched;
//  4. 9D: the heading offsets of both passes relative to that 6D orientation are averaged on the
//     circle with equal weights. (Weighting a pass down while it rides out a disturbance made BROAD
//     worse, 1.67°–1.95° instead of 1.59°; so did filtering the magnetometer's heading disagreement
//     forwards and backwards, 1.77°: docs/validation/inertial.md.)
// Same outputs as the online filter: sensor→ENU quaternion, bias, rest and disturbance flags.
#include "plugins/inertial/OrientationFilter.h"

#include <functional>

namespace athlos::inertial {

class OfflineOrientation {
public:
    struct Params {
        OrientationFilter::Params filter;  // the online filter run in each pass
        bool smoothBias = true;            // false: both passes keep their own online bias estimate
    };

    OfflineOrientation(double ts, const Params& params) : p_(params), ts_(ts) {}
    explicit OfflineOrientation(double ts) : OfflineOrientation(ts, Params()) {}

    // The whole recording at once; in.mag == nullptr runs 6D. `keepGoing` is polled between the four
    // passes with the fraction done; returning false stops early (returns false, `out` incomplete).
    bool updateBatch(const ImuBatch& in, OrientationTrack& out, const std::function<bool(double)>& keepGoing = {});

    const Params& params() const { return p_; }

private:
    Params p_;
    double ts_;
};

}  // namespace athlos::inertial
