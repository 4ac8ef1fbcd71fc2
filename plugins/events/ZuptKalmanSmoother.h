#pragma once
// Zero-velocity-aided error-state Kalman filter with Rauch–Tung–Striebel smoothing over a whole
// foot-IMU recording (Foxlin 2005; Skog et al. 2010, OpenShoe; Simón Colomar, Nilsson & Händel
// 2012, "Smoothing for ZUPT-aided INSs"; gaitmap's RtsKalman, Küderle et al. 2024). Unlike the
// per-stride integration of StrideIntegrator, which sets the velocity to zero at one mid-stance
// instant per stance, every sample detected as stance is a zero-velocity pseudo-measurement, and
// the smoother spreads each correction backwards over the swing according to the error model.
//
// Nominal state: position p, velocity v (world frame, z up), orientation q (sensor → world). Error
// state δx = (δp, δv, δθ) ∈ R⁹ with p_true = p + δp, v_true = v + δv, R_true = Exp(δθ) R (global
// attitude error, Solà 2017 §7).
//  1. Strapdown step k → k+1 (Δt = t_{k+1} − t_k): q_{k+1} = q_k ⊗ Exp(ω̄ Δt), ω̄ = (ω_k + ω_{k+1})/2;
//     f = (q_k a_k + q_{k+1} a_{k+1})/2; v_{k+1} = v_k + (f − g e_z) Δt;
//     p_{k+1} = p_k + (v_k + v_{k+1}) Δt/2.
//  2. Error transition Φ_k = I + F Δt (+ the Δt² term for position): δp' = δv, δv' = −[f]× δθ,
//     δθ' = 0 (plus noise); Φ = [[I, IΔt, −[f]× Δt²/2], [0, I, −[f]× Δt], [0, 0, I]].
//  3. Process noise per step Q = diag(0, (σ_a,k Δt)² I, (σ_ω,k Δt)² I); P⁻_{k+1} = Φ P⁺_k Φᵀ + Q,
//     with σ_a,k = σ_a + c_a |‖a_{k+1}‖ − g| (3a) and σ_ω,k = σ_ω + c_ω ‖ω_{k+1}‖ (3b; ZuptKalmanParams).
//  4. Zero-velocity update at a stance sample: H = [0 I 0], innovation z = 0 − v, R = σ_z² I,
//     K = P⁻Hᵀ (H P⁻ Hᵀ + R)⁻¹, δ = K z, P⁺ = (I − KH) P⁻ (I − KH)ᵀ + K R Kᵀ (Joseph form).
//  5. The correction δ is fed back into the nominal state (closed loop, Colomar et al. Alg. 1):
//     p += δp, v += δv, q = Exp(δθ) ⊗ q; the error estimate is zero again.
//  6. RTS backward pass in error-state form. With the error relative to the forward posterior
//     x⁺_k, the forward estimate is 0 and the prior at k+1 is −δ_{k+1}, so
//       A_k = P⁺_k Φ_kᵀ (P⁻_{k+1})⁻¹,   e_N = 0,   e_k = A_k (δ_{k+1} + e_{k+1}),
//     and the smoothed state is x⁺_k ⊕ e_k (eq. 5 applied with e_k).
// The gain A_k is computed in the forward pass, so only A_k and δ_{k+1} are kept per sample
// (90 doubles, 0.7 KB; core/estimation/RtsSmoother keeps five 9 × 9 matrices per node, which for
// 10 min at 204.8 Hz would be 250 MB); the batch smooth() keeps them for one block at a time.
#include "plugins/events/StrideIntegrator.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <functional>
#include <vector>

namespace athlos::events {

struct ZuptKalmanParams {
    // Accelerometer process noise per sample, eq. 3a: σ_a,k = σ_a + c_a · |‖a_k‖ − g|. The floor
    // σ_a covers sensor noise and vibration (OpenShoe: 0.01 m/s² for white noise alone; with that
    // a simulated accelerometer bias moves a still foot by 2 cm in 4 s, with 0.05 m/s² by 2 mm).
    // The velocity errors of a foot IMU come from the dynamics: scale and cross-axis errors,
    // band-limited impacts and a shoe or strap that deforms under load all grow with the specific
    // force away from gravity, so c_a tells the smoother where in the swing a stance's correction
    // belongs (push-off and landing, not the quiet mid-swing). With c_a = 0 the noise is white and
    // a correction spreads evenly over the swing (processor version ≤ 4: σ_a = 0.5 m/s², c_a = 0).
    // docs/validation/gait-parameters.md: against a heel marker the mean absolute stride-length
    // error drops from 3.9 % to 3.0 % (2.6 % between the estimated strides' own mid-stances).
    double accNoise = 0.05;         // m/s², σ_a
    double accNoiseDynamic = 0.05;  // c_a: σ per m/s² of |‖a‖ − g| (dimensionless)
    // Gyroscope process noise per sample, σ_ω,k = σ_ω + c_ω ‖ω_k‖ (3b: a scale error grows with the
    // rate). c_ω = 0.01 keeps the end of the smoothing span from reaching back several strides, at
    // a slightly larger length error on the heel-marker walk (docs/validation/gait-parameters.md).
    double gyrNoise = 0.01;        // rad/s, σ_ω
    double gyrNoiseDynamic = 0.0;  // c_ω (dimensionless)
    double zuptNoise = 0.01;    // m/s, σ_z: zero-velocity pseudo-measurement (OpenShoe: 0.01 m/s)
    double initialTilt = 0.02;  // rad, σ of the levelled initial inclination (1.1°)
};

struct ZuptKalmanState {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();               // m, world (z up)
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();               // m/s
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // sensor → world
};

class ZuptKalmanSmoother {
public:
    // q0: orientation at the first sample (levelled from gravity), g: gravity (m/s²).
    ZuptKalmanSmoother(const ZuptKalmanParams& params, const Eigen::Quaterniond& q0, double gravity);

