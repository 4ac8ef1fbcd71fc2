#include "plugins/events/ZuptKalmanSmoother.h"

#include "core/math/QuaternionOps.h"
#include "plugins/events/StrideSegmenter.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace athlos::events {

namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

Matrix3d skew(const Vector3d& v) {
    Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

// Eq. 5: x ⊕ δ.
void inject(ZuptKalmanState& x, const Eigen::Matrix<double, 9, 1>& d) {
    x.position += d.head<3>();
    x.velocity += d.segment<3>(3);
    x.orientation = (math::quatFromRotationVector(d.tail<3>()) * x.orientation).normalized();
}

}  // namespace

ZuptKalmanSmoother::ZuptKalmanSmoother(const ZuptKalmanParams& params, const Quaterniond& q0, double gravity)
    : params_(params), gravity_(gravity) {
    state_.orientation = q0.normalized();
    // The first sample is a mid-stance: position 0 by definition, velocity zero within σ_z, tilt
    // from the levelling, heading 0 by definition (it is unobservable with zero velocity only).
    Vector9 p0;
    const double tilt2 = params.initialTilt * params.initialTilt, v2 = params.zuptNoise * params.zuptNoise;
    p0 << 1e-10, 1e-10, 1e-10, v2, v2, v2, tilt2, tilt2, 1e-10;
    P_ = p0.asDiagonal();
}

void ZuptKalmanSmoother::addSample(double t, const Vector3d& acc, const Vector3d& gyr, bool stance) {
    Matrix9 gain;
    Vector9 delta;
    if (advance(t, acc, gyr, stance, &gain, delta)) {
        gain_.push_back(gain);
        correction_.push_back(delta);
    }
    nominal_.push_back(state_);
}

bool ZuptKalmanSmoother::advance(double t, const Vector3d& acc, const Vector3d& gyr, bool stance, Matrix9* gain,
                                 Vector9& correction) {
    if (!started_) {
        started_ = true;
        t_ = t;
        acc_ = acc;
        gyr_ = gyr;
        return false;
    }
    const double dt = t - t_;
    // Eq. 1: strapdown step with the mean rate and the mean specific force in the world frame.
    const Quaterniond q1 = math::integrateBodyRate(state_.orientation, 0.5 * (gyr_ + gyr), dt);
    const Vector3d f = 0.5 * (state_.orientation * acc_ + q1 * acc);
    const Vector3d v1 = state_.velocity + (f - gravity_ * Vector3d::UnitZ()) * dt;
    state_.position += 0.5 * (state_.velocity + v1) * dt;
    state_.velocity = v1;
    state_.orientation = q1;
    t_ = t;
    acc_ = acc;
    gyr_ = gyr;

    // Eqs. 2–3, with Φ = I + N and N's three non-zero blocks written out: Φ P = P + N P and
    // (Φ P) Φᵀ = Φ P + (Φ P) Nᵀ, so only the products with [f]× remain (a quarter of the full products).
    const Matrix3d F = skew(f);
    const double h = 0.5 * dt * dt;
    const Eigen::Matrix<double, 3, 9> G = F * P_.middleRows<3>(6);  // [f]× (rows δθ of P)
    Matrix9 PhiP = P_;
    PhiP.middleRows<3>(0) += dt * P_.middleRows<3>(3) - h * G;
    PhiP.middleRows<3>(3) -= dt * G;
    const Eigen::Matrix<double, 9, 3> H = PhiP.middleCols<3>(6) * F.transpose();
    Matrix9 prior = PhiP;
    prior.middleCols<3>(0) += dt * PhiP.middleCols<3>(3) - h * H;
    prior.middleCols<3>(3) -= dt * H;
    // Eqs. 3a–3b: the noise grows with the dynamics of the new sample.
    const double qa = (params_.accNoise + params_.accNoiseDynamic * std::abs(acc.norm() - gravity_)) * dt;
    const double qw = (params_.gyrNoise + params_.gyrNoiseDynamic * gyr.norm()) * dt;
    for (int i = 0; i < 3; ++i) {
        prior(3 + i, 3 + i) += qa * qa;
        prior(6 + i, 6 + i) += qw * qw;
    }
    prior = 0.5 * (prior + prior.transpose());
    // Eq. 6's gain A_k = P⁺_k Φᵀ (P⁻_{k+1})⁻¹, i.e. Aᵀ = (P⁻)⁻¹ Φ P⁺ (P⁻ symmetric). The jitter
    // keeps the position block (no process noise of its own) invertible right after the start.
    if (gain) {
        const Eigen::LDLT<Matrix9> ldlt(prior + 1e-14 * Matrix9::Identity());
        *gain = ldlt.solve(PhiP).transpose();
    }

    Vector9 delta = Vector9::Zero();
    if (stance) {
        // Eq. 4: H selects the velocity error.
        const Matrix3d S = prior.block<3, 3>(3, 3) + params_.zuptNoise * params_.zuptNoise * Matrix3d::Identity();
        const Eigen::Matrix<double, 9, 3> K = prior.block<9, 3>(0, 3) * S.inverse();
        delta = K * (-state_.velocity);
        Matrix9 IKH = Matrix9::Identity();
        IKH.block<9, 3>(0, 3) -= K;
        // Small fixed-size products coefficient by coefficient (lazyProduct): Eigen's general matrix
        // product path (packing, blocking) costs more than the arithmetic at 9 × 9.
        const Matrix9 IKHP = IKH.lazyProduct(prior);
        P_ = IKHP.lazyProduct(IKH.transpose()) +
             params_.zuptNoise * params_.zuptNoise * K.lazyProduct(K.transpose());  // K R Kᵀ with R = σ_z² I
        inject(state_, delta);                                           // eq. 5
    } else {
        P_ = prior;
    }
    correction = delta;
    return true;
}

