#include "plugins/positioning/AnchorSmootherProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/positioning/AnchorPipeline.h"
#include "plugins/positioning/GateTable.h"

#include <QStringList>
#include <cmath>
#include <limits>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "AnchorSmootherProcessor"};
const double kInf = std::numeric_limits<double>::infinity();

int triple(const StreamInfo& info, const QString& prefix) {
    for (int i = 0; i + 2 < int(info.columns.size()); ++i)
        if (info.columns[i].name == prefix + QLatin1Char('x') &&
            info.columns[i + 1].name == prefix + QLatin1Char('y') &&
            info.columns[i + 2].name == prefix + QLatin1Char('z'))
            return i;
    return -1;
}

struct Plan {
    AnchorPipelineInput input;
    AnchorPipelineParams params;
    QString recording;
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    auto imu = c.samples(0);
    if (!imu) return imu.error();
    auto orientation = c.samples(1);
    if (!orientation) return orientation.error();
    auto table = c.requireTable(2);
    if (!table) return table.error();
    plan.recording = c.inputPath(0).section(QLatin1Char('/'), 0, 0);

    const int acc = triple(imu->info(), QStringLiteral("acc_")), gyr = triple(imu->info(), QStringLiteral("gyr_")),
              mag = triple(imu->info(), QStringLiteral("mag_"));
    if (acc < 0 || gyr < 0) return imu->error(QStringLiteral("needs columns acc_x..acc_z and gyr_x..gyr_z"));
    if (mag < 0)
        return imu->error(
            QStringLiteral("no magnetometer columns mag_x..mag_z: the gates are found from the field of "
                           "their magnets"));
    const auto& info = orientation->info();
    int qw = -1;
    for (int i = 0; i + 3 < int(info.columns.size()); ++i)
        if (info.columns[i].name == QLatin1String("qw") && info.columns[i + 1].name == QLatin1String("qx") &&
            info.columns[i + 2].name == QLatin1String("qy") && info.columns[i + 3].name == QLatin1String("qz"))
            qw = i;
    if (qw < 0) return orientation->error(QStringLiteral("needs columns qw, qx, qy, qz"));
    const StreamData& d = *imu->data;
    const StreamData& q = *orientation->data;
    if (q.rows() != d.rows() || d.rows() == 0 || std::abs(q.t.front() - d.t.front()) > 1e-6 ||
        std::abs(q.t.back() - d.t.back()) > 1e-6)
        return orientation->error(QStringLiteral("needs one row per sample of '%1' (%2 rows; it has %3): run "
                                                 "`orientation` on that stream")
                                      .arg(c.inputPath(0))
                                      .arg(d.rows())
                                      .arg(q.rows()));
    auto gates = gatesFromTable(**table, c.inputPath(2));
    if (!gates) return gates.error();

