#include "plugins/inertial/OfflineOrientation.h"

#include <cmath>
#include <algorithm>
#include <numbers>

namespace athlos::inertial {

namespace {

// Per-sample record of one pass, indexed in the pass's own time order.
struct Pass {
    std::vector<Quat> q6, q9;
    std::vector<Vec3> bias;
    std::vector<double> biasVar;  // (rad/s)², largest diagonal element of the bias covariance
    std::vector<unsigned char> rest, magDisturbed;
};

// Samples in a pass's time order, stride 3; mag empty = 6D.
struct Series {
    std::vector<double> gyr, acc, mag;
};

Pass runPass(const OrientationFilter::Params& params, double ts, const Series& s, std::size_t n) {
    OrientationFilter f(ts, params);
    Pass p;
    p.q6.resize(n);
    p.q9.resize(n);
    p.bias.resize(n);
    p.biasVar.resize(n);
    p.rest.resize(n);
    p.magDisturbed.resize(n);
    const bool hasMag = !s.mag.empty();

    for (std::size_t k = 0; k < n; ++k) {
        const Vec3 g(s.gyr[3 * k], s.gyr[3 * k + 1], s.gyr[3 * k + 2]);
        const Vec3 a(s.acc[3 * k], s.acc[3 * k + 1], s.acc[3 * k + 2]);
        if (hasMag) {
            const Vec3 m(s.mag[3 * k], s.mag[3 * k + 1], s.mag[3 * k + 2]);
            f.update(g, a, &m);
        } else {
            f.update(g, a, nullptr);
        }
        p.q6[k] = f.quaternion6D();
        p.q9[k] = f.quaternion();
        p.bias[k] = f.bias();
        const double sigma = f.biasSigma();
        p.biasVar[k] = sigma * sigma;
        p.rest[k] = f.restDetected();
        p.magDisturbed[k] = f.magDisturbed();
    }
    return p;
}

// The heading angle (rad, about the ENU vertical) of a rotation: the twist of r about z.
double yawOf(const Quat& r) { return 2.0 * std::atan2(r.z(), r.w()); }

double wrapPi(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

// Zero-phase inclination: strapdown integration of the bias-corrected gyroscope gives the almost
// inertial frame I (eq. 4); the accelerometer expressed in I is low-pass filtered forwards and then
// backwards (the Butterworth of eqs. 5–8 applied twice, zero phase: a slowly drifting gravity is
// tracked without lag), and each sample's orientation is turned about a horizontal axis so that the
// filtered vector points up (eq. 9).
std::vector<Quat> zeroPhaseInclination(const Series& s, std::size_t n, double ts, const OrientationFilter::Params& p) {
    std::vector<Quat> gyrQuat(n);
    std::vector<Vec3> accI(n);
    Quat q = Quat::Identity();
    Vec3 last = Vec3::Zero();
    bool haveLast = false;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3 w(s.gyr[3 * k], s.gyr[3 * k + 1], s.gyr[3 * k + 2]);
        const double wn = w.allFinite() ? w.norm() : 0.0;
        if (wn > 1e-12) {
            const double half = 0.5 * wn * ts, sn = std::sin(half) / wn;
            q = (q * Quat(std::cos(half), sn * w.x(), sn * w.y(), sn * w.z())).normalized();
        }
        gyrQuat[k] = q;
        const Vec3 a(s.acc[3 * k], s.acc[3 * k + 1], s.acc[3 * k + 2]);
        const bool valid = a.allFinite() && a.squaredNorm() > 0.0 &&
                           !(p.accRange > 0.0 && a.cwiseAbs().maxCoeff() >= 0.995 * p.accRange);
        if (valid) {
            last = q * a;
            haveLast = true;
        }
        accI[k] = haveLast ? last : Vec3(0.0, 0.0, p.gravity);
    }
    // A clipped or missing sample holds the last valid one (the online filter substitutes gravity).
    std::vector<Vec3> y(n);
    LowPass2<3> lp(p.tauAcc, ts);
    for (std::size_t k = 0; k < n; ++k) y[k] = lp.step(accI[k]);
    LowPass2<3> lpb(p.tauAcc, ts);
    for (std::size_t k = n; k-- > 0;) y[k] = lpb.step(y[k]);
    std::vector<Quat> out(n);
    const Vec3 up(0.0, 0.0, 1.0);
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3& g = y[k];
        out[k] = g.norm() > 1e-9 ? (Quat::FromTwoVectors(g, up) * gyrQuat[k]).normalized() : gyrQuat[k];
    }
    return out;
}

}  // namespace

