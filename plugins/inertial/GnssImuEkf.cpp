#include "plugins/inertial/GnssImuEkf.h"

#include "core/math/Angles.h"

#include <Eigen/LU>

namespace athlos::inertial {

namespace {
Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}
Eigen::Matrix4d omegaMatrix(const Vec3& w) {  // q̇ = ½ Ω(ω) q, eq. 6
    Eigen::Matrix4d o;
    o << 0, -w.x(), -w.y(), -w.z(), w.x(), 0, w.z(), -w.y(), w.y(), -w.z(), 0, w.x(), w.z(), w.y(), -w.x(), 0;
    return o;
}
// C(q) f for a (not necessarily unit) quaternion, eq. 12.
Vec3 rotate(const Eigen::Vector4d& q, const Vec3& f) {
    const double q0 = q[0];
    const Vec3 qv = q.tail<3>();
    return (q0 * q0 - qv.squaredNorm()) * f + 2.0 * qv.dot(f) * qv + 2.0 * q0 * qv.cross(f);
}
}  // namespace

GnssImuEkf::GnssImuEkf(double ts, const Params& params) : ts_(ts), p_(params) {
    if (p_.attitude == AttitudeSource::Orientation) orientation_.emplace(ts);
    if (p_.attitude == AttitudeSource::Kalman) kalman_.emplace(ts, QuaternionKalman::Params());
}

GnssImuEkf::State GnssImuEkf::propagate(const State& x, const Vec3& f, const Vec3& w, double ts, double g) {
    State n;
    const Eigen::Vector4d q = x.segment<4>(6);
    n.segment<3>(0) = x.segment<3>(0) + ts * x.segment<3>(3);
    n.segment<3>(3) = x.segment<3>(3) + ts * (rotate(q, f) - Vec3(0.0, 0.0, g));
    n.segment<4>(6) = q + 0.5 * ts * omegaMatrix(w) * q;
    return n;
}

GnssImuEkf::Matrix GnssImuEkf::jacobian(const State& x, const Vec3& f, const Vec3& w, double ts) {
    Matrix F = Matrix::Identity();
    F.block<3, 3>(0, 3) = ts * Mat3::Identity();
    const double q0 = x[6];
    const Vec3 qv = x.segment<3>(7);
    F.block<3, 1>(3, 6) = ts * (2.0 * q0 * f + 2.0 * qv.cross(f));
    F.block<3, 3>(3, 7) = ts * (2.0 * qv.dot(f) * Mat3::Identity() + 2.0 * qv * f.transpose() -
                                2.0 * f * qv.transpose() - 2.0 * q0 * skew(f));
    F.block<4, 4>(6, 6) += 0.5 * ts * omegaMatrix(w);
    return F;
}

Quat GnssImuEkf::attitudeInclination() const {
    Quat att = ownAttitude_;
    if (orientation_) att = orientation_->quaternion6D();
    if (kalman_) att = kalman_->quaternion();
    Quat h, incl;
    math::splitHeadingInclination(att, h, incl);
    return incl;
}

void GnssImuEkf::predict(const Vec3& acc, const Vec3& gyr) {
    if (orientation_) orientation_->update(gyr, acc, nullptr);
    if (kalman_) kalman_->update(gyr, acc, nullptr);
    if (!haveAcc_) {
        ownAttitude_ = math::quatFromAccelerometer(acc);
        haveAcc_ = true;
    }
    if (!initialised_) {
        ownAttitude_ = math::integrateBodyRate(ownAttitude_, gyr, ts_);
        return;
    }
    const Vec3 fE = quaternion() * acc - Vec3(0.0, 0.0, p_.gravity);
    dvImu_ += ts_ * fE;
    // Until the heading is aligned the IMU's horizontal acceleration points the wrong way: predict
    // a constant horizontal velocity and let the GNSS carry it.
    Vec3 f = acc;
    if (!aligned_) f = quaternion().conjugate() * Vec3(0.0, 0.0, fE.z() + p_.gravity);
    const Matrix F = jacobian(x_, f, gyr, ts_);
    x_ = propagate(x_, f, gyr, ts_, p_.gravity);
    x_.segment<4>(6).normalize();
    Matrix Q = Matrix::Zero();
    const double qa = (aligned_ ? p_.accNoise * p_.accNoise : 25.0) * ts_;
    Q.diagonal().segment<3>(0).setConstant(1e-6 * ts_);
    Q.diagonal().segment<3>(3).setConstant(qa);
    Q.diagonal().segment<4>(6).setConstant(0.25 * p_.gyrNoise * p_.gyrNoise * ts_);
    P_ = F * P_ * F.transpose() + Q;
    if (p_.attitude != AttitudeSource::Ekf) {
        // Inclination from the attitude filter, heading from the EKF.
        Quat h, incl;
        math::splitHeadingInclination(quaternion(), h, incl);
        x_.segment<4>(6) = math::wxyz(math::canonical(h * attitudeInclination()));
    }
}

