#include "plugins/inertial/DriftReduction.h"

#include "plugins/inertial/LowPass2.h"
#include "plugins/inertial/NelderMead.h"
#include "plugins/inertial/ProperRotation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

namespace athlos::inertial {

using math::Quat;
using math::Vec3;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Vec4 = Eigen::Vector4d;
using Estimator = DriftReduction::Params::Estimator;
using HeadingStatus = DriftReduction::HeadingStatus;

namespace {

Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

// ω (low-passed) and ω̇ of one sensor; ã = a + K r with K = [ω̇]× + [ω]×² (Eqs. 5.3–5.4). ω̇ is the
// central difference of ω (one-sided at the ends), formed where it is used rather than stored: it is
// read about twenty times per sample, and one more array per sensor costs more in memory traffic.
struct Kinematics {
    std::vector<Vec3> omega;
    double rate = 0.0;  // 1 / ts
    Vec3 omegaDot(std::size_t i) const {
        const std::size_t last = omega.size() - 1;
        if (i == 0 || i == last) return (omega[std::min(last, i + 1)] - omega[i == 0 ? 0 : i - 1]) * rate;
        return (omega[i + 1] - omega[i - 1]) * (0.5 * rate);
    }
    Mat3 k(std::size_t i) const {
        const Mat3 w = skew(omega[i]);
        return skew(omegaDot(i)) + w * w;
    }
    // ω × (ω × r) written as ω (ω·r) − r |ω|² (fewer operations than two cross products).
    Vec3 virtualAcc(const Vec3& a, std::size_t i, const Vec3& r) const {
        const Vec3& w = omega[i];
        return a + omegaDot(i).cross(r) + w * w.dot(r) - r * w.squaredNorm();
    }
};

Vec4 toVec(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
Quat toQuat(const Vec4& v) { return Quat(v[0], v[1], v[2], v[3]).normalized(); }

// Largest eigenvector of a symmetric positive semi-definite 4×4 matrix by power iteration from a
// guess (the previous sample's mean changes little, so a few steps suffice); a full eigen solve when
// the guess is missing or does not converge.
Vec4 dominantEigenvector(const Mat4& m, const Vec4* guess) {
    if (guess) {
        Vec4 v = *guess;
        for (int i = 0; i < 6; ++i) {
            const Vec4 next = m * v;
            const double norm = next.norm();
            if (!(norm > 0.0)) break;
            const Vec4 u = next / norm;
            if ((u - v).squaredNorm() < 1e-18) return u;
            v = u;
        }
        // Converged well enough when the Rayleigh quotient is close to the largest eigenvalue bound.
        const Vec4 mv = m * v;
        if ((mv - v.dot(mv) * v).norm() <= 1e-9 * mv.norm()) return v;
    }
    Eigen::SelfAdjointEigenSolver<Mat4> es(m);
    return es.eigenvectors().col(3);
}

// SLERP from a to b (Shoemake 1985) for many t: the angle and its sine once per pair, and one sincos
// per sample (sin((1−t)θ) = sin θ cos tθ − cos θ sin tθ); equal to math::slerp up to rounding.
class SlerpSegment {
public:
    SlerpSegment(const Quat& a, const Quat& b) : a_(a.coeffs()), b_(b.coeffs()) {
        double d = a.dot(b);
        if (d < 0.0) {  // shorter arc
            b_ = -b_;
            d = -d;
        }
        linear_ = d > 1.0 - 1e-12;
        if (!linear_) {
            theta_ = std::acos(d);
            cotTheta_ = d / std::sin(theta_);
            invSin_ = 1.0 / std::sin(theta_);
        }
    }
    Quat at(double t) const {
        Quat r;
        if (linear_) {
            r.coeffs() = (1.0 - t) * a_ + t * b_;
            return r.normalized();
        }
        const double st = std::sin(t * theta_), ct = std::cos(t * theta_);
        r.coeffs() = (ct - cotTheta_ * st) * a_ + (st * invSin_) * b_;
        return r;
    }
    // at(i / m) for i = 1 … m − 1, passed to visit(i, q). sin(iΔ) and cos(iΔ), Δ = θ / m, advance by the
    // angle-addition formulas and are recomputed exactly every 256 steps, so the rounding error stays
    // near 1e-13 and the sweep needs no sincos per sample.
    template <class Visit>
    void sweep(std::size_t m, Visit&& visit) const {
        if (linear_) {
            for (std::size_t i = 1; i < m; ++i) visit(i, at(double(i) / double(m)));
            return;
        }
        const double step = theta_ / double(m), cd = std::cos(step), sd = std::sin(step);
        double c = 1.0, sn = 0.0;
        for (std::size_t i = 1; i < m; ++i) {
            if (i % 256 == 0) {
                sn = std::sin(double(i) * step);
                c = std::cos(double(i) * step);
            } else {
                const double next = c * cd - sn * sd;
                sn = sn * cd + c * sd;
                c = next;
            }
            Quat r;
            r.coeffs() = (c - cotTheta_ * sn) * a_ + (sn * invSin_) * b_;
            visit(i, r);
        }
    }

private:
    Vec4 a_, b_;  // Eigen's coefficient order (x, y, z, w)
    bool linear_ = false;
    double theta_ = 0.0, cotTheta_ = 0.0, invSin_ = 0.0;
};

// Heading (rotation about earth z) that best turns the horizontal parts of u onto those of v, from the
// samples whose horizontal parts both exceed minNorm (the azimuth pass's signal-to-noise condition,
// Fasel 2017 Eqs. 6.12–6.13): ψ = atan2(Σ (u × v)_z, Σ u·v). Also the coherence ρ = |Σ |u||v| e^{iθ}| /
// Σ |u||v| of the per-sample heading differences θ (the weighted mean resultant length of circular
// statistics, Mardia & Jupp 2000 §2.3): 1 when one heading explains every sample, near 0 when the
// horizontal parts are unrelated.
struct HeadingFit {
    double psi = 0.0, coherence = 0.0;
    std::size_t samples = 0;
};
HeadingFit bestHeading(const std::vector<Vec3>& u, const std::vector<Vec3>& v, double minNorm) {
    double s = 0.0, c = 0.0, w = 0.0;
    HeadingFit f;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const double nu = u[i].head<2>().norm(), nv = v[i].head<2>().norm();
        if (!(nu > minNorm && nv > minNorm)) continue;
        s += u[i].x() * v[i].y() - u[i].y() * v[i].x();
        c += u[i].x() * v[i].x() + u[i].y() * v[i].y();
        w += nu * nv;
        ++f.samples;
    }
    if (w > 0.0) {
        f.psi = std::atan2(s, c);
        f.coherence = std::hypot(s, c) / w;
    }
    return f;
}

}  // namespace

std::vector<Vec3> DriftReduction::zeroPhaseLowPass(const std::vector<Vec3>& x, double cutoff, double ts) {
    std::vector<Vec3> y(x.size());
    if (x.empty()) return y;
    // LowPass2 is parametrised by τ with f_c = √2 / (2π τ).
    const double tau = std::numbers::sqrt2 / (2.0 * std::numbers::pi * cutoff);
    LowPass2<3> forward(tau, ts), backward(tau, ts);
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = forward.step(x[i]);
    for (std::size_t i = x.size(); i-- > 0;) y[i] = backward.step(y[i]);
    return y;
}

Quat DriftReduction::markleyMean(const std::vector<Quat>& q) {
    Mat4 m = Mat4::Zero();
    for (const Quat& x : q) {
        const Vec4 v = toVec(x);
        m += v * v.transpose();
    }
    if (q.empty()) return Quat::Identity();
    return toQuat(dominantEigenvector(m, nullptr));
}

bool DriftReduction::windowedMean(const std::vector<Quat>& q, const std::vector<unsigned char>& valid,
                                  std::size_t halfWidth, int minCount, std::vector<Quat>& out) {
    const std::size_t n = q.size();
    out.assign(n, Quat::Identity());
    std::vector<unsigned char> estimated(n, 0);
    Mat4 m = Mat4::Zero();
    long count = 0;
    const auto add = [&](std::size_t i, double sign) {
        if (!valid[i]) return;
        const Vec4 v = toVec(q[i]);
        m.noalias() += sign * (v * v.transpose());
        count += sign > 0 ? 1 : -1;
    };
    // Window [k − w, k + w]: start with [0, w − 1], then enter k + w and leave k − w − 1 each step.
    for (std::size_t i = 0; i < std::min(halfWidth, n); ++i) add(i, 1.0);
    Vec4 previous;
    bool havePrevious = false;
    for (std::size_t k = 0; k < n; ++k) {
        if (k + halfWidth < n) add(k + halfWidth, 1.0);
        if (k > halfWidth) add(k - halfWidth - 1, -1.0);
        if (count < minCount) {
            havePrevious = false;
            continue;
        }
        Vec4 v = dominantEigenvector(m, havePrevious ? &previous : nullptr);
        if (havePrevious && v.dot(previous) < 0.0) v = -v;
        previous = v;
        havePrevious = true;
        out[k] = toQuat(v);
        estimated[k] = 1;
    }
    // Fill the gaps by SLERP between the neighbouring estimates; hold at both ends.
    std::size_t last = n;  // last estimated index
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) {
        if (!estimated[k]) continue;
        any = true;
        if (last == n) {
            for (std::size_t i = 0; i < k; ++i) out[i] = out[k];
        } else if (k > last + 1) {
            for (std::size_t i = last + 1; i < k; ++i)
                out[i] = math::slerp(out[last], out[k], double(i - last) / double(k - last));
        }
        last = k;
    }
    if (!any) return false;
    for (std::size_t i = last + 1; i < n; ++i) out[i] = out[last];
    return true;
}