bool OfflineOrientation::updateBatch(const ImuBatch& in, OrientationTrack& out,
                                     const std::function<bool(double)>& keepGoing) {
    const std::size_t n = in.rows;
    out.resize(n);
    if (n == 0) return true;
    const bool hasMag = in.mag != nullptr;
    const auto at = [&](const double* base, std::size_t r, int i) { return base[r * in.stride + i]; };

    // Forward and time-reversed series. Reversal: the forward step k integrates ω_k from t_{k-1} to
    // t_k, so going back from t_{k+1} to t_k integrates −ω_{k+1} (eq. 4 with dt < 0); the backward
    // pass's sample k therefore carries −ω_{k+1} (and −ω_{n-1} for the last sample, which only sets
    // the start of the pass).
    Series fwd, bwd;
    fwd.gyr.resize(3 * n);
    fwd.acc.resize(3 * n);
    bwd.gyr.resize(3 * n);
    bwd.acc.resize(3 * n);
    if (hasMag) {
        fwd.mag.resize(3 * n);
        bwd.mag.resize(3 * n);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = n - 1 - k;
        const std::size_t next = std::min(k + 1, n - 1);
        for (int i = 0; i < 3; ++i) {
            fwd.gyr[3 * k + i] = at(in.gyr, k, i);
            fwd.acc[3 * k + i] = bwd.acc[3 * j + i] = at(in.acc, k, i);
            bwd.gyr[3 * j + i] = -at(in.gyr, next, i);
            if (hasMag) fwd.mag[3 * k + i] = bwd.mag[3 * j + i] = at(in.mag, k, i);
        }
    }
    const auto poll = [&](double f) { return !keepGoing || keepGoing(f); };

    // 1. Bias smoothing: two-filter fusion of the forward estimate b_f and the backward one −b_b.
    std::vector<Vec3> bias(n, Vec3::Zero());
    const bool estimateBias = p_.filter.restBiasEstimation || p_.filter.motionBiasEstimation;
    const bool smooth = estimateBias && p_.smoothBias;
    std::vector<unsigned char> rest(n, 0);
    OrientationFilter::Params op = p_.filter;
    if (smooth) {
        if (!poll(0.0)) return false;
        const Pass bf = runPass(p_.filter, ts_, fwd, n);
        if (!poll(0.25)) return false;
        const Pass bb = runPass(p_.filter, ts_, bwd, n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t j = n - 1 - k;
            // The backward pass's estimate for sample k was made after integrating −ω_{k+1}: use the
            // estimate at its sample j (it refers to the same stretch of data).
            const double wf = 1.0 / std::max(bf.biasVar[k], 1e-20), wb = 1.0 / std::max(bb.biasVar[j], 1e-20);
            bias[k] = (wf * bf.bias[k] - wb * bb.bias[j]) / (wf + wb);
            rest[k] = bf.rest[k] || bb.rest[j];
        }
        // Subtract it: the orientation passes then run with bias estimation off.
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t j = n - 1 - k;
            const std::size_t next = std::min(k + 1, n - 1);
            for (int i = 0; i < 3; ++i) {
                fwd.gyr[3 * k + i] -= bias[k][i];
                bwd.gyr[3 * j + i] += bias[next][i];
            }
        }
    }
    if (smooth) op.restBiasEstimation = op.motionBiasEstimation = false;

    // 2. Orientation passes.
    if (!poll(0.5)) return false;
    const Pass f = runPass(op, ts_, fwd, n);
    if (!poll(0.75)) return false;
    const Pass b = runPass(op, ts_, bwd, n);

    if (!smooth) {
        // Without smoothing: the mean of both passes' own estimates (zero if not estimated), subtracted
        // from the forward series for the inclination below.
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t j = n - 1 - k;
            bias[k] = 0.5 * (f.bias[k] - b.bias[j]);
            rest[k] = f.rest[k] || b.rest[j];
            for (int i = 0; i < 3; ++i) fwd.gyr[3 * k + i] -= bias[k][i];
        }
    }

    // 3. Inclination from the whole recording (forward pass's frame: its heading at the first sample).
    const std::vector<Quat> incl = zeroPhaseInclination(fwd, n, ts_, op);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = n - 1 - k;
        const Quat& q6 = incl[k];
        Quat q = q6;
        if (hasMag) {
            // Heading: each pass's offset about the vertical relative to the fused 6D orientation.
            const double df = yawOf(f.q9[k] * q6.conjugate()), db = yawOf(b.q9[j] * q6.conjugate());
            const double d = wrapPi(df + 0.5 * wrapPi(db - df));
            q = (Quat(std::cos(0.5 * d), 0.0, 0.0, std::sin(0.5 * d)) * q6).normalized();
        }
        out.q[k] = q;
        out.bias[k] = bias[k];
        out.rest[k] = rest[k];
        out.magDisturbed[k] = hasMag && f.magDisturbed[k] && b.magDisturbed[j];
    }
    return poll(1.0);
}

}  // namespace athlos::inertial