    AnchorPipelineInput& in = plan.input;
    const std::size_t n = d.rows();
    in.t = d.t;
    in.acc.resize(n);
    in.gyr.resize(n);
    in.mag.resize(n);
    in.orientation.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        in.acc[k] = math::Vec3(d.at(k, acc), d.at(k, acc + 1), d.at(k, acc + 2));
        in.gyr[k] = math::Vec3(d.at(k, gyr), d.at(k, gyr + 1), d.at(k, gyr + 2));
        in.mag[k] = math::Vec3(d.at(k, mag), d.at(k, mag + 1), d.at(k, mag + 2));
        in.orientation[k] = math::Quat(q.at(k, qw), q.at(k, qw + 1), q.at(k, qw + 2), q.at(k, qw + 3));
        if (!in.acc[k].allFinite() || !in.gyr[k].allFinite() || !in.mag[k].allFinite())
            return imu->error(QStringLiteral("sample %1 (t = %2 s) is not finite").arg(k + 1).arg(d.t[k]));
        if (!in.orientation[k].coeffs().allFinite() || in.orientation[k].norm() < 0.5)
            return orientation->error(
                QStringLiteral("sample %1 (t = %2 s) is not a unit quaternion").arg(k + 1).arg(q.t[k]));
    }
    in.gates = std::move(*gates);

    const QString start = c.text(QStringLiteral("start")).trimmed();
    if (!start.isEmpty()) {
        const QStringList parts = start.split(QLatin1Char(','));
        bool ok = parts.size() == 3;
        math::Vec3 s;
        for (int i = 0; ok && i < 3; ++i) s[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok || !s.allFinite())
            return makeError(QStringLiteral("parameter 'start': expected east,north,up in m, got '%1'").arg(start));
        in.start = s;
    }

    AnchorPipelineParams& p = plan.params;
    p.detector.threshold = c.number(QStringLiteral("mag_threshold"));
    p.detector.minInterval = c.number(QStringLiteral("min_interval"));
    p.smoother.rate = c.number(QStringLiteral("rate"));
    p.smoother.accSigma = c.number(QStringLiteral("acc_sigma"));
    p.smoother.jerkBase = c.number(QStringLiteral("jerk"));
    p.smoother.accOffsetWalk = c.number(QStringLiteral("acc_offset_walk"));
    p.smoother.anchorSigma1 = c.number(QStringLiteral("anchor_sigma1"));
    p.smoother.anchorSigma2 = c.number(QStringLiteral("anchor_sigma2"));
    p.smoother.sacrumHeight = c.number(QStringLiteral("sacrum_height"));
    p.smoother.matchRadius = c.number(QStringLiteral("match_radius"));
    p.smoother.lowPass = c.number(QStringLiteral("lowpass"));
    p.smoother.passes = c.integer(QStringLiteral("passes"));
    p.stillGyr = c.number(QStringLiteral("still_gyr"));
    p.stillAcc = c.number(QStringLiteral("still_acc"));
    p.restAligned = c.text(QStringLiteral("orientation")) == QLatin1String("rest-aligned");
    const double rate = 1.0 / std::max(d.medianInterval(), 1e-9);
    if (p.smoother.lowPass >= 0.5 * p.smoother.rate)
        return makeError(QStringLiteral("parameter 'lowpass' (%1 Hz) must be below half of 'rate' (%2 Hz)")
                             .arg(p.smoother.lowPass)
                             .arg(p.smoother.rate));
    if (p.smoother.rate > rate * 1.01)
        return makeError(QStringLiteral("parameter 'rate' (%1 Hz) is above the IMU's rate (%2 Hz)")
                             .arg(p.smoother.rate)
                             .arg(rate, 0, 'g', 4));
    return plan;
}

}  // namespace

QString AnchorSmootherProcessor::name() const { return tr("Anchor-point smoother (gate magnets)"); }

QString AnchorSmootherProcessor::description() const {
    return tr(
        "Sacrum trajectory from an IMU with magnetometer, its orientation and the gate positions (Fasel thesis "
        "ch. 9): gate crossings from magnetometer peaks (eq. 9.1), a 16-state extended Kalman smoother "
        "(constant acceleration, ZUPT at start and finish) with anchor updates at the gates in two passes "
        "(1 m, then 0.2 m), low-passed at 5 Hz.");
}

