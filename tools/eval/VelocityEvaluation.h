#pragma once
// Scoring velocity-reset (plugins/inertial/VelocityReset.h) against ground truth: the cross-country
// ski simulator (SkiingSimulator: cycle speed and length, thrust timing), the foot simulator
// (FootMotionSimulator: stride lengths, stance phases) and gaitmap's real walk (stance phases
// against the motion-capture strides; stride lengths against gait-parameters, as the shared data has
// no distance reference). Orientation is 6D VQF (`orientation`'s default without a magnetometer) or,
// on the simulators, strap-down from the first sample.
// Used by athlos-eval-velocity-reset and the inertial family's tests.
#include "core/util/Expected.h"
#include "plugins/events/FootMotionSimulator.h"
#include "plugins/events/SkiingSimulator.h"
#include "plugins/inertial/VelocityReset.h"

#include <QString>
#include <QVariantMap>
#include <vector>

namespace athlos::inertial {

struct ErrorStat {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double mean() const;
    double sd() const;
    double meanAbs() const;
    double maxAbs() const;
};

struct SkiVelocityScore {
    int truthThrusts = 0, matchedThrusts = 0, extraPhases = 0;
    ErrorStat cycleSpeed;              // m/s, estimate − truth
    ErrorStat cycleSpeedPct;           // % of the truth
    ErrorStat cycleLength;             // m
    ErrorStat thrustStart, thrustEnd;  // s
    double speedRmse = 0.0;            // m/s, per sample over the anchored span
    double speedRmseNoReset = 0.0;     // m/s, the same acceleration integrated without resets
    void add(const SkiVelocityScore& o);
};
// One simulated cross-country run (seed, `cycles` cycles) with the given velocity-reset parameters.
SkiVelocityScore evaluateSkiVelocity(unsigned seed, int cycles, const VelocityReset::Params& params,
                                     bool strapdown = false);

struct FootVelocityScore {
    int truthStrides = 0, matchedStances = 0, extraPhases = 0;
    ErrorStat strideLength;            // m, horizontal displacement between the truth's mid-stances
    ErrorStat strideLengthPct;         // %
    ErrorStat strideLengthNoResetPct;  // %, integrated without resets (the drift the resets remove)
    void add(const FootVelocityScore& o);
};
FootVelocityScore evaluateFootVelocity(const events::SimConfig& config, const VelocityReset::Params& params,
                                       bool strapdown = false);
// The level walk of the gait-parameters simulation tests (12 strides 1.20–1.64 m), with a seed.
events::SimConfig footWalkConfig(unsigned seed);

struct GaitmapVelocityScore {
    int referenceStrides = 0;
    int oneStance = 0;          // reference strides (IC to IC) holding exactly one zero-velocity phase centre
    int someStance = 0;         // … at least one
    int strides = 0;            // gait-parameters strides compared
    ErrorStat lengthDiffPct;    // % of gait-parameters' stride_length
    ErrorStat heightDiff;       // m, against gait-parameters' stride_height
    ErrorStat speedAtMidSwing;  // m/s, horizontal speed at the middle between two phases
};
// The processors end to end on a gaitmap IMU file (import --format gaitmap, orientation mode=6d,
// velocity-reset mode=foot, gait-parameters) for both feet; bordersCsv may be empty (stairs).
Expected<GaitmapVelocityScore> evaluateGaitmapVelocity(const QString& imuCsv, const QString& bordersCsv,
                                                       const QVariantMap& resetParameters = {});

}  // namespace athlos::inertial
