#include "plugins/inertial/OrientationFilter.h"

#include <cmath>

namespace athlos::inertial {

namespace {
inline double sq(double x) { return x * x; }
// Inverse of a symmetric 3×3 matrix by cofactors (six distinct entries; S is positive definite).
inline Mat3 symmetricInverse(const Mat3& s) {
    const double a = s(0, 0), b = s(0, 1), c = s(0, 2), d = s(1, 1), e = s(1, 2), f = s(2, 2);
    const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
    const double invDet = 1.0 / (a * c00 + b * c01 + c * c02);
    Mat3 m;
    m(0, 0) = c00 * invDet;
    m(0, 1) = m(1, 0) = c01 * invDet;
    m(0, 2) = m(2, 0) = c02 * invDet;
    m(1, 1) = (a * f - c * c) * invDet;
    m(1, 2) = m(2, 1) = (b * c - a * e) * invDet;
    m(2, 2) = (a * d - b * b) * invDet;
    return m;
}
}  // namespace

OrientationFilter::OrientationFilter(double ts, const Params& params) : p_(params), ts_(ts) {
    // Bias Kalman filter noise (eqs. 24–27). Only the ratios matter for the gain, so the units of
    // P and W just have to agree: (rad/s)².
    biasP0_ = sq(p_.biasSigmaInit);
    biasV_ =
        sq(0.1 * math::kDeg) * ts_ / p_.biasForgettingTime;  // the uncertainty grows by 0.1 °/s per forgetting time
    // A measurement that, repeated every step, would hold P at pMotion in steady state: w = p²/v + p.
    const double pMotion = sq(p_.biasSigmaMotion);
    biasMotionW_ = sq(pMotion) / biasV_ + pMotion;
    biasVerticalW_ = biasMotionW_ / std::max(p_.biasVerticalForgettingFactor, 1e-10);
    const double pRest = sq(p_.biasSigmaRest);
    biasRestW_ = sq(pRest) / biasV_ + pRest;
    kMag_ = gainFromTau(p_.tauMag, ts_);
    accLp_.setup(p_.tauAcc, ts_);
    biasLp_.setup(p_.tauAcc, ts_);
    RestDetector::Params rp = p_.rest;
    rp.biasClip = p_.biasClip;
    rest_.setup(rp, ts_);
    magDist_.setup(p_.mag, ts_);
    reset();
}

OrientationFilter::OrientationFilter(double ts) : OrientationFilter(ts, Params()) {}

void OrientationFilter::reset() {
    gyrQuat_.setIdentity();
    accQuat_.setIdentity();
    delta_ = 0.0;
    headingQuat_.setIdentity();
    bias_.setZero();
    biasP_ = biasP0_ * Mat3::Identity();
    accLp_.reset();
    biasLp_.reset();
    rest_.reset();
    magDist_.reset();
    kMagInit_ = 1.0;
    magRejectT_ = 0.0;
    hasMag_ = false;
}

double OrientationFilter::biasSigma() const { return std::sqrt(biasP_.diagonal().maxCoeff()); }

void OrientationFilter::update(const Vec3& gyr, const Vec3& acc, const Vec3* mag) {
    // Missing values (NaN) must not poison the state: a bad gyro sample is skipped, a bad
    // accelerometer or magnetometer sample is treated as absent.
    if (gyr.allFinite()) updateGyr(gyr);
    Vec3 accEarth;
    bool accOk = false;
    if ((acc.x() != 0.0 || acc.y() != 0.0 || acc.z() != 0.0) && acc.allFinite()) {
        if (p_.accRange > 0.0 && acc.cwiseAbs().maxCoeff() >= 0.995 * p_.accRange)
            accOk = updateAcc((accQuat_ * gyrQuat_).conjugate() * Vec3(0.0, 0.0, p_.gravity), accEarth);
        else
            accOk = updateAcc(acc, accEarth);
    }
    const bool magOk = mag && (mag->x() != 0.0 || mag->y() != 0.0 || mag->z() != 0.0) && mag->allFinite();
    const bool bias = accOk && (p_.restBiasEstimation || p_.motionBiasEstimation);
    if (!bias && !magOk) return;
    // The 6D rotation after the inclination correction, shared by the bias and heading updates.
    const Mat3 r = (accQuat_ * gyrQuat_).toRotationMatrix();
    if (bias) updateBias(accEarth, r);
    if (magOk) updateMag(*mag, r);
}

void OrientationFilter::updateGyr(const Vec3& gyr) {
    if (p_.restBiasEstimation || p_.mag.newMinGyr > 0.0) rest_.updateGyr(gyr);
    // Strapdown (eq. 4): q_gyr ← q_gyr ⊗ exp(ω dt / 2), exact for constant ω over the step.
    const Vec3 w = gyr - bias_;
    const double n = w.norm();
    if (n > 1e-12) {
        const double half = 0.5 * n * ts_;
        const double s = std::sin(half) / n;
        gyrQuat_ = gyrQuat_ * Quat(std::cos(half), s * w.x(), s * w.y(), s * w.z());
        gyrQuat_.normalize();
    }
}

bool OrientationFilter::updateAcc(const Vec3& acc, Vec3& accE) {
    rest_.updateAcc(acc);
    // Eqs. 5–8: low-pass the accelerometer in the almost inertial frame I, rotate into E.
    const Vec3 accI = gyrQuat_ * acc;
    const Vec3 accLp = accLp_.step(accI);
    accE = accQuat_ * accLp;
    const double an = accE.norm();
    if (an < 1e-9) return false;
    accE /= an;
    // Eq. 9: the smallest rotation taking accE to the vertical (axis horizontal, so it never changes
    // heading), applied on the left (in E).
    const double qw = std::sqrt(0.5 * (accE.z() + 1.0));
    const Quat corr = qw > 1e-6 ? Quat(qw, 0.5 * accE.y() / qw, -0.5 * accE.x() / qw, 0.0) : Quat(0.0, 1.0, 0.0, 0.0);
    accQuat_ = (corr * accQuat_).normalized();
    return true;
}

void OrientationFilter::updateBias(const Vec3& accEarth, const Mat3& r) {
    // The bias the correction above already accounts for went through the same low-pass as accE.
    const Eigen::Vector2d biasLp = biasLp_.step((r.topRows<2>() * bias_).eval());

    Vec3 e, w;
    Mat3 h;
    bool measure = true;
    if (rest_.isRest() && p_.restBiasEstimation) {
        // Eq. 26: at rest the low-pass gyro is the bias.
        e = rest_.gyrLowPass() - bias_;
        h.setIdentity();
        w.setConstant(biasRestW_);
    } else if (p_.motionBiasEstimation) {
        // Eqs. 20–23: the inclination correction (rotation vector (a_y, -a_x, 0) per step) is the
        // negative of the residual drift rate in E; add the filtered bias estimate to get a
        // measurement of R·b on the horizontal axes. The vertical axis carries no information and is
        // only pulled weakly towards zero (biasVerticalW).
        h = r;
        e.x() = -accEarth.y() / ts_ + biasLp.x() - r.row(0).dot(bias_);
        e.y() = accEarth.x() / ts_ + biasLp.y() - r.row(1).dot(bias_);
        e.z() = -r.row(2).dot(bias_);
        w = Vec3(biasMotionW_, biasMotionW_, biasVerticalW_);
    } else {
        measure = false;
    }
    // Prediction: the bias may wander; P grows but never beyond its initial value.
    for (int i = 0; i < 3; ++i)
        if (biasP_(i, i) < biasP0_) biasP_(i, i) += biasV_;
    if (!measure) return;
    e = e.cwiseMax(-p_.biasClip).cwiseMin(p_.biasClip);
    // Kalman update, eq. 27: K = P Hᵀ (W + H P Hᵀ)⁻¹, b += K e, P -= K H P = K (P Hᵀ)ᵀ (P symmetric).
    const Mat3 pht = biasP_ * h.transpose();
    Mat3 s = h * pht;
    s.diagonal() += w;
    const Mat3 k = pht * symmetricInverse(s);
    bias_ += k * e;
    biasP_ -= k * pht.transpose();
    bias_ = bias_.cwiseMax(-p_.biasClip).cwiseMin(p_.biasClip);
}

void OrientationFilter::updateMag(const Vec3& mag, const Mat3& r) {
    hasMag_ = true;
    const Vec3 magE = r * mag;
    if (p_.magDisturbanceRejection) magDist_.update(magE, rest_.gyrLowPass());
    // Eq. 11: heading disagreement between the field's horizontal direction (north = +y in ENU) and δ.
    double dis = std::atan2(magE.x(), magE.y()) - delta_;  // both in [-π, π]: one wrap suffices
    if (dis > std::numbers::pi) dis -= 2.0 * std::numbers::pi;
    if (dis < -std::numbers::pi) dis += 2.0 * std::numbers::pi;
    double k = kMag_;
    if (p_.magDisturbanceRejection) {
        if (magDist_.isDisturbed()) {
            // Ride the disturbance out on the gyroscope, but not forever: after maxRejectionTime a
            // lasting change of the environment must eventually be followed (with a reduced gain).
            if (magRejectT_ <= p_.magMaxRejectionTime) {
                magRejectT_ += ts_;
                k = 0.0;
            } else {
                k /= p_.magRejectionFactor;
            }
        } else {
            magRejectT_ = std::max(magRejectT_ - p_.magRejectionFactor * ts_, 0.0);
        }
    }
    // Fast start: average the first samples (gain 1, 1/2, 1/3, ...) until the averaging is slower
    // than the regular filter — the initial heading comes from the first second of data.
    if (kMagInit_ != 0.0) {
        k = std::max(k, kMagInit_);
        kMagInit_ = kMagInit_ / (kMagInit_ + 1.0);
        if (kMagInit_ * p_.tauMag < ts_) kMagInit_ = 0.0;
    }
    if (k == 0.0) return;
    delta_ += k * dis;
    if (delta_ > std::numbers::pi) delta_ -= 2.0 * std::numbers::pi;  // one step never wraps more than once
    if (delta_ < -std::numbers::pi) delta_ += 2.0 * std::numbers::pi;
    headingQuat_ = Quat(std::cos(0.5 * delta_), 0.0, 0.0, std::sin(0.5 * delta_));
}

}  // namespace athlos::inertial