ParameterSpecs AnchorSmootherProcessor::parameters() const {
    const AnchorPipelineParams d;
    const auto& s = d.smoother;
    using PS = ParameterSpec;
    return {
        PS::number(QStringLiteral("mag_threshold"), d.detector.threshold, 0.01, 100.0, QStringLiteral("1"),
                   tr("Gate detection: magnet field in units of the ambient field (eq. 9.1: 0.3 = 0.88 m; the "
                      "thesis saw magnets up to 0.8 m).")),
        PS::number(QStringLiteral("min_interval"), d.detector.minInterval, 0.0, 60.0, QStringLiteral("s"),
                   tr("Shortest time between two gate crossings.")),
        PS::text(QStringLiteral("start"), QString(),
                 tr("Sacrum position at the start as east,north,up (m) in the gates' frame; empty = from the "
                    "matched gates.")),
        PS::choice(QStringLiteral("orientation"), {QStringLiteral("rest-aligned"), QStringLiteral("stream")},
                   QStringLiteral("rest-aligned"),
                   tr("rest-aligned: re-integrate the gyroscope from the stream's start orientation with the bias of "
                      "the start rest and remove the tilt drift found at the finish rest (thesis ch. 3-4, 9); "
                      "stream: use the orientation stream as it is.")),
        PS::number(QStringLiteral("rate"), s.rate, 10.0, 1000.0, QStringLiteral("Hz"),
                   tr("Smoother rate (the IMU is block-averaged onto it).")),
        PS::number(QStringLiteral("acc_sigma"), s.accSigma, 0.01, 100.0, QStringLiteral("m/s^2"),
                   tr("Acceleration accuracy (thesis sec. 9.2.2: 1.5 m/s^2).")),
        PS::number(QStringLiteral("jerk"), s.jerkBase, 0.0, 1e4, QStringLiteral("m/s^3"),
                   tr("Jerk noise floor of the constant-acceleration model; the measured acceleration change adds "
                      "to it (thesis: larger noise in the turns).")),
        PS::number(QStringLiteral("acc_offset_walk"), s.accOffsetWalk, 0.0, 100.0, QStringLiteral("m/s^2/sqrt(s)"),
                   tr("Random walk of the acceleration offset state.")),
        PS::number(QStringLiteral("anchor_sigma1"), s.anchorSigma1, 0.001, 100.0, QStringLiteral("m"),
                   tr("Anchor accuracy in the first pass (thesis: 1 m).")),
        PS::number(QStringLiteral("anchor_sigma2"), s.anchorSigma2, 0.001, 100.0, QStringLiteral("m"),
                   tr("Anchor accuracy in the second pass (thesis: 0.2 m).")),
        PS::number(QStringLiteral("sacrum_height"), s.sacrumHeight, 0.0, 2.0, QStringLiteral("m"),
                   tr("Sacrum above the snow at a gate crossing (|d_m| of eqs. 9.2-9.5).")),
        PS::number(QStringLiteral("match_radius"), s.matchRadius, 0.1, 1000.0, QStringLiteral("m"),
                   tr("Largest distance of a crossing from its expected gate.")),
        PS::number(QStringLiteral("lowpass"), s.lowPass, 0.0, 500.0, QStringLiteral("Hz"),
                   tr("Zero-phase 2nd-order Butterworth on the output (thesis: 5 Hz); 0 = none.")),
        PS::integer(QStringLiteral("passes"), s.passes, 0, 5,
                    tr("Anchor passes (thesis: 2); 0 = ZUPT-only integration, for comparison.")),
        PS::number(QStringLiteral("still_gyr"), d.stillGyr, 0.0, kInf, QStringLiteral("rad/s"),
                   tr("Standing at start/finish: angular rate below this.")),
        PS::number(QStringLiteral("still_acc"), d.stillAcc, 0.0, kInf, QStringLiteral("m/s^2"),
                   tr("Standing at start/finish: gravity-free acceleration below this.")),
    };
}

QList<InputSpec> AnchorSmootherProcessor::inputs() const {
    return {
        InputSpec{
            QStringLiteral("imu"), {QStringLiteral("imu")}, false, false, tr("Sacrum IMU with acc, gyr and mag.")},
        InputSpec{QStringLiteral("orientation"),
                  {QStringLiteral("orientation")},
                  false,
                  false,
                  tr("Its orientation (processor orientation), one row per IMU sample.")},
        InputSpec{
            QStringLiteral("gates"), {}, true, false, tr("Gates table: id, east, north, up (m), in course order.")}};
}

QList<OutputSpec> AnchorSmootherProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("trajectory"), false, QString(),
                   tr("Sacrum x, y, z (m), vx, vy, vz, speed (m/s) in the gates' frame.")},
        OutputSpec{QStringLiteral("gate-crossings"), true, QStringLiteral("crossings"),
                   tr("Detected gate crossings: t, gate, gate_to_gate (s since the previous crossing: the "
                      "coach's gate-to-gate time), distance, excess, side, residual, pass-0 gate estimate.")},
        OutputSpec{QString(), false, QStringLiteral("gates"),
                   tr("Gate passages as predicted instants labelled \"gate\" (a lane in the action timeline)."), true}};
}

