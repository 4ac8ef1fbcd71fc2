#include "plugins/positioning/AnchorSmoother.h"

#include "core/estimation/Ekf.h"
#include "core/estimation/RtsSmoother.h"
#include "core/processing/Processor.h"
#include "plugins/signal/Butterworth.h"

#include <algorithm>
#include <cmath>

namespace athlos::positioning {

using math::Vec3;
using Mat3 = Eigen::Matrix3d;

namespace {

constexpr int kP = 0, kV = 3, kA = 6, kO = 9, kB = 12, kPsi = 15;

Mat3 rotZ(double psi) { return Eigen::AngleAxisd(psi, Vec3::UnitZ()).toRotationMatrix(); }
Mat3 rotZDerivative(double psi) {
    Mat3 d = Mat3::Zero();
    d(0, 0) = -std::sin(psi);
    d(0, 1) = -std::cos(psi);
    d(1, 0) = std::cos(psi);
    d(1, 1) = -std::sin(psi);
    return d;
}

// The 16-state model; one measurement slot (3-D) whose meaning the smoother switches before each
// update: the acceleration a + b, a zero velocity, or an anchor R_z(ψ)(p + vΔ) + o.
struct AnchorModel : estimation::ModelDefaults<16, 3> {
    enum class Mode { Acceleration, Zupt, Anchor };
    Mode mode = Mode::Acceleration;
    Mat3 R = Mat3::Identity();
    double delta = 0.0;
    double jerkPsd = 1.0;     // m²/s⁵
    double offsetWalk = 0.0;  // (m/s²)²/s
    double anchorOffsetWalk = 1e-8, azimuthWalk = 1e-10;