std::vector<ZuptKalmanState> ZuptKalmanSmoother::smooth() const {
    std::vector<ZuptKalmanState> out = nominal_;
    Vector9 e = Vector9::Zero();  // e_N = 0: the last sample's filtered state is its smoothed one
    for (std::size_t k = out.size() - (out.empty() ? 0 : 1); k-- > 0;) {
        e = gain_[k] * (correction_[k] + e);
        inject(out[k], e);
    }
    return out;
}

std::vector<ZuptKalmanState> ZuptKalmanSmoother::smooth(const ZuptKalmanParams& params, const Quaterniond& q0,
                                                        double gravity, const double* t, const double* acc,
                                                        std::size_t accStride, const double* gyr, std::size_t gyrStride,
                                                        const std::vector<bool>& stance, const Progress& progress) {
    const std::size_t n = stance.size();
    std::vector<ZuptKalmanState> out(n);
    if (n == 0) return out;
    const auto step = [&](ZuptKalmanSmoother& f, std::size_t k, Matrix9* gain, Vector9& delta) {
        f.advance(t[k], Vector3d(acc + k * accStride), Vector3d(gyr + k * gyrStride), stance[k], gain, delta);
    };
    // Forward pass: the filtered states, and a copy of the filter after every kBlock-th sample. The
    // gains are not needed yet (the filter does not depend on them), which halves its work.
    ZuptKalmanSmoother filter(params, q0, gravity);
    std::vector<ZuptKalmanSmoother> checkpoints;  // after sample b·kBlock
    checkpoints.reserve(n / kBlock + 1);
    Vector9 delta;
    constexpr std::size_t kReportEvery = 8192;  // samples (a few ms of work)
    for (std::size_t k = 0; k < n; ++k) {
        if (progress && k % kReportEvery == 0 && !progress(0.45 * double(k) / double(n))) return {};
        step(filter, k, nullptr, delta);
        out[k] = filter.state_;
        if (k % kBlock == 0) checkpoints.push_back(filter);
    }
    // Backward pass (eq. 6), block by block from the end: a block's gains A_k and corrections δ_{k+1}
    // are formed again from its checkpoint — the same operations on the same numbers as in the forward
    // pass — so only one block of them is ever kept.
    std::vector<Matrix9> gains(kBlock);
    std::vector<Vector9> deltas(kBlock);
    Vector9 e = Vector9::Zero();  // e_N = 0: the last sample's filtered state is its smoothed one
    for (std::size_t b = checkpoints.size(); b-- > 0;) {
        if (progress && !progress(0.45 + 0.55 * double(checkpoints.size() - 1 - b) / double(checkpoints.size())))
            return {};
        const std::size_t k0 = b * kBlock, k1 = std::min(n - 1, k0 + kBlock);  // A_k, k = k0 … k1 − 1
        ZuptKalmanSmoother f = checkpoints[b];
        for (std::size_t k = k0 + 1; k <= k1; ++k) step(f, k, &gains[k - 1 - k0], deltas[k - 1 - k0]);
        for (std::size_t k = k1; k-- > k0;) {
            e = gains[k - k0] * (deltas[k - k0] + e);
            inject(out[k], e);
        }
    }
    if (progress && !progress(1.0)) return {};
    return out;
}

