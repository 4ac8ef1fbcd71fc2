#pragma once
// Scoring the anchor smoother on the gate-run simulator (docs/validation/anchor-smoother.md): the
// simulated sacrum IMU → orientation (vqf, inertial family) → runAnchorPipeline, against the
// simulator's truth between the first and the last gate (the thesis scored between the second and
// the second-last gate against dGNSS). Shared by athlos-eval-anchor-smoother and the tests.
#include "core/util/Expected.h"
#include "plugins/positioning/AnchorPipeline.h"
#include "plugins/positioning/GateRunSimulator.h"

namespace athlos::positioning {

struct AnchorEvalOptions {
    GateRunSimulator::Params simulation;
    AnchorPipelineParams pipeline;
    bool useMagnetometer = true;      // orientation in 9D (false: 6D, heading from the gyroscope only)
    bool offlineOrientation = false;  // vqf forward–backward over the whole run
    bool truthOrientation = false;    // the simulator's orientation (isolates the smoother)
    double tauAcc = 3.0;              // s, vqf inclination time constant
    bool giveStart = true;            // pass the start position to the smoother
    int keepEveryGate = 1;            // 2, 3: keep every 2nd/3rd gate (thesis's simulated super-G / downhill)
};

struct AnchorScore {
    double positionRmse = 0.0;  // m, 3-D
    double speedMean = 0.0;     // m/s, |v̂| − |v|
    double speedSd = 0.0;       // m/s
    double tiltRmse = 0.0;      // deg, orientation inclination error
    double headingRmse = 0.0;   // deg
    int gates = 0, crossings = 0, matched = 0;
    double azimuthOffset = 0.0;  // rad, estimated ψ
};

Expected<AnchorScore> evaluateAnchorRun(const AnchorEvalOptions& options);

// GNSS-free gates (ch. 10): `runs` simulated runs on one course (seeds seed0 … seed0 + runs − 1),
// ZUPT-only gate estimates averaged by GateAveraging; errors after a similarity that puts the first
// and last gates on the truth (the thesis aligned azimuth and the first gate).
struct GateAverageScore {
    double singleMean = 0.0;    // m, mean horizontal gate error of one run (mean over runs)
    double averagedMean = 0.0;  // m, of the averaged gates
    double averagedMax = 0.0;   // m
};
Expected<GateAverageScore> evaluateGateAveraging(AnchorEvalOptions options, int runs, std::uint64_t seed0);

}  // namespace athlos::positioning
