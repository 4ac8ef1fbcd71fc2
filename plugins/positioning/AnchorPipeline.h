#pragma once
// From a sacrum IMU and its orientation to the anchor-smoothed trajectory: gravity-free earth-frame
// acceleration (a = R f − g e_z), the start/finish still phases for the ZUPT, the magnetometer
// anomaly and gate crossings (GateDetector), then the AnchorSmoother. Shared by the
// `anchor-smoother` processor, its tests and the evaluation program.
#include "plugins/positioning/AnchorSmoother.h"
#include "plugins/positioning/GateDetector.h"
#include "plugins/positioning/RestAlignedStrapdown.h"

namespace athlos::positioning {

struct AnchorPipelineParams {
    GateDetector::Params detector;
    AnchorSmoother::Params smoother;
    double stillGyr = 0.3;  // rad/s: standing still below this angular rate …
    double stillAcc = 0.8;  // m/s²: … and gravity-free acceleration below this (ZUPT at start and finish)
    double gravity = 9.81;
    // true: RestAlignedStrapdown from the stream's start orientation (default: the turns' centripetal
    // acceleration tilts accelerometer-aided filters); false: the orientation stream as it is.
    bool restAligned = true;
};

struct AnchorPipelineInput {
    std::vector<double> t;
    std::vector<math::Vec3> acc, gyr, mag;  // sensor frame: m/s², rad/s, µT (any unit for mag)
    std::vector<math::Quat> orientation;    // sensor → earth (ENU), same times
    std::vector<Gate> gates;
    std::optional<math::Vec3> start;
};

struct AnchorPipelineResult {
    std::vector<GateCrossing> crossings;
    std::vector<double> anomaly;          // e(t) per input sample (ambient units)
    std::vector<math::Quat> orientation;  // the orientation used (after RestAlignedStrapdown)
    AnchorSmoother::Result smoothed;
};

// Errors: "no gate crossing found (magnetometer anomaly never above <threshold>, peak <max>)",
// and those of the smoother; the caller adds the recording's name.
Expected<AnchorPipelineResult> runAnchorPipeline(const AnchorPipelineInput& input, const AnchorPipelineParams& params,
                                                 const std::function<bool(double)>& keepGoing = {});

}  // namespace athlos::positioning