void GnssImuEkf::tryAlign(const Vec3& vGnss, int blockEpochs) {
    // Without GNSS velocity the filter's velocity is noisy epoch to epoch: compare velocity changes
    // over blocks of epochs (1 s), where the athlete's accelerations dominate the noise.
    if (lastGnssVel_ && ++epochsInBlock_ < blockEpochs) return;
    epochsInBlock_ = 0;
    if (lastGnssVel_) {
        const Vec3 dvG = vGnss - *lastGnssVel_;
        // Rotation about z taking the IMU's velocity change onto the GNSS one (2D Procrustes).
        sumDot_ += dvImu_.x() * dvG.x() + dvImu_.y() * dvG.y();
        sumCross_ += dvImu_.x() * dvG.y() - dvImu_.y() * dvG.x();
    }
    lastGnssVel_ = vGnss;
    dvImu_.setZero();
    if (std::hypot(sumDot_, sumCross_) < blockEpochs * p_.alignExcitation) return;
    const double psi = std::atan2(sumCross_, sumDot_);
    const Quat q = math::headingRotation(psi) * quaternion();
    x_.segment<4>(6) = math::wxyz(math::canonical(q));
    x_.segment<3>(3) = vGnss;
    // Heading uncertainty after alignment (5°) along the quaternion direction of a rotation about z.
    Eigen::Vector4d u = 0.5 * math::wxyz(Quat(0.0, 0.0, 0.0, 1.0) * q);
    P_.setZero();
    P_.diagonal().segment<3>(0).setConstant(p_.gnssSigmaHorizontal * p_.gnssSigmaHorizontal);
    P_.diagonal().segment<3>(3).setConstant(p_.gnssVelocitySigma * p_.gnssVelocitySigma);
    P_.block<4, 4>(6, 6) = std::pow(5.0 * math::kDeg, 2) * u * u.transpose() + 1e-6 * Eigen::Matrix4d::Identity();
    aligned_ = true;
}

void GnssImuEkf::updateGnss(const Vec3& pos, const Vec3* vel) {
    if (!initialised_) {
        x_.segment<3>(0) = pos;
        x_.segment<3>(3) = vel ? *vel : Vec3::Zero();
        x_.segment<4>(6) = math::wxyz(orientation_ || kalman_ ? attitudeInclination() : ownAttitude_);
        P_.setZero();
        P_.diagonal() << Vec3::Constant(p_.gnssSigmaHorizontal * p_.gnssSigmaHorizontal),
            Vec3::Constant(vel ? p_.gnssVelocitySigma * p_.gnssVelocitySigma : 4.0), Eigen::Vector4d::Constant(1e-4);
        initialised_ = true;
        if (vel) lastGnssVel_ = *vel;
        dvImu_.setZero();
        return;
    }
    const int m = vel ? 6 : 3;
    Eigen::Matrix<double, 6, 1> z;
    z.head<3>() = pos;
    if (vel) z.tail<3>() = *vel;
    Eigen::Matrix<double, 6, 10> H = Eigen::Matrix<double, 6, 10>::Zero();
    H.leftCols<6>().setIdentity();  // eq. 20: H = [I 0]
    Eigen::Matrix<double, 6, 1> r;
    r << p_.gnssSigmaHorizontal, p_.gnssSigmaHorizontal, p_.gnssSigmaVertical, Vec3::Constant(p_.gnssVelocitySigma);
    const auto Hm = H.topRows(m);
    const Eigen::MatrixXd S =
        Hm * P_ * Hm.transpose() + Eigen::MatrixXd(r.head(m).array().square().matrix().asDiagonal());
    Eigen::MatrixXd K = P_ * Hm.transpose() * S.inverse();  // eq. 16
    if (!aligned_) K.bottomRows<4>().setZero();             // the heading is not yet meaningful
    const Eigen::VectorXd innovation = z.head(m) - Hm * x_;
    x_ += K * innovation;  // eq. 17
    x_.segment<4>(6).normalize();
    P_ = (Matrix::Identity() - K * Hm) * P_;  // eq. 18
    P_ = 0.5 * (P_ + P_.transpose()).eval();
    // Without GNSS velocity, the filter's velocity (smoothed from the positions) stands in for it.
    if (!aligned_) tryAlign(vel ? *vel : velocity(), vel ? 1 : 10);
}

}  // namespace athlos::inertial