std::vector<bool> detectStance(const double* t, const double* gyr, std::size_t rows, std::size_t stride, double window,
                               double threshold, const std::vector<std::size_t>& midStances) {
    const std::vector<double> mean = meanGyroNorm(t, gyr, rows, stride, window);
    std::vector<bool> stance(rows);
    for (std::size_t k = 0; k < rows; ++k) stance[k] = mean[k] <= threshold;
    for (std::size_t m : midStances) {
        if (m >= rows) continue;
        // The mid-stance, and its neighbours as far as the foot stays as quiet as there, within the
        // detector's own threshold: a running foot rolls fast on either side of it (simulated 0.2 s
        // stance: mean length error 6.1 % → 1.7 %; docs/validation/gait-parameters.md).
        const double quiet = mean[m] + threshold;
        stance[m] = true;
        for (std::size_t j = m + 1; j < rows && t[j] <= t[m] + 0.5 * window && mean[j] <= quiet; ++j) stance[j] = true;
        for (std::size_t j = m; j > 0 && t[j - 1] >= t[m] - 0.5 * window && mean[j - 1] <= quiet; --j)
            stance[j - 1] = true;
    }
    return stance;
}

FootTrajectory smoothStrides(const ZuptStrideParams& params, const std::vector<StrideSegment>& segments,
                             const double* t, const double* acc, std::size_t accStride, const double* gyr,
                             std::size_t gyrStride, std::size_t rows, std::size_t* stanceSamples,
                             const ZuptKalmanSmoother::Progress& progress) {
    FootTrajectory out;
    if (segments.empty() || rows == 0) return out;
    const std::size_t first = segments.front().start, last = segments.back().end;
    std::vector<std::size_t> midStances;
    for (const StrideSegment& s : segments) {
        midStances.push_back(s.start - first);
        midStances.push_back(s.end - first);
    }
    const std::size_t n = last - first + 1;
    const double* tt = t + first;
    const double* a = acc + first * accStride;
    const double* w = gyr + first * gyrStride;
    const std::vector<bool> stance =
        detectStance(tt, w, n, gyrStride, params.stanceWindow, params.stanceThreshold, midStances);
    // Gravity as the accelerometer reads it while standing (absorbs a scale error, as integrateStrides).
    double g = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < n; ++k)
        if (stance[k]) {
            g += Vector3d(a + k * accStride).norm();
            ++count;
        }
    g /= double(count);  // count ≥ 1: the mid-stances are stance
    if (stanceSamples) *stanceSamples = count;
    const Quaterniond q0 =
        levelledOrientation(meanAccelerometer(t, acc, accStride, rows, first, params.levelWindow), 0.0);
    const std::vector<ZuptKalmanState> states =
        ZuptKalmanSmoother::smooth(params.filter, q0, g, tt, a, accStride, w, gyrStride, stance, progress);
    if (states.empty()) return out;  // cancelled

    out.first = first;
    out.position.reserve(n);
    for (const ZuptKalmanState& s : states) out.position.push_back(s.position);
    for (const StrideSegment& s : segments) {
        const ZuptKalmanState &x0 = states[s.start - first], &x1 = states[s.end - first];
        StrideEstimate e;
        e.tStart = t[s.start];
        e.tEnd = t[s.end];
        const Vector3d d = x1.position - x0.position;
        e.length = d.head<2>().norm();
        e.height = d.z();
        double maxZ = 0.0;
        for (std::size_t k = s.start; k <= s.end; ++k)
            maxZ = std::max(maxZ, states[k - first].position.z() - x0.position.z());
        e.maxClearance = maxZ - std::max(0.0, e.height);
        // The twist about the vertical of the rotation between the two mid-stances (the mounting cancels).
        e.turningAngle = math::twistHeadingAngle((x1.orientation * x0.orientation.conjugate()).normalized());
        e.endSpeed = x1.velocity.norm();
        out.strides.push_back(e);
    }
    return out;
}

}  // namespace athlos::events