    StateVector predict(const StateVector& x, double T, double, StateMatrix* jacobian) const {
        StateMatrix F = StateMatrix::Identity();
        F.block<3, 3>(kP, kV) = T * Mat3::Identity();
        F.block<3, 3>(kP, kA) = 0.5 * T * T * Mat3::Identity();
        F.block<3, 3>(kV, kA) = T * Mat3::Identity();
        if (jacobian) *jacobian = F;
        return F * x;
    }
    StateMatrix processNoise(double T, double) const {
        // White jerk of PSD q on each axis (constant-acceleration model).
        StateMatrix Q = StateMatrix::Zero();
        const double q = jerkPsd, T2 = T * T, T3 = T2 * T;
        for (int i = 0; i < 3; ++i) {
            Q(kP + i, kP + i) = q * T3 * T2 / 20.0;
            Q(kP + i, kV + i) = Q(kV + i, kP + i) = q * T2 * T2 / 8.0;
            Q(kP + i, kA + i) = Q(kA + i, kP + i) = q * T3 / 6.0;
            Q(kV + i, kV + i) = q * T3 / 3.0;
            Q(kV + i, kA + i) = Q(kA + i, kV + i) = q * T2 / 2.0;
            Q(kA + i, kA + i) = q * T;
            Q(kO + i, kO + i) = anchorOffsetWalk * T;
            Q(kB + i, kB + i) = offsetWalk * T;
        }
        Q(kPsi, kPsi) = azimuthWalk * T;
        return Q;
    }
    Measurement measure(const StateVector& x, double) const {
        switch (mode) {
            case Mode::Acceleration:
                return x.segment<3>(kA) + x.segment<3>(kB);
            case Mode::Zupt:
                return x.segment<3>(kV);
            case Mode::Anchor:
                return rotZ(x(kPsi)) * (x.segment<3>(kP) + delta * x.segment<3>(kV)) + x.segment<3>(kO);
        }
        return Measurement::Zero();
    }
    MeasurementJacobian measurementJacobian(const StateVector& x, double) const {
        MeasurementJacobian H = MeasurementJacobian::Zero();
        switch (mode) {
            case Mode::Acceleration:
                H.block<3, 3>(0, kA) = Mat3::Identity();
                H.block<3, 3>(0, kB) = Mat3::Identity();
                break;
            case Mode::Zupt:
                H.block<3, 3>(0, kV) = Mat3::Identity();
                break;
            case Mode::Anchor: {
                const Mat3 Rz = rotZ(x(kPsi));
                H.block<3, 3>(0, kP) = Rz;
                H.block<3, 3>(0, kV) = delta * Rz;
                H.block<3, 3>(0, kO) = Mat3::Identity();
                H.col(kPsi) = rotZDerivative(x(kPsi)) * (x.segment<3>(kP) + delta * x.segment<3>(kV));
                break;
            }
        }
        return H;
    }
    MeasurementMatrix measurementNoise(double) const { return R; }
};

struct Grid {
    std::vector<double> t;
    std::vector<Vec3> acc;
    std::vector<unsigned char> still;
};

// Block averages of the IMU samples onto a grid of about `rate`.
Grid makeGrid(const AnchorSmoother::Input& in, double rate) {
    Grid g;
    const std::size_t n = in.t.size();
    const double dtIn = (in.t.back() - in.t.front()) / double(n - 1);
    const std::size_t f = std::max<std::size_t>(1, std::size_t(std::lround(1.0 / (rate * dtIn))));
    for (std::size_t b = 0; b + f <= n; b += f) {
        double t = 0.0;
        Vec3 a = Vec3::Zero();
        bool still = true;
        for (std::size_t k = b; k < b + f; ++k) {
            t += in.t[k];
            a += in.acc[k];
            still = still && in.still[k];
        }
        g.t.push_back(t / double(f));
        g.acc.push_back(a / double(f));
        g.still.push_back(still ? 1 : 0);
    }
    return g;
}

struct Anchor {
    std::size_t node = 0;
    double delta = 0.0;
    Vec3 y;
    int crossing = -1, gate = -1;
};

struct PassResult {
    std::vector<estimation::SmootherNode<16>> nodes;
};

std::size_t nearestNode(const std::vector<double>& t, double time) {
    const auto it = std::lower_bound(t.begin(), t.end(), time);
    if (it == t.begin()) return 0;
    if (it == t.end()) return t.size() - 1;
    const std::size_t k = std::size_t(it - t.begin());
    return time - t[k - 1] < t[k] - time ? k - 1 : k;
}

}  // namespace

Vec3 AnchorSmoother::sacrumToMagnet(const Vec3& velocity, double distance, int side, double height) {
    const Vec3 up = Vec3::UnitZ();
    Vec3 vhat = velocity.norm() > 1e-6 ? Vec3(velocity.normalized()) : Vec3::UnitX();
    if (std::abs(vhat.z()) > 0.99) vhat = Vec3::UnitX();
    const Vec3 down = -(up - up.dot(vhat) * vhat).normalized();  // d_m direction (eq. 9.3), ⟂ v
    const Vec3 left = up.cross(vhat).normalized();               // ⟂ v and d_m (eqs. 9.4/9.5)
    const double h = std::min(height, distance);
    const double lateral = std::sqrt(std::max(0.0, distance * distance - h * h));
    return h * down + double(side) * lateral * left;  // eq. 9.2
}

std::vector<unsigned char> AnchorSmoother::startFinishStill(const std::vector<double>& gyrNorm,
                                                            const std::vector<double>& freeAccNorm, double gyrLimit,
                                                            double accLimit) {
    const std::size_t n = std::min(gyrNorm.size(), freeAccNorm.size());
    std::vector<unsigned char> still(n, 0);
    auto quiet = [&](std::size_t k) { return gyrNorm[k] < gyrLimit && freeAccNorm[k] < accLimit; };
    std::size_t k = 0;
    while (k < n && quiet(k)) still[k++] = 1;
    if (k == n) return still;  // never moved: all still
    std::size_t e = n;
    while (e > 0 && quiet(e - 1)) still[--e] = 1;
    return still;
}

std::vector<int> AnchorSmoother::matchGates(const std::vector<Vec3>& est, const std::vector<Gate>& gates, double radius,
                                            bool relative) {
    const int M = int(est.size()), N = int(gates.size());
    constexpr int kLookAhead = 4;
    std::vector<int> best(M, -1);
    int bestCount = 0;
    double bestCost = 0.0;
    auto run = [&](int m0, int n0) {
        std::vector<int> match(M, -1);
        int count = 0, lastM = -1, lastN = n0 - 1;
        double cost = 0.0;
        for (int m = m0; m < M; ++m) {
            int pick = -1;
            double pickDist = radius;
            for (int n = lastN + 1; n < std::min(N, lastN + 1 + kLookAhead); ++n) {
                Vec3 predicted = est[m];
                if (relative) {
                    if (lastM < 0)
                        predicted = gates[n0].position;  // the hypothesis: crossing m0 is gate n0
                    else
                        predicted = gates[lastN].position + (est[m] - est[lastM]);
                }
                const Vec3 diff = predicted - gates[n].position;
                const double dist = Eigen::Vector2d(diff.x(), diff.y()).norm();
                if (dist < pickDist) pickDist = dist, pick = n;
            }
            if (relative && lastM < 0 && pick != n0) continue;
            if (pick < 0) continue;
            match[m] = pick;
            ++count;
            cost += pickDist;
            lastM = m;
            lastN = pick;
        }
        if (count > bestCount || (count == bestCount && count > 0 && cost < bestCost)) {
            best = match;
            bestCount = count;
            bestCost = cost;
        }
    };
    if (relative) {
        for (int m0 = 0; m0 < std::min(M, 3); ++m0)
            for (int n0 = 0; n0 < std::min(N, 4); ++n0) run(m0, n0);
    } else {
        run(0, 0);
    }
    return best;
}

Expected<AnchorSmoother::Result> AnchorSmoother::run(const Input& in,
                                                     const std::function<bool(double)>& keepGoing) const {
    const Params& P = params_;
    if (in.t.size() < 10 || in.acc.size() != in.t.size() || in.still.size() != in.t.size())
        return makeError(QStringLiteral("too few samples for the anchor smoother"));
    const Grid grid = makeGrid(in, P.rate);
    const std::size_t n = grid.t.size();
    if (n < 3) return makeError(QStringLiteral("too few samples for the anchor smoother"));

    using Ekf = estimation::Ekf<AnchorModel>;
    using Node = estimation::SmootherNode<16>;
    Result result;
    result.stillNodes = int(std::count(grid.still.begin(), grid.still.end(), 1));

    const int passes = std::max(0, P.passes);
    std::vector<Node> nodes(n);
    Vec3 offset0 = in.start.value_or(Vec3::Zero());
    double offsetSigma0 = in.start ? P.startSigma : 1.0;
    std::vector<Anchor> anchors;
    std::vector<int> matched;

    auto smooth = [&](double anchorSigma, double gate, int pass) -> bool {
        AnchorModel model;
        model.offsetWalk = P.accOffsetWalk * P.accOffsetWalk;
        Ekf ekf(model);
        Ekf::StateVector x0 = Ekf::StateVector::Zero();
        x0.segment<3>(kO) = offset0;
        Ekf::StateMatrix P0 = Ekf::StateMatrix::Zero();
        P0.block<3, 3>(kP, kP) = 1e-6 * Mat3::Identity();
        P0.block<3, 3>(kV, kV) = 0.05 * 0.05 * Mat3::Identity();
        P0.block<3, 3>(kA, kA) = 4.0 * Mat3::Identity();
        P0.block<3, 3>(kO, kO) = offsetSigma0 * offsetSigma0 * Mat3::Identity();
        P0.block<3, 3>(kB, kB) = P.accOffsetSigma * P.accOffsetSigma * Mat3::Identity();
        P0(kPsi, kPsi) = P.azimuthSigma * P.azimuthSigma;
        ekf.reset(x0, P0);
        std::size_t next = 0;
        const Mat3 Racc = P.accSigma * P.accSigma * Mat3::Identity();
        const Mat3 Rzupt = P.zuptSigma * P.zuptSigma * Mat3::Identity();
        const Mat3 Ranchor = anchorSigma * anchorSigma * Mat3::Identity();
        for (std::size_t k = 0; k < n; ++k) {
            Node& node = nodes[k];
            node.t = grid.t[k];
            if (k > 0) {
                const double T = grid.t[k] - grid.t[k - 1];
                const double jerk = (grid.acc[k] - grid.acc[k - 1]).norm() / T;
                ekf.model().jerkPsd = (P.jerkBase * P.jerkBase + jerk * jerk) * T;
                node.C = ekf.predict(T, grid.t[k]);
            } else {
                node.C.setZero();
            }
            node.xp = ekf.x();
            node.Pp = ekf.covariance();
            ekf.model().mode = AnchorModel::Mode::Acceleration;
            ekf.model().R = Racc;
            ekf.update(grid.acc[k], grid.t[k]);
            if (grid.still[k]) {
                ekf.model().mode = AnchorModel::Mode::Zupt;
                ekf.model().R = Rzupt;
                ekf.update(Vec3::Zero(), grid.t[k]);
            }
            while (next < anchors.size() && anchors[next].node == k) {
                ekf.model().mode = AnchorModel::Mode::Anchor;
                ekf.model().R = Ranchor;
                ekf.model().delta = anchors[next].delta;
                ekf.update(anchors[next].y, grid.t[k], gate);
                ++next;
            }
            node.xf = ekf.x();
            node.Pf = ekf.covariance();
            if (keepGoing && k % 500 == 0 && !keepGoing((pass + 0.5 * double(k) / double(n)) / (passes + 1)))
                return false;
        }
        estimation::RtsSmoother<AnchorModel> rts(ekf.model());
        rts.smoothAll(nodes);
        return true;
    };

    // Position, velocity in G (from the current smoothed nodes) at time t.
    auto stateAt = [&](double time, Vec3& pos, Vec3& vel) {
        const std::size_t k = nearestNode(grid.t, time);
        const auto& x = nodes[k].xf;
        const double d = time - grid.t[k];
        const Mat3 Rz = rotZ(x(kPsi));
        pos = Rz * (x.segment<3>(kP) + d * x.segment<3>(kV) + 0.5 * d * d * x.segment<3>(kA)) + x.segment<3>(kO);
        vel = Rz * (x.segment<3>(kV) + d * x.segment<3>(kA));
    };
    auto buildAnchors = [&](bool relative) {
        std::vector<Vec3> estimated, rel;
        for (const auto& c : in.crossings) {
            Vec3 pos, vel;
            stateAt(c.t, pos, vel);
            rel.push_back(sacrumToMagnet(vel, c.distance, c.side, P.sacrumHeight));
            estimated.push_back(pos + rel.back());
        }
        matched = matchGates(estimated, in.gates, P.matchRadius, relative);
        anchors.clear();
        for (std::size_t m = 0; m < in.crossings.size(); ++m) {
            if (matched[m] < 0) continue;
            Anchor a;
            a.node = nearestNode(grid.t, in.crossings[m].t);
            a.delta = in.crossings[m].t - grid.t[a.node];
            a.y = in.gates[std::size_t(matched[m])].position - rel[m];
            a.crossing = int(m);
            a.gate = matched[m];
            anchors.push_back(a);
        }
        std::stable_sort(anchors.begin(), anchors.end(),
                         [](const Anchor& a, const Anchor& b) { return a.node < b.node; });
    };

    if (!smooth(1.0, estimation::kNoGate, 0)) return cancelledError();
    for (const auto& c : in.crossings) {  // pass-0 gate estimates (GNSS-free averaging over runs, ch. 10)
        Vec3 pos, vel;
        stateAt(c.t, pos, vel);
        result.inertialGates.push_back(pos + sacrumToMagnet(vel, c.distance, c.side, P.sacrumHeight));
    }
    for (int pass = 1; pass <= passes; ++pass) {
        buildAnchors(pass == 1);
        if (anchors.empty()) return makeError(QStringLiteral("no detected crossing matches a gate"));
        if (pass == 1 && !in.start) {
            // The translation I → G from the matches (ψ starts at 0): the median offset per axis.
            std::vector<double> ox, oy, oz;
            for (const auto& a : anchors) {
                const Vec3 p = nodes[a.node].xf.segment<3>(kP) + a.delta * nodes[a.node].xf.segment<3>(kV);
                const Vec3 o = a.y - p;
                ox.push_back(o.x());
                oy.push_back(o.y());
                oz.push_back(o.z());
            }
            auto med = [](std::vector<double> v) {
                std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
                return v[v.size() / 2];
            };
            offset0 = Vec3(med(ox), med(oy), med(oz));
            offsetSigma0 = 20.0;
        }
        const double sigma = pass == 1 ? P.anchorSigma1 : P.anchorSigma2;
        const double gate = pass == 1 ? estimation::kNoGate : P.anchorGate;
        if (!smooth(sigma, gate, pass)) return cancelledError();
    }

    // Output in G, low-passed.
    Eigen::MatrixXd out(Eigen::Index(n), 6);
    for (std::size_t k = 0; k < n; ++k) {
        const auto& x = nodes[k].xf;
        const Mat3 Rz = rotZ(x(kPsi));
        out.row(Eigen::Index(k)).head<3>() = (Rz * x.segment<3>(kP) + x.segment<3>(kO)).transpose();
        out.row(Eigen::Index(k)).tail<3>() = (Rz * x.segment<3>(kV)).transpose();
    }
    const double rate = double(n - 1) / (grid.t.back() - grid.t.front());
    if (P.lowPass > 0.0 && P.lowPass < 0.5 * rate && n > 12) {
        signal::Butterworth::Params bp;
        bp.order = 2;
        bp.cutoff = P.lowPass;
        bp.samplingRate = rate;
        const signal::Butterworth filter(bp);
        for (int c = 0; c < 6; ++c) {
            Eigen::VectorXd col = out.col(c);
            filter.filtFilt(col);
            out.col(c) = col;
        }
    }
    result.t = grid.t;
    result.position.resize(n);
    result.velocity.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        result.position[k] = out.row(Eigen::Index(k)).head<3>().transpose();
        result.velocity[k] = out.row(Eigen::Index(k)).tail<3>().transpose();
    }
    result.azimuthOffset = nodes.back().xf(kPsi);
    result.positionOffset = nodes.back().xf.segment<3>(kO);
    for (const auto& a : anchors) {
        Vec3 pos, vel;
        stateAt(in.crossings[std::size_t(a.crossing)].t, pos, vel);
        result.matches.push_back({a.crossing, a.gate, a.y, (a.y - pos).norm()});
    }
    if (keepGoing) keepGoing(1.0);
    return result;
}

}  // namespace athlos::positioning