bool DriftReduction::windowedWahba(const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                                   const std::vector<unsigned char>& valid, std::size_t halfWidth, std::size_t step,
                                   int minCount, bool aboutVertical, std::vector<Quat>& out, double prior,
                                   std::size_t stride, std::size_t outSize) {
    const std::size_t n = from.size();
    stride = std::max<std::size_t>(1, stride);
    const std::size_t size = std::max(outSize, n == 0 ? 0 : (n - 1) * stride + 1);
    if (n == 0) {
        out.assign(size, Quat::Identity());
        return false;
    }
    step = std::max<std::size_t>(1, step);
    // B = Σ to·fromᵀ over the window, kept as a running sum: the window only moves forward, so every
    // sample enters and leaves once.
    Mat3 window = Mat3::Zero();
    long count = 0;
    std::size_t lo = 0, hi = 0;  // window [lo, hi)
    std::vector<std::size_t> at;
    std::vector<Quat> rotation;
    for (std::size_t k = 0; k < n; k += step) {
        const std::size_t a = k > halfWidth ? k - halfWidth : 0, b = std::min(n, k + halfWidth + 1);
        for (; hi < b; ++hi)
            if (valid[hi]) {
                window.noalias() += to[hi] * from[hi].transpose();
                ++count;
            }
        for (; lo < a; ++lo)
            if (valid[lo]) {
                window.noalias() -= to[lo] * from[lo].transpose();
                --count;
            }
        if (count < minCount) continue;
        const Mat3& bm = window;
        if (aboutVertical) {
            // Rotation about z only: ψ = atan2(Σ (from × to)_z, Σ from·to) of the horizontal parts.
            at.push_back(k);
            rotation.push_back(math::headingRotation(std::atan2(bm(1, 0) - bm(0, 1), bm(0, 0) + bm(1, 1))));
            continue;
        }
        // Wahba's problem: R maximising tr(Rᵀ B) (Markley 1988: SVD solution). A weak pull towards the
        // identity (+λI) keeps R defined when all vectors of the window are parallel (at rest they are
        // all gravity, and the rotation about them is unobservable): then R is the smallest rotation.
        at.push_back(k);
        rotation.push_back(Quat(properRotation(bm + prior * bm.norm() * Mat3::Identity())).normalized());
    }
    if (at.empty()) {
        out.assign(size, Quat::Identity());
        return false;
    }
    // Every output sample: held before the first and after the last estimate, SLERP in between (in
    // output samples: estimate j is at output sample at[j]·stride).
    out.resize(size);
    for (std::size_t k = 0; k <= at.front() * stride; ++k) out[k] = rotation.front();
    for (std::size_t j = 0; j + 1 < at.size(); ++j) {
        const std::size_t first = at[j] * stride, last = at[j + 1] * stride;
        SlerpSegment(rotation[j], rotation[j + 1]).sweep(last - first, [&](std::size_t i, const Quat& r) {
            out[first + i] = r;
        });
        out[last] = rotation[j + 1];
    }
    for (std::size_t k = at.back() * stride + 1; k < size; ++k) out[k] = rotation.back();
    return true;
}

