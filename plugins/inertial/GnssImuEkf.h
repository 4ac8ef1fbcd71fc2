#pragma once
// Loosely-coupled GNSS/IMU extended Kalman filter of Kim, Park, Yoon, Sensors 2023 (seed 004,
// eqs. 10–21, 46–49): state x = [p (3), v (3), q (4)] in a local ENU frame, input u = [f (3), ω (3)]
// from the IMU at its rate, GNSS position (and velocity) updates at theirs with H = [I 0].
//   p⁺ = p + T v,  v⁺ = v + T (C(q) f − g e_z),  q⁺ = (I + T/2 Ω(ω)) q   (Euler discretisation, eq. 46)
// The Jacobian F = ∂x⁺/∂x is derived here (the printed entries, eqs. 22–45, are partly garbled):
//   ∂v⁺/∂q = T ∂(C(q) f)/∂q with C(q) f = (q0² − |q_v|²) f + 2 (q_v·f) q_v + 2 q0 (q_v × f):
//     ∂/∂q0  = 2 q0 f + 2 q_v × f
//     ∂/∂q_v = 2 (q_v·f) I + 2 q_v fᵀ − 2 f q_vᵀ − 2 q0 [f]×
//   ∂q⁺/∂q = I + T/2 Ω(ω);  ∂p⁺/∂v = T I.
// Attitude options: the EKF's own quaternion (the seed's 10-state filter as printed), or the
// inclination of an attitude filter (the seed's quaternion Kalman filter, or our OrientationFilter)
// with the EKF keeping the heading, which the GNSS velocity makes observable when the athlete
// accelerates. The initial heading is found by aligning IMU and GNSS velocity changes (2D
// Procrustes) before the IMU drives the velocity.
#include "plugins/inertial/Baselines.h"
#include "plugins/inertial/OrientationFilter.h"

#include <memory>
#include <optional>

namespace athlos::inertial {

enum class AttitudeSource { Orientation, Kalman, Ekf };

class GnssImuEkf {
public:
    using State = Eigen::Matrix<double, 10, 1>;
    using Matrix = Eigen::Matrix<double, 10, 10>;

    struct Params {
        double gravity = 9.81;             // m/s²
        double accNoise = 0.3;             // m/s² (σ of the specific force incl. attitude error), continuous
        double gyrNoise = 0.01;            // rad/s
        double gnssSigmaHorizontal = 1.8;  // m per horizontal axis
        double gnssSigmaVertical = 4.0;    // m
        double gnssVelocitySigma = 0.1;    // m/s per axis
        double alignExcitation = 5.0;      // (m/s)², velocity-change correlation needed for heading
        // The EKF's own quaternion is the best on simulated sprints: GNSS velocity corrects its tilt
        // during sustained accelerations, which fool any IMU-only attitude filter (docs/validation/inertial.md).
        AttitudeSource attitude = AttitudeSource::Ekf;
    };

    GnssImuEkf(double ts, const Params& params);

    // Discrete model and its Jacobian (public for the numeric Jacobian test).
    static State propagate(const State& x, const Vec3& f, const Vec3& w, double ts, double g);
    static Matrix jacobian(const State& x, const Vec3& f, const Vec3& w, double ts);

    bool isInitialised() const { return initialised_; }
    bool isAligned() const { return aligned_; }
    // One IMU sample (before the first GNSS fix only the attitude filter runs).
    void predict(const Vec3& acc, const Vec3& gyr);
    // One GNSS epoch in the local frame; vel may be null (position only).
    void updateGnss(const Vec3& pos, const Vec3* vel);

    Vec3 position() const { return x_.segment<3>(0); }
    Vec3 velocity() const { return x_.segment<3>(3); }
    Quat quaternion() const { return math::quatFromWxyz(x_.segment<4>(6)).normalized(); }
    const Matrix& covariance() const { return P_; }

private:
    void tryAlign(const Vec3& vGnss, int blockEpochs);
    Quat attitudeInclination() const;

    double ts_;
    Params p_;
    State x_ = State::Zero();
    Matrix P_ = Matrix::Identity();
    bool initialised_ = false, aligned_ = false;
    std::optional<OrientationFilter> orientation_;
    std::optional<QuaternionKalman> kalman_;
    Quat ownAttitude_ = Quat::Identity();  // before the first fix: inclination from the first sample
    bool haveAcc_ = false;
    // heading alignment
    Vec3 dvImu_ = Vec3::Zero();
    std::optional<Vec3> lastGnssVel_;
    double sumDot_ = 0.0, sumCross_ = 0.0;
    int epochsInBlock_ = 0;
};

}  // namespace athlos::inertial
