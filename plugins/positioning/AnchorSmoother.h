#pragma once
// Anchor-point smoother (Fasel thesis ch. 9, "Extended Kalman Smoother 1/2"; digest §7): the
// gravity-free sacrum acceleration, integrated by an extended Kalman smoother with 16 states
//     x = [p (3), v (3), a (3), o (3), b (3), ψ]
// position, velocity and acceleration in the inertial frame I (origin: the sacrum at the start),
// the position offset o and azimuth offset ψ that take I to the gates' earth frame G
// (g = R_z(ψ) p + o, thesis "Anchor point matching": only an azimuth rotation and a translation),
// and the acceleration offset b (measured a_m = a + b). Constant-acceleration model; the jerk noise
// grows with the measured acceleration change ("larger noise during phases with high acceleration
// variations"). Zero-velocity updates while the athlete stands at the start and the finish.
//
// Anchors: at a detected crossing m (GateDetector) the sacrum→magnet vector r_m is built as in
// eqs. 9.2–9.5 — d_m points from the sacrum to the snow surface (length `sacrumHeight`, in the
// plane normal to the velocity), x_m = √(|r_m|² − |d_m|²) sideways towards the gate — and the
// update is y = g_n − r_m = R_z(ψ)(p + v Δ) + o, Δ the time from the grid node to the crossing.
// Pass 0 runs without anchors; its crossings are matched to the gates in order (nearest expected
// gate, displacement since the last match); pass 1 fuses them with σ = 1 m; r_m and the matching
// are recomputed from pass 1 and pass 2 fuses them with σ = 0.2 m (thesis: 1 m, then 0.2 m). The
// output (G frame) is low-passed with a zero-phase 2nd-order Butterworth at 5 Hz (thesis §9.2.1).
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"
#include "plugins/positioning/GateDetector.h"
#include "plugins/positioning/GateRunSimulator.h"

#include <functional>
#include <optional>
#include <vector>

namespace athlos::positioning {

class AnchorSmoother {
public:
    struct Params {
        double rate = 100.0;          // Hz, smoother grid (the IMU is block-averaged onto it)
        double accSigma = 1.5;        // m/s², acceleration accuracy (thesis §9.2.2: 1.5 m/s²)
        double jerkBase = 20.0;       // m/s³, jerk noise floor of the constant-acceleration model
        double accOffsetSigma = 0.3;  // m/s², prior of b
        double accOffsetWalk = 0.15;  // m/s² per √s, random walk of b
        double azimuthSigma = 0.2;    // rad, prior of ψ (the orientation stream's heading error)
        double zuptSigma = 0.01;      // m/s
        double anchorSigma1 = 1.0;    // m, pass 1 (thesis)
        double anchorSigma2 = 0.2;    // m, pass 2 (thesis)
        double sacrumHeight = 0.5;    // m, |d_m|: sacrum above the snow at a gate
        double matchRadius = 8.0;     // m, largest distance of a crossing from its expected gate
        // Mahalanobis gate (d²) of the anchors after the first pass: χ²(3) at 0.9999, so that a wrongly
        // matched gate is rejected (innovation gating, thesis eq. 4.1).
        double anchorGate = 21.1;
        double lowPass = 5.0;      // Hz (thesis: 2nd-order Butterworth, 5 Hz); 0 = none
        int passes = 2;            // anchor passes (0: ZUPT-only integration, for comparison)
        double startSigma = 0.05;  // m, when the start position is given
    };

    struct Input {
        std::vector<double> t;             // s
        std::vector<math::Vec3> acc;       // gravity-free acceleration, earth frame of the orientation (m/s²)
        std::vector<unsigned char> still;  // 1 = standing (ZUPT)
        std::vector<GateCrossing> crossings;
        std::vector<Gate> gates;
        std::optional<math::Vec3> start;  // sacrum at the start, G frame
    };

    struct Match {
        int crossing = -1, gate = -1;
        math::Vec3 anchor;      // g_n − r_m (G frame)
        double residual = 0.0;  // m, |anchor − smoothed position| after the last pass
    };

    struct Result {
        std::vector<double> t;
        std::vector<math::Vec3> position, velocity;  // G frame, low-passed
        std::vector<Match> matches;                  // of the last pass
        std::vector<math::Vec3> inertialGates;       // per crossing: p + r_m of pass 0 (I frame)
        double azimuthOffset = 0.0;
        math::Vec3 positionOffset = math::Vec3::Zero();
        int stillNodes = 0;
    };

    explicit AnchorSmoother(Params params) : params_(params) {}

    // keepGoing(fraction) returns false to cancel (the result is then an error "cancelled").
    Expected<Result> run(const Input& input, const std::function<bool(double)>& keepGoing = {}) const;

    // Eqs. 9.2–9.5: sacrum → magnet from the velocity, the distance |r| and the side (+1 left).
    static math::Vec3 sacrumToMagnet(const math::Vec3& velocity, double distance, int side, double height);

    // Standing still at the start and the finish: the leading and trailing samples whose angular
    // rate stays below gyrLimit and whose gravity-free earth-frame acceleration stays below
    // accLimit (not the specific-force norm: gliding down a slope keeps |f| close to g).
    static std::vector<unsigned char> startFinishStill(const std::vector<double>& gyrNorm,
                                                       const std::vector<double>& freeAccNorm, double gyrLimit,
                                                       double accLimit);

    // In-order matching of estimated gate positions (crossing order) to the gates: the nearest of the
    // next few gates to where the displacement since the last match (relative) or the estimate
    // itself (absolute) puts it, within radius. −1 for an unmatched crossing.
    static std::vector<int> matchGates(const std::vector<math::Vec3>& estimated, const std::vector<Gate>& gates,
                                       double radius, bool relative);

private:
    Params params_;
};

}  // namespace athlos::positioning