Status AnchorSmootherProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> AnchorSmootherProcessor::run(const RunContext& c) const {
    auto plan = makePlan(c);
    if (!plan) return plan.error();
    c.report(0.0, QStringLiteral("smoothing"));
    auto result = runAnchorPipeline(plan->input, plan->params, [&](double f) {
        c.report(f);
        return !c.isCancelled();
    });
    if (c.isCancelled()) return cancelledError();
    if (!result) return makeError(QStringLiteral("recording '%1': %2").arg(plan->recording, result.error().message));
    const auto& r = result->smoothed;

    StreamData data(r.t.size(), 7);
    data.t = r.t;
    for (std::size_t k = 0; k < r.t.size(); ++k) {
        for (int i = 0; i < 3; ++i) {
            data.at(k, i) = r.position[k][i];
            data.at(k, 3 + i) = r.velocity[k][i];
        }
        data.at(k, 6) = r.velocity[k].norm();
    }
    for (double v : data.values)
        if (!std::isfinite(v))
            return makeError(
                QStringLiteral("recording '%1': the smoother diverged (non-finite trajectory)").arg(plan->recording));
    const QJsonObject attributes{{QStringLiteral("gates_detected"), int(result->crossings.size())},
                                 {QStringLiteral("gates_matched"), int(r.matches.size())},
                                 {QStringLiteral("gates_surveyed"), int(plan->input.gates.size())},
                                 {QStringLiteral("azimuth_offset"), r.azimuthOffset}};
    Stream trajectory =
        outputStream(QStringLiteral("trajectory"), QStringLiteral("ENU"),
                     columnsOf({"x", "y", "z", "vx", "vy", "vz", "speed"}, {"m", "m", "m", "m/s", "m/s", "m/s", "m/s"}),
                     std::move(data), attributes);

    Table crossings;
    crossings.kind = QStringLiteral("gate-crossings");
    auto numeric = [](const char* name, const char* unit) {
        return TableColumn{QString::fromLatin1(name), QString::fromLatin1(unit), false, {}, {}};
    };
    TableColumn t = numeric("t", "s"), split = numeric("gate_to_gate", "s"), distance = numeric("distance", "m"),
                excess = numeric("excess", "1"), side = numeric("side", "1"), residual = numeric("residual", "m"),
                ge = numeric("est_east", "m"), gn = numeric("est_north", "m"), gu = numeric("est_up", "m");
    TableColumn gate{QStringLiteral("gate"), QString(), true, {}, {}};
    Annotations passages;
    for (std::size_t m = 0; m < result->crossings.size(); ++m) {
        const auto& x = result->crossings[m];
        t.numbers.push_back(x.t);
        split.numbers.push_back(m == 0 ? std::numeric_limits<double>::quiet_NaN() : x.t - result->crossings[m - 1].t);
        Annotation passage;
        passage.label = QStringLiteral("gate");
        passage.tStart = passage.tEnd = x.t;
        passages.push_back(passage);
        distance.numbers.push_back(x.distance);
        excess.numbers.push_back(x.excess);
        side.numbers.push_back(x.side);
        QString id;
        double res = std::numeric_limits<double>::quiet_NaN();
        for (const auto& match : r.matches)
            if (match.crossing == int(m)) {
                id = plan->input.gates[std::size_t(match.gate)].id;
                res = match.residual;
            }
        gate.texts << id;
        residual.numbers.push_back(res);
        const math::Vec3 g = m < r.inertialGates.size()
                                 ? r.inertialGates[m]
                                 : math::Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        ge.numbers.push_back(g.x());
        gn.numbers.push_back(g.y());
        gu.numbers.push_back(g.z());
    }
    crossings.columns = {t, gate, split, distance, excess, side, residual, ge, gn, gu};

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(trajectory)});
    outputs.push_back({QStringLiteral("crossings"), std::move(crossings)});
    outputs.push_back({QStringLiteral("gates"), std::move(passages)});
    c.report(1.0);
    return outputs;
}

}  // namespace athlos::positioning