DriftReduction::Result DriftReduction::run(const std::vector<Segment>& segments, const std::vector<Link>& links,
                                           double ts, const Progress& progress) const {
    const Params& p = params_;
    Result result;
    result.q.reserve(segments.size());
    for (const Segment& s : segments) result.q.push_back(s.q);
    result.links.resize(links.size());
    result.restIntervals.assign(segments.size(), 0);
    const std::size_t n = segments.empty() ? 0 : segments.front().q.size();
    const auto report = [&](double f) { return !progress || progress(f); };
    const auto cancelled = [&]() {
        result.q.clear();
        return result;
    };

    // (a) Static correction (Fasel 2017 Eq. 2.7, spread by SLERP between rest instants).
    if (p.staticCorrection) {
        for (std::size_t s = 0; s < segments.size(); ++s) {
            RestDetector rest(p.rest, ts);
            std::vector<std::size_t> anchor;
            std::vector<Quat> anchorDelta;
            std::size_t begin = n;
            Vec3 sum = Vec3::Zero();
            for (std::size_t k = 0; k <= n; ++k) {
                bool isRest = false;
                if (k < n) {
                    rest.updateGyr(segments[s].gyr[k]);
                    rest.updateAcc(segments[s].acc[k]);
                    isRest = rest.isRest();
                }
                if (isRest) {
                    if (begin == n) {
                        begin = k;
                        sum.setZero();
                    }
                    sum += result.q[s][k] * segments[s].acc[k];
                } else if (begin != n) {
                    // The measured specific force at rest points up: δ takes it onto e_z.
                    if (sum.norm() > 0.0) {
                        anchor.push_back((begin + k - 1) / 2);
                        anchorDelta.push_back(Quat::FromTwoVectors(sum, Vec3::UnitZ()));
                    }
                    begin = n;
                }
            }
            result.restIntervals[s] = static_cast<int>(anchor.size());
            if (anchor.empty()) continue;
            std::vector<Quat>& q = result.q[s];
            const auto apply = [&](std::size_t from, std::size_t to, const Quat& d) {
                for (std::size_t k = from; k < to; ++k) q[k] = (d * q[k]).normalized();
            };
            apply(0, std::min(n, anchor.front() + 1), anchorDelta.front());
            for (std::size_t j = 0; j + 1 < anchor.size(); ++j) {
                const std::size_t first = anchor[j];
                SlerpSegment(anchorDelta[j], anchorDelta[j + 1])
                    .sweep(anchor[j + 1] - first,
                           [&](std::size_t i, const Quat& d) { q[first + i] = (d * q[first + i]).normalized(); });
                q[anchor[j + 1]] = (anchorDelta[j + 1] * q[anchor[j + 1]]).normalized();
            }
            apply(anchor.back() + 1, n, anchorDelta.back());
        }
    }
    if (!report(0.1)) return cancelled();
    if (!p.jointCorrection || links.empty() || n < 3) return result;

    // Chain order: the root (never distal) first, then breadth first (Eqs. 5.12–5.14).
    std::vector<int> isDistal(segments.size(), 0);
    for (const Link& l : links) isDistal[static_cast<std::size_t>(l.distal)] = 1;
    int root = 0;
    while (root < static_cast<int>(segments.size()) && isDistal[static_cast<std::size_t>(root)]) ++root;
    std::vector<std::size_t> order;
    {
        std::vector<int> frontier{root};
        while (!frontier.empty()) {
            std::vector<int> next;
            for (int s : frontier)
                for (std::size_t l = 0; l < links.size(); ++l)
                    if (links[l].proximal == s) {
                        order.push_back(l);
                        next.push_back(links[l].distal);
                    }
            frontier = std::move(next);
        }
    }

    // Low-passed ω and its derivative per sensor.
    std::vector<Kinematics> kin(segments.size());
    for (std::size_t s = 0; s < segments.size(); ++s) {
        kin[s].omega = zeroPhaseLowPass(segments[s].gyr, p.gyrCutoff, ts);
        kin[s].rate = 1.0 / ts;
    }
    if (!report(0.2)) return cancelled();

    // Sensor-to-joint vectors by Nelder–Mead on Eq. 5.5. The cost compares the virtual accelerations
    // in the earth frame, so the very drift to be removed would bias r; each block of `fitBlock`
    // seconds therefore gets its own best rotation (Kabsch), which a slowly growing drift cannot
    // affect — the cost is Σ|R_block ã_d^G − ã_p^G| instead of Σ|ã_d^G − ã_p^G|.
    const auto fitVectors = [&](std::size_t l) {
        const auto ip = static_cast<std::size_t>(links[l].proximal), id = static_cast<std::size_t>(links[l].distal);
        LinkResult& lr = result.links[l];
        std::vector<std::size_t> c;
        for (std::size_t k = 0; k < n; ++k)
            if (kin[ip].omega[k].norm() > p.omegaThreshold) c.push_back(k);
        // A proximal segment that hardly turns (the pelvis in walking) leaves too few samples; then the
        // distal segment's rotation has to provide the excitation.
        if (c.size() < static_cast<std::size_t>(p.minFitSamples)) {
            c.clear();
            for (std::size_t k = 0; k < n; ++k)
                if (std::max(kin[ip].omega[k].norm(), kin[id].omega[k].norm()) > p.omegaThreshold) c.push_back(k);
            lr.distalExcitation = true;
        }
        if (c.size() > static_cast<std::size_t>(p.maxOptimisationSamples)) {
            std::vector<std::size_t> thinned(static_cast<std::size_t>(p.maxOptimisationSamples));
            for (std::size_t i = 0; i < thinned.size(); ++i) thinned[i] = c[i * c.size() / thinned.size()];
            c = std::move(thinned);
        }
        lr.optimisationSamples = static_cast<int>(c.size());
        if (c.size() < 10) return;
        // Blocks: consecutive samples within fitBlock seconds (longer for long recordings, so that there
        // are at most maxFitBlocks), at least 10 samples each.
        const double block = std::max(p.fitBlock, double(c.back() - c.front()) * ts / std::max(1, p.maxFitBlocks));
        std::vector<std::size_t> blockStart{0};
        for (std::size_t i = 1; i < c.size(); ++i)
            if (double(c[i] - c[blockStart.back()]) * ts > block && i - blockStart.back() >= 10)
                blockStart.push_back(i);
        if (blockStart.size() > 1 && c.size() - blockStart.back() < 10) blockStart.pop_back();
        blockStart.push_back(c.size());
        // Structure of arrays (one column per sample) so that the cost, evaluated a few hundred times,
        // runs as vectorised Eigen expressions: ã^G = A + Σ_j B_j r_j with A = R a and B_j the j-th
        // column of R K (Eq. 5.4), stacked as rows 3j … 3j + 2.
        const auto m = static_cast<Eigen::Index>(c.size());
        using Rows3 = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>;
        using Rows9 = Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::RowMajor>;
        Rows3 ap(3, m), ad(3, m), up(3, m), ud(3, m), residual(3, m);
        Rows9 bp(9, m), bd(9, m);
        for (Eigen::Index i = 0; i < m; ++i) {
            const std::size_t k = c[static_cast<std::size_t>(i)];
            const Mat3 rp = result.q[ip][k].toRotationMatrix(), rd = result.q[id][k].toRotationMatrix();
            ap.col(i) = rp * segments[ip].acc[k];
            ad.col(i) = rd * segments[id].acc[k];
            bp.col(i) = (rp * kin[ip].k(k)).reshaped();
            bd.col(i) = (rd * kin[id].k(k)).reshaped();
        }
        std::vector<Mat3> profile(blockStart.size() - 1);
        const auto cost = [&](const Eigen::VectorXd& x) {
            up = ap + bp.middleRows<3>(0) * x[0] + bp.middleRows<3>(3) * x[1] + bp.middleRows<3>(6) * x[2];
            ud = ad + bd.middleRows<3>(0) * x[3] + bd.middleRows<3>(3) * x[4] + bd.middleRows<3>(6) * x[5];
            // Σ up udᵀ per block, as nine vectorised dot products over the block, and their sum.
            Mat3 total = Mat3::Zero();
            for (std::size_t b = 0; b + 1 < blockStart.size(); ++b) {
                const auto from = static_cast<Eigen::Index>(blockStart[b]);
                const auto len = static_cast<Eigen::Index>(blockStart[b + 1]) - from;
                const auto bu = up.middleCols(from, len);
                const auto bv = ud.middleCols(from, len);
                Mat3& h = profile[b];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) h(i, j) = bu.row(i).dot(bv.row(j));
                total += h;
            }
            // Each block's rotation ud → up (Kabsch) with a weak pull towards the common rotation of all
            // blocks (the drift changes little from one block to the next): where a block's vectors are
            // nearly parallel (all close to gravity: walking), the rotation about them follows the others.
            const Mat3 common = p.fitPrior > 0.0 ? properRotation(total) : Mat3::Identity();
            double e = 0.0;
            for (std::size_t b = 0; b + 1 < blockStart.size(); ++b) {
                const auto from = static_cast<Eigen::Index>(blockStart[b]);
                const auto len = static_cast<Eigen::Index>(blockStart[b + 1]) - from;
                const Mat3& h = profile[b];
                const Mat3 turn = properRotation(p.fitPrior > 0.0 ? Mat3(h + p.fitPrior * h.norm() * common) : h);
                auto r = residual.middleCols(from, len);
                r.noalias() = turn * ud.middleCols(from, len);
                r -= up.middleCols(from, len);
                e += (r.row(0).array().square() + r.row(1).array().square() + r.row(2).array().square()).sqrt().sum();
            }
            return e / double(c.size());
        };
        NelderMead::Params nm;
        nm.initialStep = 0.1;
        nm.xTolerance = 1e-4;
        nm.fTolerance = 1e-7;
        const NelderMead::Result best = NelderMead::minimize(cost, Eigen::VectorXd::Zero(6), nm);
        lr.proximalToJoint = best.x.head<3>();
        lr.distalToJoint = best.x.tail<3>();
        lr.optimisationCost = best.value;
    };

    // The drift estimates use every `stride`-th sample (Params::estimationRate): ne samples, sample j of
    // them being sample j·stride of the recording.
    const std::size_t stride =
        p.estimator == Estimator::Wahba && p.estimationRate > 0.0
            ? std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(1.0 / (ts * p.estimationRate) + 1e-9)))
            : 1;
    const std::size_t ne = (n - 1) / stride + 1;
    const double te = ts * double(stride);  // their spacing

    // Virtual joint accelerations of both ends of a link with the orientations q (at the estimation samples).
    std::vector<Vec3> gp(ne), gd(ne);
    const auto virtualAccelerations = [&](const std::vector<std::vector<Quat>>& q, const Link& link,
                                          const LinkResult& lr) {
        const auto ip = static_cast<std::size_t>(link.proximal), id = static_cast<std::size_t>(link.distal);
        for (std::size_t j = 0, k = 0; j < ne; ++j, k += stride) {
            gp[j] = q[ip][k] * kin[ip].virtualAcc(segments[ip].acc[k], k, lr.proximalToJoint);
            gd[j] = q[id][k] * kin[id].virtualAcc(segments[id].acc[k], k, lr.distalToJoint);
        }
    };

    const auto halfWidth = static_cast<std::size_t>(std::lround(p.window / te));
    std::vector<Quat> delta, smoothed(n);  // delta: per-sample drifts of the Markley estimator only
    if (p.estimator == Estimator::Markley) delta.resize(n);
    std::vector<unsigned char> valid(ne);
    const int minCount =
        std::max(p.minWindowSamples, static_cast<int>(std::lround(p.minWindowShare * double(2 * halfWidth + 1))));
    const auto wahbaStep = static_cast<std::size_t>(std::max(1L, std::lround(p.wahbaStep / te)));
    constexpr double kWindowPrior = 0.01;  // the window solution's pull to the identity (windowedWahba)
    // Smoothed drift taking `from` onto `to` (Eqs. 5.6–5.11 + Markley mean); returns the share of valid samples.
    const auto smoothedDrift = [&](const std::vector<Vec3>& from, const std::vector<Vec3>& to, bool horizontal,
                                   std::vector<Quat>& out) {
        const double minNorm = horizontal ? p.azimuthMinNorm : p.minNorm;
        std::size_t used = 0;
        for (std::size_t k = 0; k < ne; ++k) {
            Vec3 u = from[k], v = to[k];
            if (horizontal) u.z() = v.z() = 0.0;
            const double nu = u.norm(), nv = v.norm();
            bool ok = nu > minNorm && nv > minNorm && std::abs(nu - nv) < p.maxNormDifference;
            if (ok && p.maxRelativeDifference > 0.0)
                ok = std::abs(nu - nv) / (0.5 * (nu + nv)) < p.maxRelativeDifference;
            // Opposite vectors leave the axis undefined; they are not drift.
            if (ok && u.dot(v) < -0.5 * nu * nv) ok = false;
            valid[k] = ok;
            if (p.estimator == Estimator::Markley) delta[k] = ok ? Quat::FromTwoVectors(u, v) : Quat::Identity();
            used += ok;
        }
        const bool any = p.estimator == Estimator::Markley
                             ? windowedMean(delta, valid, halfWidth, minCount, out)
                             // The azimuth pass's Wahba solution uses only the horizontal components.
                             : windowedWahba(from, to, valid, halfWidth, wahbaStep, minCount, horizontal, out,
                                             kWindowPrior, stride, n);
        if (!any) out.assign(n, Quat::Identity());
        return double(used) / double(ne);
    };

    // The correction itself (heading alignment, then the passes of Eqs. 5.12–5.14 / 6.12–6.13) of q.
    const auto correct = [&](std::vector<std::vector<Quat>>& q) {
        for (LinkResult& lr : result.links) lr.meanCorrection = 0.0;
        if (p.alignHeading) {
            for (std::size_t l : order) {
                virtualAccelerations(q, links[l], result.links[l]);
                const HeadingFit fit = bestHeading(gd, gp, p.azimuthMinNorm);
                LinkResult& lr = result.links[l];
                lr.headingSamples = static_cast<int>(fit.samples);
                lr.headingCoherence = fit.coherence;
                lr.heading = fit.samples < static_cast<std::size_t>(minCount) ? HeadingStatus::TooFewSamples
                             : fit.coherence < p.minHeadingCoherence          ? HeadingStatus::Incoherent
                                                                              : HeadingStatus::Aligned;
                if (lr.heading != HeadingStatus::Aligned) continue;
                const Quat turn = math::headingRotation(fit.psi);
                for (Quat& x : q[static_cast<std::size_t>(links[l].distal)]) x = (turn * x).normalized();
                lr.headingOffset = fit.psi;
            }
        }
        // A link whose heading could not be aligned is not corrected: its distal segment turns with the
        // proximal one (the correction of the proximal in each pass), so the joint keeps the relative
        // orientation of its input, and it does not take part in the root's mean drift.
        const auto headingKept = [&](std::size_t l) {
            const HeadingStatus h = result.links[l].heading;
            return h == HeadingStatus::TooFewSamples || h == HeadingStatus::Incoherent;
        };
        std::vector<unsigned char> keepsCorrection(segments.size(), 0);
        for (std::size_t l = 0; l < links.size(); ++l)
            if (headingKept(l)) keepsCorrection[static_cast<std::size_t>(links[l].proximal)] = 1;
        std::vector<std::vector<Quat>> passCorrection(segments.size());
        std::vector<std::vector<Quat>> rootDriftStore;
        const std::size_t passes = (p.azimuthPass ? 2 : 1) * static_cast<std::size_t>(std::max(1, p.iterations));
        for (std::size_t pass = 0; pass < passes; ++pass) {
            const bool horizontal = p.azimuthPass && pass % 2 == 1;
            // Root: the mean of its drifts against every neighbour (Eqs. 5.12–5.13).
            std::size_t rootLinks = 0;
            for (std::size_t l = 0; l < links.size(); ++l) {
                if (links[l].proximal != root) continue;
                if (headingKept(l)) continue;
                virtualAccelerations(q, links[l], result.links[l]);
                if (rootLinks == rootDriftStore.size()) rootDriftStore.emplace_back();  // kept between passes
                smoothedDrift(gp, gd, horizontal, rootDriftStore[rootLinks++]);
            }
            const std::span<const std::vector<Quat>> rootDrifts(rootDriftStore.data(), rootLinks);
            std::vector<Quat>& rootCorrection = passCorrection[static_cast<std::size_t>(root)];
            if (keepsCorrection[static_cast<std::size_t>(root)]) rootCorrection.assign(n, Quat::Identity());
            if (!rootDrifts.empty()) {
                std::vector<Quat>& r = q[static_cast<std::size_t>(root)];
                Vec4 previous;
                for (std::size_t k = 0; k < n; ++k) {
                    Vec4 v;
                    if (rootDrifts.size() <= 2) {
                        // Closed form: for unit q₁, q₂ the eigenvectors of q₁q₁ᵀ + q₂q₂ᵀ in their plane are
                        // q₁ ± q₂ with eigenvalues 1 ± q₁·q₂, so the mean is q₁ + sign(q₁·q₂) q₂.
                        v = toVec(rootDrifts.front()[k]);
                        if (rootDrifts.size() == 2) {
                            const Vec4 w = toVec(rootDrifts.back()[k]);
                            v += v.dot(w) < 0.0 ? Vec4(-w) : w;
                        }
                        v.normalize();
                    } else {
                        Mat4 m = Mat4::Zero();
                        for (const auto& d : rootDrifts) {
                            const Vec4 x = toVec(d[k]);
                            m += x * x.transpose();
                        }
                        v = dominantEigenvector(m, k > 0 ? &previous : nullptr);
                    }
                    if (k > 0 && v.dot(previous) < 0.0) v = -v;
                    previous = v;
                    const Quat c = toQuat(v);
                    r[k] = (c * r[k]).normalized();
                    if (!rootCorrection.empty()) rootCorrection[k] = c;
                }
            }
            // Then proximal to distal (Eq. 5.14).
            for (std::size_t l : order) {
                const auto ip = static_cast<std::size_t>(links[l].proximal);
                const auto id = static_cast<std::size_t>(links[l].distal);
                std::vector<Quat>& d = q[id];
                LinkResult& lr = result.links[l];
                if (headingKept(l)) {
                    smoothed = passCorrection[ip];
                    (horizontal ? lr.azimuthValidShare : lr.validShare) = 0.0;
                } else {
                    virtualAccelerations(q, links[l], lr);
                    const double share = smoothedDrift(gd, gp, horizontal, smoothed);
                    (horizontal ? lr.azimuthValidShare : lr.validShare) = share;
                }
                for (std::size_t k = 0; k < n; ++k) d[k] = (smoothed[k] * d[k]).normalized();
                // The mean angle is a summary: sampled at the drift estimates' own spacing (wahbaStep),
                // which spares an acos per sample.
                double angle = 0.0;
                std::size_t count = 0;
                for (std::size_t k = 0; k < n; k += wahbaStep * stride, ++count)
                    angle += 2.0 * std::acos(std::clamp(std::abs(smoothed[k].w()), 0.0, 1.0));
                lr.meanCorrection += angle / double(count);
                if (keepsCorrection[id]) passCorrection[id] = smoothed;
            }
        }
    };

    for (std::size_t l = 0; l < links.size(); ++l) {
        fitVectors(l);
        if (!report(0.2 + 0.4 * double(l + 1) / double(links.size()))) return cancelled();
    }
    correct(result.q);
    if (!report(1.0)) return cancelled();
    return result;
}

}  // namespace athlos::inertial
