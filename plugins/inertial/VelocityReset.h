#pragma once
// Velocity resets for a foot- or ski-mounted sensor (Fasel 2017 ch. 2.3, 3.2.5 and 4.2; digest
// inertial-biomechanics.md §2): the sensor is still at known phases of every cycle (the foot's
// stance, the ski's thrust in cross-country diagonal stride and ski mountaineering), so its
// velocity is zero there, and the drift of the integrated velocity between two such phases can be
// estimated and removed.
//
//  1. Zero-velocity candidates: the mean gyroscope norm over `window` below gyrThreshold, the
//     mean |‖a‖ − g| below accThreshold and the spread of the acceleration vector (√ of the summed
//     per-axis variances) below accStdThreshold (the detectors of Skog et al. 2010 SHOE,
//     gaitmap's NormZuptDetector; for the ski, the still-ski criterion of Fasel 2017 ch. 3), for at
//     least minDuration; phases less than mergeGap apart are merged.
//  2a. Gyroscope bridge (Fasel 2017 ch. 3.2.5: the ski's orientation by integration of the angular
//     velocity between thrusts): from each phase centre to the next, the orientation is the input's
//     at the first centre carried by strap-down integration of the gyroscope, and the mismatch with
//     the input at the second centre is spread by SLERP. An online filter's inclination is pulled by
//     the large accelerations between thrusts; the gyroscope over one cycle is not.
//  2. Inclination reset (Fasel 2017 Eq. 2.7, ch. 3.2.5 "the accelerometer served as an
//     inclinometer"): at each phase the mean specific force, rotated to the earth frame with the
//     given orientation, must point up; the rotation δ_i taking it onto e_z is spread between the
//     phase centres by SLERP and held before the first and after the last.
//  3. Gravity removal in the earth frame, a_E = R'_k a_k − g e_z, g the mean accelerometer norm over
//     all zero-velocity samples (absorbs an accelerometer scale error, as StrideIntegrator eq. 4).
//  4. Velocity by trapezoidal integration; the drift is the mean velocity over the central
//     `anchorShare` of each phase (Fasel 2017 ch. 4: "only the central 50 % of the motionless period
//     was used to estimate the drift"), interpolated linearly between phase centres and removed
//     (Sabatini et al. 2005; Mariani et al. 2010); inside the phases the velocity is set to zero.
//  5. Cross-country skiing (Fasel 2017 ch. 3, Table 3.1): the thrust is then refined to the samples
//     around each candidate where the corrected speed stays below zeroSpeed (0.1 m/s) and the
//     inertial acceleration below zeroAcc, and steps 2–4 are repeated with the refined phases.
//  6. Position by trapezoidal integration of the corrected velocity, zero at the first phase centre.
// Velocity and position are defined only between the first and the last phase centre (NaN outside:
// there the drift is anchored on one side only).
#include "core/math/QuaternionOps.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace athlos::inertial {

class VelocityReset {
public:
    struct Params {
        enum class Mode { Foot, CrossCountrySki };
        Mode mode = Mode::Foot;
        double window = 0.1;  // s, centred moving mean of the detector signals
        // Foot defaults measured on gaitmap's real walk (docs/validation/drift-reduction.md): the right
        // foot's mid-stances there never go below 1.06 rad/s averaged over 0.1 s, so the ≈ 34°/s of the
        // stricter ZUPT detectors (Skog et al. 2010) misses them; the accelerometer's spread (SHOE's
        // accelerometer term) tells the still foot. 2 rad/s is gait-parameters' rest_threshold.
        double gyrThreshold = 2.0;     // rad/s, mean |ω|
        double accThreshold = 0.0;     // m/s², mean |‖a‖ − g|; 0 = not used
        double accStdThreshold = 1.0;  // m/s², spread of the acceleration vector over the window; 0 = not used
        double minDuration = 0.05;     // s, shortest zero-velocity phase
        double mergeGap = 0.1;         // s, phases closer than this are one (a stance split by noise)
        double anchorShare = 0.5;      // central share of a phase whose mean velocity is the drift (ch. 4)
        bool inclinationReset = true;
        bool gyroBridge = true;  // carry the orientation by the gyroscope between phases (step 2a)
        double gravity = 0.0;    // m/s²; 0 = mean accelerometer norm at the zero-velocity phases
        bool refine = false;     // cross-country: refine the thrust by speed and acceleration (ch. 3)
        double zeroSpeed = 0.1;  // m/s, Fasel 2017 ch. 3 Table 3.1 / ch. 4 (0.1 m/s)
        double zeroAcc = 1.0;    // m/s², inertial acceleration of a still ski (Table 3.1)
        double nominalG = 9.81;  // m/s², for the detector only
    };
    // Foot: stance by gyroscope and accelerometer energy. Cross-country ski: the thrust phase, the
    // still-ski thresholds of SkiCycleAnalyzer (|ω| < 0.2 rad/s, |‖a‖ − g| < 1 m/s² for ≥ 0.08 s),
    // refined by speed and acceleration.
    static Params foot() { return {}; }
    static Params crossCountrySki() {
        Params p;
        p.mode = Params::Mode::CrossCountrySki;
        p.window = 0.04;
        p.gyrThreshold = 0.2;
        p.accThreshold = 1.0;
        p.accStdThreshold = 0.0;
        p.minDuration = 0.08;
        p.mergeGap = 0.0;
        p.refine = true;
        return p;
    }

    struct Phase {
        std::size_t begin = 0, end = 0;         // samples [begin, end)
        math::Vec3 drift = math::Vec3::Zero();  // m/s, integrated velocity removed at this phase
        double tilt = 0.0;                      // rad, inclination reset at this phase
    };
    struct Result {
        std::vector<math::Vec3> velocity, position;  // earth frame (that of q), NaN outside the anchored span
        std::vector<unsigned char> zeroVelocity;     // 1 inside a phase
        std::vector<math::Vec3> acceleration;        // m/s², inertial (gravity removed), earth frame
        std::vector<Phase> phases;
        std::vector<math::Quat> q;        // orientation after the inclination resets
        double gravity = 0.0;             // m/s², the g removed
        std::size_t first = 0, last = 0;  // anchored span [first, last] (empty when last < first)
    };
    using Progress = std::function<bool(double)>;

    explicit VelocityReset(const Params& params) : p_(params) {}
    // q sensor → earth, acc (m/s²) and gyr (rad/s) in the sensor frame, all of the same length; ts the
    // sampling interval (s). Fewer than two phases: no anchored span (velocity all NaN).
    Result run(const std::vector<math::Quat>& q, const std::vector<math::Vec3>& acc, const std::vector<math::Vec3>& gyr,
               double ts, const Progress& progress = {}) const;

    // Step 1 alone (exposed for tests).
    std::vector<Phase> detect(const std::vector<math::Vec3>& acc, const std::vector<math::Vec3>& gyr, double ts) const;

private:
    void integrate(const std::vector<math::Quat>& q, const std::vector<math::Vec3>& acc,
                   const std::vector<math::Vec3>& gyr, std::vector<Phase>& phases, double ts, Result& out) const;
    Params p_;
};

}  // namespace athlos::inertial
