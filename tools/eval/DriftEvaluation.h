#pragma once
// Joint-angle errors on the body simulator with and without drift reduction (issue #17 items 3, 5):
// simulate → orientation per sensor (6D) → functional calibration (upright + squats) → optional
// drift reduction → joint angles (ISB / Grood & Suntay) → RMSE against the true angles over the
// walking or skiing phase. Shared by athlos-eval-drift-reduction and the validation test.
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/DriftReduction.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <array>

namespace athlos::eval {

struct DriftEvaluationOptions {
    inertial::BodySimulatorParams simulation;
    inertial::OrientationOptions orientation;  // useMagnetometer is forced off (6D)
    inertial::DriftReduction::Params reduction;
    bool driftReduction = true;
    bool trueMounts = false;  // skip the functional calibration (feet always use the true mounts)
    // reduction.staticCorrection as the processor's static_correction=auto decides it from the orientation
    // algorithm (staticCorrectionSuits: strap-down only); false = reduction.staticCorrection as given.
    bool staticCorrectionAuto = true;
};

struct JointError {
    std::array<double, 3> rmse{};  // flexion, abduction, rotation (rad)
};

struct DriftEvaluation {
    std::array<JointError, inertial::kBodyJoints> joints;                // indexed by BodyJoint
    std::array<double, inertial::kBodySegments> calibrationAxisError{};  // rad, mount vs truth (NaN = true mount used)
    std::array<double, inertial::kBodySegments>
        orientationError{};  // rad, mean sensor orientation error (motion phase)
    double seconds = 0.0;    // run time of drift reduction
    // Joints whose heading drift reduction found unobservable (DriftReduction::HeadingStatus): their
    // angles use the start alignment, as without drift reduction.
    std::array<bool, inertial::kBodyJoints> headingKept{};
};

DriftEvaluation evaluateDriftReduction(const DriftEvaluationOptions& options);

}  // namespace athlos::eval