    // Forward pass, one sample (t in s, acc in m/s², gyr in rad/s, sensor frame): eqs. 1–3 from
    // the previous sample, then eqs. 4–5 when `stance`. The first sample only sets the start.
    void addSample(double t, const Eigen::Vector3d& acc, const Eigen::Vector3d& gyr, bool stance);

    // Forward (filtered) state of the last sample added.
    const ZuptKalmanState& filtered() const { return state_; }
    std::size_t samples() const { return nominal_.size(); }

    // Eq. 6 over every sample added: one smoothed state per sample.
    std::vector<ZuptKalmanState> smooth() const;

    // Progress of a batch: fraction done (forward pass 0–0.45, backward 0.45–1); false cancels.
    using Progress = std::function<bool(double)>;

    // Batch: every sample of a recording (acc/gyr: x of the first sample, strides in doubles
    // between samples; stance one flag per sample). Empty when cancelled through `progress`. Equal to
    // addSample() for every sample then smooth(), in bounded memory: instead of A_k and δ_{k+1} for every
    // sample it keeps the filter after every kBlock-th sample and forms them again per block in the
    // backward pass (the first forward pass skips the gains; ~80 B per sample for the states instead of
    // ~0.8 KB).
    static constexpr std::size_t kBlock = 4096;
    static std::vector<ZuptKalmanState> smooth(const ZuptKalmanParams& params, const Eigen::Quaterniond& q0,
                                               double gravity, const double* t, const double* acc,
                                               std::size_t accStride, const double* gyr, std::size_t gyrStride,
                                               const std::vector<bool>& stance, const Progress& progress = {});

private:
    using Matrix9 = Eigen::Matrix<double, 9, 9>;
    using Vector9 = Eigen::Matrix<double, 9, 1>;

    // Eqs. 1–5 for one sample: the filter moves on, and A_{k−1} (when `gain` is given) and δ_k of this
    // sample k are returned (false for the first sample, which only sets the start).
    bool advance(double t, const Eigen::Vector3d& acc, const Eigen::Vector3d& gyr, bool stance, Matrix9* gain,
                 Vector9& correction);

    ZuptKalmanParams params_;
    double gravity_;
    ZuptKalmanState state_;
    Matrix9 P_;
    double t_ = 0.0;
    bool started_ = false;
    Eigen::Vector3d acc_ = Eigen::Vector3d::Zero(), gyr_ = Eigen::Vector3d::Zero();
    // Per-sample interface only (addSample / smooth()):
    std::vector<ZuptKalmanState> nominal_;  // x⁺_k
    std::vector<Matrix9> gain_;             // A_k, k = 0 … n − 2
    std::vector<Vector9> correction_;       // δ_{k+1}, k = 0 … n − 2
};

// Stance samples for the zero-velocity updates: the gyroscope norm averaged over `window` (s) at
// most `threshold` (rad/s) — the gyroscope-energy detector of Skog et al. 2010 (as gaitmap's
// NormZuptDetector) — or within window/2 of one of the given mid-stance samples m and no more than
// `threshold` above the average at m, so that a foot that is never still below the threshold still
// gets the zero-velocity instants of the segmentation, but not the fast roll around a short stance.
std::vector<bool> detectStance(const double* t, const double* gyr, std::size_t rows, std::size_t stride, double window,
                               double threshold, const std::vector<std::size_t>& midStances);

struct ZuptStrideParams {
    ZuptKalmanParams filter;
    double stanceWindow = 0.15;     // s: gyroscope-norm average of the stance detector (gaitmap NormZuptDetector)
    double stanceThreshold = 0.26;  // rad/s: stance when the average is at most this (15 deg/s, gaitmap)
    double levelWindow = 0.15;      // s: accelerometer mean for the initial levelling and gravity
};

// The strides' spatial parameters from the smoothed trajectory: the filter runs from the first
// segment's start to the last segment's end (stance from detectStance, the segments' mid-stances
// always included), starts levelled with heading 0, g the mean accelerometer norm over the stance
// samples; each stride is the displacement between its two mid-stance samples (same definitions as
// integrateStrides). Also returns the number of stance samples in `stanceSamples`.
// Cancelled through `progress` (ZuptKalmanSmoother::smooth): no strides and no positions.
FootTrajectory smoothStrides(const ZuptStrideParams& params, const std::vector<StrideSegment>& segments,
                             const double* t, const double* acc, std::size_t accStride, const double* gyr,
                             std::size_t gyrStride, std::size_t rows, std::size_t* stanceSamples = nullptr,
                             const ZuptKalmanSmoother::Progress& progress = {});

}  // namespace athlos::events
