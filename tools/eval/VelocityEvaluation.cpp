#include "tools/eval/VelocityEvaluation.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/events/GaitParametersProcessor.h"
#include "plugins/inertial/OrientationEstimation.h"
#include "plugins/inertial/OrientationProcessor.h"
#include "plugins/inertial/VelocityResetProcessor.h"
#include "tools/eval/GaitEvaluation.h"

#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

namespace athlos::inertial {

using math::Quat;
using math::Vec3;

double ErrorStat::mean() const {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
}
double ErrorStat::sd() const {
    const double m = mean();
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return v.size() > 1 ? std::sqrt(s / double(v.size() - 1)) : 0.0;
}
double ErrorStat::meanAbs() const {
    double s = 0;
    for (double x : v) s += std::abs(x);
    return v.empty() ? 0.0 : s / double(v.size());
}
double ErrorStat::maxAbs() const {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

namespace {
void append(ErrorStat& a, const ErrorStat& b) { a.v.insert(a.v.end(), b.v.begin(), b.v.end()); }

// 6D VQF on row-major acc_x..z, gyr_x..z rows, then velocity resets.
struct Run {
    VelocityReset::Result r;
    std::vector<Vec3> acc, gyr;
};
Run runOnRows(const std::vector<double>& rows, std::size_t n, double ts, const VelocityReset::Params& params,
              bool strapdown) {
    Run run;
    run.acc.resize(n);
    run.gyr.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        for (int a = 0; a < 3; ++a) {
            run.acc[k][a] = rows[6 * k + std::size_t(a)];
            run.gyr[k][a] = rows[6 * k + 3 + std::size_t(a)];
        }
    OrientationOptions options;
    options.useMagnetometer = false;
    if (strapdown) options.algorithm = OrientationAlgorithm::Strapdown;
    const ImuBatch batch{rows.data() + 3, rows.data(), nullptr, n, 6};
    const OrientationRun orientation = estimateOrientation(options, batch, ts);
    run.r = VelocityReset(params).run(orientation.track.q, run.acc, run.gyr, ts);
    return run;
}

// The inertial acceleration integrated from the first anchor without any reset.
std::vector<Vec3> withoutResets(const VelocityReset::Result& r, double ts) {
    std::vector<Vec3> v(r.acceleration.size(), Vec3::Zero());
    for (std::size_t k = r.first + 1; k < v.size(); ++k)
        v[k] = v[k - 1] + 0.5 * ts * (r.acceleration[k - 1] + r.acceleration[k]);
    return v;
}

std::size_t sampleAt(const std::vector<double>& t, double time) {
    const auto it = std::lower_bound(t.begin(), t.end(), time);
    if (it == t.end()) return t.size() - 1;
    const auto k = std::size_t(it - t.begin());
    return (k > 0 && time - t[k - 1] < t[k] - time) ? k - 1 : k;
}
}  // namespace

void SkiVelocityScore::add(const SkiVelocityScore& o) {
    const double n0 = truthThrusts, n1 = o.truthThrusts;
    if (n0 + n1 > 0) {
        speedRmse = std::sqrt((n0 * speedRmse * speedRmse + n1 * o.speedRmse * o.speedRmse) / (n0 + n1));
        speedRmseNoReset = std::sqrt(
            (n0 * speedRmseNoReset * speedRmseNoReset + n1 * o.speedRmseNoReset * o.speedRmseNoReset) / (n0 + n1));
    }
    truthThrusts += o.truthThrusts;
    matchedThrusts += o.matchedThrusts;
    extraPhases += o.extraPhases;
    append(cycleSpeed, o.cycleSpeed);
    append(cycleSpeedPct, o.cycleSpeedPct);
    append(cycleLength, o.cycleLength);
    append(thrustStart, o.thrustStart);
    append(thrustEnd, o.thrustEnd);
}

SkiVelocityScore evaluateSkiVelocity(unsigned seed, int cycles, const VelocityReset::Params& params, bool strapdown) {
    events::SkiCycleSimConfig config;
    config.seed = seed;
    config.cycles = cycles;
    const events::SkiCycleRecording rec = events::simulateSkiCycles(config);
    const std::size_t n = rec.t.size();
    const double ts = 1.0 / config.rate;
    const Run run = runOnRows(rec.ski, n, ts, params, strapdown);
    const VelocityReset::Result& r = run.r;
    SkiVelocityScore score;
    if (r.last < r.first) return score;
    // Thrusts: the first cycle's thrust merges with the initial stand (not scored, as in
    // athlos-eval-skiing-events); each other true thrust is matched by the phase whose centre lies in it.
    std::vector<char> used(r.phases.size(), 0);
    for (std::size_t c = 1; c < rec.truth.size(); ++c) {
        const events::SkiCycleTruth& truth = rec.truth[c];
        ++score.truthThrusts;
        for (std::size_t i = 0; i < r.phases.size(); ++i) {
            const double tc = rec.t[(r.phases[i].begin + r.phases[i].end - 1) / 2];
            if (tc < truth.thrustStart || tc > truth.thrustEnd) continue;
            used[i] = 1;
            ++score.matchedThrusts;
            score.thrustStart.add(rec.t[r.phases[i].begin] - truth.thrustStart);
            score.thrustEnd.add(rec.t[r.phases[i].end - 1] - truth.thrustEnd);
            break;
        }
    }
    for (std::size_t i = 1; i + 1 < r.phases.size(); ++i) score.extraPhases += used[i] ? 0 : 1;
    // Cycle speed and length: ∫|v| dt from one true thrust start to the next (Fasel 2017 ch. 3).
    for (std::size_t c = 1; c < rec.truth.size(); ++c) {
        const events::SkiCycleTruth& truth = rec.truth[c];
        const std::size_t a = sampleAt(rec.t, truth.thrustStart), b = sampleAt(rec.t, truth.end);
        if (a < r.first || b > r.last || b <= a) continue;
        double length = 0.0;
        for (std::size_t k = a + 1; k <= b; ++k) length += 0.5 * ts * (r.velocity[k - 1].norm() + r.velocity[k].norm());
        const double duration = rec.t[b] - rec.t[a];
        score.cycleLength.add(length - truth.length);
        score.cycleSpeed.add(length / duration - truth.speed);
        score.cycleSpeedPct.add(100.0 * (length / duration - truth.speed) / truth.speed);
    }
    const std::vector<Vec3> raw = withoutResets(r, ts);
    double e = 0.0, e0 = 0.0;
    for (std::size_t k = r.first; k <= r.last; ++k) {
        e += std::pow(r.velocity[k].norm() - rec.speed[k], 2);
        e0 += std::pow(raw[k].norm() - rec.speed[k], 2);
    }
    const double count = double(r.last - r.first + 1);
    score.speedRmse = std::sqrt(e / count);
    score.speedRmseNoReset = std::sqrt(e0 / count);
    return score;
}

void FootVelocityScore::add(const FootVelocityScore& o) {
    truthStrides += o.truthStrides;
    matchedStances += o.matchedStances;
    extraPhases += o.extraPhases;
    append(strideLength, o.strideLength);
    append(strideLengthPct, o.strideLengthPct);
    append(strideLengthNoResetPct, o.strideLengthNoResetPct);
}

events::SimConfig footWalkConfig(unsigned seed) {
    events::SimConfig c;
    c.seed = seed;
    for (int i = 0; i < 12; ++i) {
        events::SimStride s;
        s.length = 1.2 + 0.04 * i;
        s.stance = 0.6 + 0.01 * (i % 3);
        c.strides.push_back(s);
    }
    return c;
}

FootVelocityScore evaluateFootVelocity(const events::SimConfig& config, const VelocityReset::Params& params,
                                       bool strapdown) {
    const events::SimRecording rec = events::simulateFoot(config);
    const std::size_t n = rec.t.size();
    const double ts = 1.0 / config.rate;
    const Run run = runOnRows(rec.values, n, ts, params, strapdown);
    const VelocityReset::Result& r = run.r;
    FootVelocityScore score;
    if (r.last < r.first) return score;
    // Stances: the still foot before each swing, [swingStart − stance, swingStart]; the first merges
    // with the initial stand (not scored, nor is the stand's phase counted as extra).
    std::vector<char> used(r.phases.size(), 0);
    for (std::size_t s = 1; s < rec.truth.size(); ++s) {
        const events::SimTruth& truth = rec.truth[s];
        ++score.truthStrides;
        const double a = truth.swingStart - truth.stance, b = truth.swingStart;
        int hits = 0;
        for (std::size_t i = 0; i < r.phases.size(); ++i) {
            const double tc = rec.t[(r.phases[i].begin + r.phases[i].end - 1) / 2];
            if (tc >= a && tc <= b) {
                ++hits;
                used[i] = 1;
            }
        }
        score.matchedStances += hits == 1 ? 1 : 0;
    }
    for (std::size_t i = 1; i + 1 < r.phases.size(); ++i) score.extraPhases += used[i] ? 0 : 1;
    // Positions without resets, from the first anchor.
    const std::vector<Vec3> raw = withoutResets(r, ts);
    std::vector<Vec3> rawPos(n, Vec3::Zero());
    for (std::size_t k = r.first + 1; k < n; ++k) rawPos[k] = rawPos[k - 1] + 0.5 * ts * (raw[k - 1] + raw[k]);
    for (const events::SimTruth& truth : rec.truth) {
        const std::size_t a = sampleAt(rec.t, truth.start), b = sampleAt(rec.t, truth.end);
        if (a < r.first || b > r.last) continue;
        const double length = (r.position[b] - r.position[a]).head<2>().norm();
        const double rawLength = (rawPos[b] - rawPos[a]).head<2>().norm();
        score.strideLength.add(length - truth.length);
        score.strideLengthPct.add(100.0 * (length - truth.length) / truth.length);
        score.strideLengthNoResetPct.add(100.0 * (rawLength - truth.length) / truth.length);
    }
    return score;
}

Expected<GaitmapVelocityScore> evaluateGaitmapVelocity(const QString& imuCsv, const QString& bordersCsv,
                                                       const QVariantMap& resetParameters) {
    QTemporaryDir dir;
    if (!dir.isValid()) return makeError(QStringLiteral("cannot create a temporary folder"));
    auto project = events::importGaitmapWalk(dir.path(), imuCsv);
    if (!project) return project.error();
    Project& walk = **project;
    GaitmapVelocityScore score;
    const OrientationProcessor orientation;
    const VelocityResetProcessor reset;
    const events::GaitParametersProcessor gait;
    for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
        const QString imu = QStringLiteral("walk/%1-foot").arg(foot);
        const QString q = imu + QStringLiteral("-q"), v = imu + QStringLiteral("-v"), g = imu + QStringLiteral("-g");
        auto r1 =
            runProcessor(walk, orientation,
                         RunRequest{orientation.id(), {imu}, q, {{QStringLiteral("mode"), QStringLiteral("6d")}}});
        if (!r1) return r1.error();
        auto r2 = runProcessor(walk, reset, RunRequest{reset.id(), {q, imu}, v, resetParameters});
        if (!r2) return r2.error();
        // Against gait-parameters' per-stride method (zero velocity at one instant per stance, like the
        // resets here); the figures in drift-reduction.md were measured so before rts became the default.
        auto r3 = runProcessor(
            walk, gait, RunRequest{gait.id(), {imu}, g, {{QStringLiteral("method"), QStringLiteral("instant")}}});
        if (!r3) return r3.error();
        const Table* phases = walk.table(v + QStringLiteral("-zero-velocity"));
        const Table* strides = walk.table(g);
        auto traj = walk.stream(v)->data();
        if (!phases || !strides || !traj) return makeError(QStringLiteral("%1: an output is missing").arg(imu));
        const StreamData& d = **traj;
        const std::vector<double>& start = phases->column(QStringLiteral("start"))->numbers;
        const std::vector<double>& end = phases->column(QStringLiteral("end"))->numbers;
        if (!bordersCsv.isEmpty()) {
            auto reference = events::readStrideBorders(bordersCsv, 1.0 / d.medianInterval());
            if (!reference) return reference.error();
            for (const events::ReferenceStride& ref : *reference) {
                if (ref.foot != foot) continue;
                ++score.referenceStrides;
                int hits = 0;
                for (std::size_t i = 0; i < start.size(); ++i) {
                    const double c = 0.5 * (start[i] + end[i]);
                    hits += (c >= ref.tStart && c < ref.tEnd) ? 1 : 0;
                }
                score.oneStance += hits == 1 ? 1 : 0;
                score.someStance += hits >= 1 ? 1 : 0;
            }
        }
        const std::vector<double>& s0 = strides->column(QStringLiteral("start"))->numbers;
        const std::vector<double>& s1 = strides->column(QStringLiteral("end"))->numbers;
        const std::vector<double>& len = strides->column(QStringLiteral("stride_length"))->numbers;
        const std::vector<double>& height = strides->column(QStringLiteral("stride_height"))->numbers;
        for (std::size_t i = 0; i < s0.size(); ++i) {
            const std::size_t a = sampleAt(d.t, s0[i]), b = sampleAt(d.t, s1[i]);
            const Eigen::Vector3d pa(d.at(a, 0), d.at(a, 1), d.at(a, 2)), pb(d.at(b, 0), d.at(b, 1), d.at(b, 2));
            if (!pa.allFinite() || !pb.allFinite()) continue;
            ++score.strides;
            score.lengthDiffPct.add(100.0 * ((pb - pa).head<2>().norm() - len[i]) / len[i]);
            score.heightDiff.add((pb.z() - pa.z()) - height[i]);
        }
        for (std::size_t i = 0; i + 1 < start.size(); ++i) {
            const std::size_t k = sampleAt(d.t, 0.5 * (end[i] + start[i + 1]));
            const double speed = std::hypot(d.at(k, 3), d.at(k, 4));
            if (std::isfinite(speed)) score.speedAtMidSwing.add(speed);
        }
    }
    return score;
}

}  // namespace athlos::inertial
