#pragma once
// Centre-of-mass error of body-com on the whole-body simulator (issue #18 items 2, 5, 6): simulate (skiing,
// head and arms on the thorax with a swing) → 6D orientation per sensor → functional calibration → drift
// reduction → BodyCom, against the simulator's true CoM relative to the lumbar joint centre. Shared by
// athlos-eval-body-com and the validation test.
#include "plugins/body/WholeBodySimulator.h"
#include "plugins/inertial/DriftReduction.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <array>

namespace athlos::eval {

enum class ComOrientations { True, Uncorrected, Corrected };
enum class ComVectors { True, Estimated, Model };

struct BodyComEvaluationOptions {
    body::WholeBodyParams simulation;
    inertial::OrientationOptions orientation;  // 6D
    inertial::DriftReduction::Params reduction;
    ComOrientations orientations = ComOrientations::Corrected;
    ComVectors vectors = ComVectors::Estimated;  // Estimated needs Corrected (drift reduction's fit); else True
    bool trueMounts = false;                     // skip the functional calibration (feet always use the true mounts)
};

struct BodyComEvaluation {
    // Over the motion phase, in the pelvis' heading frame (forward, left, up), so that the arbitrary heading
    // of 6D orientations does not count: CoM relative to the lumbar joint centre.
    double rmse = 0;       // m, RMS of |error|
    double meanError = 0;  // m, mean |error| (the thesis' accuracy figure is a mean error)
    math::Vec3 bias = math::Vec3::Zero(), sd = math::Vec3::Zero();  // per axis (m)
    double foreAftRmse = 0;                                         // m, fore-aft CoM against the feet
    // In the pelvis sensor's own frame (the whole body's common inclination error removed): the chain itself.
    double pelvisFrameRmse = 0;  // m, CoM
    double ankleRmse = 0;        // m, right ankle
    // Absolute CoM from the helmet antenna (heading aligned over the first 2 s for 6D orientations).
    double absoluteRmse = 0;            // m, 3D
    double speedBias = 0, speedSd = 0;  // m/s, CoM speed error
    // Estimated vectors only: the larger of |r_p − r_p,true| and |r_d − r_d,true| per joint (BodyJoint order, m).
    std::array<double, 7> vectorError{};
    std::size_t samples = 0;
};

BodyComEvaluation evaluateBodyCom(const BodyComEvaluationOptions& options);

}  // namespace athlos::eval
