#include "plugins/metrics/SessionMetricsProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/metrics/PlayerLoad.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <map>

namespace athlos::metrics {

namespace {
constexpr Translator tr{"athlos::metrics", "SessionMetricsProcessor"};
const double kInf = std::numeric_limits<double>::infinity();

Expected<std::vector<double>> numberList(const RunContext& c, const QString& name, double scale) {
    std::vector<double> values;
    for (const QString& item : splitList(c.text(name))) {
        bool ok = false;
        const double v = item.toDouble(&ok);
        if (!ok || !std::isfinite(v) || v < 0)
            return makeError(QStringLiteral("parameter '%1': '%2' is not a non-negative number").arg(name, item));
        // Rounded to 1e-9 so that an edge given in km/h lands exactly on its m/s value (14.4 km/h = 4 m/s).
        values.push_back(std::round(v * scale * 1e9) / 1e9);
    }
    return values;
}

QString windowName(double seconds) {
    if (std::fmod(seconds, 60.0) == 0.0) return QStringLiteral("%1min").arg(seconds / 60.0);
    return QStringLiteral("%1s").arg(seconds);
}

// Column name of an action label: "actions_" + the label with every run of other characters than
// letters, digits and '-' replaced by '_'.
QString actionColumn(const QString& label) {
    QString name = label.trimmed().toLower();
    name.replace(QRegularExpression(QStringLiteral("[^\\w-]+")), QStringLiteral("_"));
    return QStringLiteral("actions_") + name;
}

struct Period {
    QString name;
    double start = 0.0, end = 0.0;
};

// Positions of the input: x, y of any position stream (gnss streams carry them in the project's ENU
// frame since their import).
Expected<positioning::PositionSamples> loadFixes(const RunContext& context, const InputSamples& input) {
    const int cx = input.info().columnIndex(QStringLiteral("x")), cy = input.info().columnIndex(QStringLiteral("y"));
    if (cx < 0 || cy < 0)
        return input.error(
            QStringLiteral("needs columns x and y (m); a gnss stream gets them from lat, lon on import "
                           "(the project's geodetic origin)"));
    (void)context;
    positioning::PositionSamples fixes;
    const StreamData& d = *input.data;
    for (std::size_t k = 0; k < d.rows(); ++k) {
        const double x = d.at(k, cx), y = d.at(k, cy);
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        fixes.t.push_back(d.t[k]);
        fixes.p.emplace_back(x, y);
    }
    return fixes;
}

// An already filtered trajectory (position-filter's output): its own speed and forward acceleration.
MotionSeries trajectoryMotion(const InputSamples& input, double maxGap) {
    const StreamData& d = *input.data;
    const int cx = input.info().columnIndex(QStringLiteral("x")), cy = input.info().columnIndex(QStringLiteral("y")),
              cv = input.info().columnIndex(QStringLiteral("speed")),
              ca = input.info().columnIndex(QStringLiteral("accel"));
    MotionSeries s;
    double previous = -kInf;
    for (std::size_t k = 0; k < d.rows(); ++k) {
        const double x = d.at(k, cx), y = d.at(k, cy);
        if (!std::isfinite(x) || !std::isfinite(y)) continue;
        if (d.t[k] - previous > maxGap && previous > -kInf) {  // an outage: an invalid sample in it
            s.t.push_back(0.5 * (previous + d.t[k]));
            s.x.push_back(std::nan(""));
            s.y.push_back(std::nan(""));
            s.speed.push_back(0.0);
            s.accel.push_back(0.0);
            s.valid.push_back(0);
        }
        s.t.push_back(d.t[k]);
        s.x.push_back(x);
        s.y.push_back(y);
        s.speed.push_back(std::abs(d.at(k, cv)));
        s.accel.push_back(ca >= 0 ? d.at(k, ca) : 0.0);
        s.valid.push_back(1);
        previous = d.t[k];
    }
    if (ca < 0) {  // no acceleration column: differentiate the speed
        for (std::size_t k = 0; k < s.size(); ++k) {
            const std::size_t lo = k > 0 && s.valid[k - 1] ? k - 1 : k,
                              hi = k + 1 < s.size() && s.valid[k + 1] ? k + 1 : k;
            s.accel[k] = hi > lo && s.valid[k] ? (s.speed[hi] - s.speed[lo]) / (s.t[hi] - s.t[lo]) : 0.0;
        }
    }
    return s;
}

}  // namespace

QString SessionMetricsProcessor::name() const { return tr("Session metrics"); }

QString SessionMetricsProcessor::description() const {
    return tr(
        "The coach's metrics per period (whole session, annotated halves or drills, consecutive windows): distance, "
        "maximum speed, distance per speed zone, high-speed running, sprints, accelerations and decelerations, "
        "peak distance over 1, 3 and 5 min, metabolic power and energy (di Prampero 2005, Osgnach 2010), PlayerLoad "
        "from an IMU and action counts from annotations. Raw positions are smoothed first by the robust Kalman "
        "smoother (noise estimated from the data), because raw positions overstate distance.");
}

ParameterSpecs SessionMetricsProcessor::parameters() const {
    const MetricsParams d;
    const MotionParams m;
    return {
        ParameterSpec::choice(QStringLiteral("filter"), {QStringLiteral("auto"), QStringLiteral("none")},
                              QStringLiteral("auto"),
                              tr("auto: smooth raw fixes (lps-position, gnss) with the robust Kalman smoother and use "
                                 "a trajectory (position-filter output) as it is; none: raw positions, speed by "
                                 "central differences (overstates distance and speed; for comparison).")),
        ParameterSpec::choice(QStringLiteral("model"), {QStringLiteral("ctra"), QStringLiteral("constant-velocity")},
                              QStringLiteral("constant-velocity"),
                              tr("Motion model of the smoother: constant velocity (white-noise acceleration; its "
                                 "smoothed speed keeps the accelerations of team sports, docs/validation/"
                                 "session-metrics.md) or constant turn rate and acceleration.")),
        ParameterSpec::number(QStringLiteral("rate"), m.rate, 1.0, 1000.0, QStringLiteral("Hz"),
                              tr("Sampling rate of the smoothed motion the metrics are computed on.")),
        ParameterSpec::number(QStringLiteral("max_gap"), m.maxGap, 0.0, kInf, QStringLiteral("s"),
                              tr("Outages longer than this are not bridged: no distance is counted across them.")),
        ParameterSpec::integer(QStringLiteral("noise_chunks"), m.noiseChunks, 0, 1000,
                               tr("The smoother's noise is estimated on this many evenly spread chunks of the "
                                  "recording (0 = on all of it).")),
        ParameterSpec::number(QStringLiteral("noise_chunk"), m.noiseChunk, 5.0, kInf, QStringLiteral("s"),
                              tr("Length of one chunk of the noise estimate.")),
        ParameterSpec::text(QStringLiteral("zones"), QStringLiteral("0,7,14.4,19.8,25.2"),
                            tr("Lower edges of the speed zones in km/h (Bradley et al. 2009; the vendors' "
                               "defaults); the last zone is open.")),
        ParameterSpec::number(QStringLiteral("hsr_speed"), d.hsrSpeed, 0.0, kInf, QStringLiteral("m/s"),
                              tr("High-speed running above this speed (19.8 km/h, Bradley et al. 2009).")),
        ParameterSpec::number(QStringLiteral("sprint_speed"), d.sprintSpeed, 0.0, kInf, QStringLiteral("m/s"),
                              tr("Sprint entry speed (25.2 km/h, Bradley et al. 2009).")),
        ParameterSpec::number(QStringLiteral("max_speed_duration"), d.maxSpeedDuration, 0.0, kInf, QStringLiteral("s"),
                              tr("max_speed is the highest speed held at least this long, so that one noisy sample "
                                 "cannot set it (0 = the largest single sample).")),
        ParameterSpec::number(QStringLiteral("sprint_duration"), d.sprintMinDuration, 0.0, kInf, QStringLiteral("s"),
                              tr("Minimum time above the sprint speed (1 s, Di Salvo et al. 2010).")),
        ParameterSpec::number(QStringLiteral("accel_threshold"), d.accelThreshold, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("Acceleration and deceleration efforts at or beyond ± this (3 m/s², Akenhead et al. "
                                 "2013).")),
        ParameterSpec::number(QStringLiteral("accel_duration"), d.accelMinDuration, 0.0, kInf, QStringLiteral("s"),
                              tr("Minimum duration of an acceleration or deceleration effort (0.5 s, Varley et al. "
                                 "2012).")),
        ParameterSpec::text(QStringLiteral("peak_windows"), QStringLiteral("60,180,300"),
                            tr("Peak distance over these window lengths (s).")),
        ParameterSpec::number(QStringLiteral("window"), 300.0, 0.0, kInf, QStringLiteral("s"),
                              tr("Consecutive windows of this length as extra rows (0 = none).")),
        ParameterSpec::text(QStringLiteral("periods"), QStringLiteral("auto"),
                            tr("Annotation labels that are periods (halves, drills), comma-separated; auto: interval "
                               "annotations whose label matches period_pattern. Other annotations are counted as "
                               "actions.")),
        ParameterSpec::text(QStringLiteral("period_pattern"),
                            QStringLiteral("half|period|drill|quarter|phase|warm.?up|session|game"),
                            tr("Regular expression (case-insensitive) of period labels for periods=auto.")),
        ParameterSpec::text(QStringLiteral("track"), QString(),
                            tr("A track (a name under the project's /geometry or a built-in: iaaf-400m, indoor-200m): "
                               "adds a row per lap and per split_distance, from the progress along the track. Empty: "
                               "no track.")),
        ParameterSpec::number(QStringLiteral("split_distance"), 100.0, 0.0, kInf, QStringLiteral("m"),
                              tr("Split length along lane 1's running line with a track (0 = laps only).")),
        ParameterSpec::number(QStringLiteral("terrain_factor"), d.metabolic.terrainFactor, 0.1, 10.0, QString(),
                              tr("KT of the energy cost: 1.29 for grass (Osgnach et al. 2010), 1 for a track.")),
        ParameterSpec::number(QStringLiteral("high_power"), d.highPowerThreshold, 0.0, kInf, QStringLiteral("W/kg"),
                              tr("High metabolic power distance above this power (20 W/kg, Osgnach et al. 2010).")),
    };
}

QList<InputSpec> SessionMetricsProcessor::inputs() const {
    return {InputSpec{QStringLiteral("positions"),
                      {QStringLiteral("lps-position"), QStringLiteral("trajectory"), QStringLiteral("gnss")},
                      false,
                      false,
                      tr("Positions t, x, y (m): LPS fixes, GNSS (x, y in the project's ENU frame) or a filtered "
                         "trajectory.")},
            InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      true,
                      tr("Optional IMU (acc_x, acc_y, acc_z) for PlayerLoad.")}};
}

QList<OutputSpec> SessionMetricsProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("session-metrics"), true, QString(),
                       tr("One row per period: period, start, end, duration, distance, max_speed, zone distances, "
                          "hsr_distance, sprint/acceleration/deceleration counts, peak distances, metabolic energy "
                          "and power, high-power distance, player_load, actions_<label>.")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("motion"),
                       tr("The motion the metrics were computed on: x, y (m), speed (m/s), accel (m/s^2), valid.")}};
}

Expected<SessionMetricsProcessor::Plan> SessionMetricsProcessor::makePlan(const RunContext& c) const {
    Plan plan;
    plan.filterMode = c.text(QStringLiteral("filter"));
    plan.motion.model = c.text(QStringLiteral("model")) == QLatin1String("ctra")
                            ? positioning::ModelKind::Unconstrained
                            : positioning::ModelKind::ConstantVelocity;
    plan.motion.rate = c.number(QStringLiteral("rate"));
    plan.motion.maxGap = c.number(QStringLiteral("max_gap"));
    plan.motion.noiseChunks = c.integer(QStringLiteral("noise_chunks"));
    plan.motion.noiseChunk = c.number(QStringLiteral("noise_chunk"));
    auto zones = numberList(c, QStringLiteral("zones"), 1.0 / 3.6);
    if (!zones) return zones.error();
    if (zones->empty() || !std::is_sorted(zones->begin(), zones->end()) ||
        std::adjacent_find(zones->begin(), zones->end()) != zones->end())
        return makeError(QStringLiteral("parameter 'zones': needs increasing speeds in km/h, e.g. 0,7,14.4,19.8,25.2"));
    plan.metrics.zoneEdges = *zones;
    plan.metrics.hsrSpeed = c.number(QStringLiteral("hsr_speed"));
    plan.metrics.sprintSpeed = c.number(QStringLiteral("sprint_speed"));
    plan.metrics.sprintMinDuration = c.number(QStringLiteral("sprint_duration"));
    plan.metrics.maxSpeedDuration = c.number(QStringLiteral("max_speed_duration"));
    plan.metrics.accelThreshold = c.number(QStringLiteral("accel_threshold"));
    plan.metrics.accelMinDuration = c.number(QStringLiteral("accel_duration"));
    auto peaks = numberList(c, QStringLiteral("peak_windows"), 1.0);
    if (!peaks) return peaks.error();
    if (std::find(peaks->begin(), peaks->end(), 0.0) != peaks->end())
        return makeError(QStringLiteral("parameter 'peak_windows': window lengths must be > 0 s"));
    plan.metrics.peakWindows = *peaks;
    plan.metrics.metabolic.terrainFactor = c.number(QStringLiteral("terrain_factor"));
    plan.metrics.highPowerThreshold = c.number(QStringLiteral("high_power"));
    plan.window = c.number(QStringLiteral("window"));
    plan.periods = c.text(QStringLiteral("periods")).trimmed();
    plan.periodPattern = c.text(QStringLiteral("period_pattern"));
    if (!QRegularExpression(plan.periodPattern).isValid())
        return makeError(QStringLiteral("parameter 'period_pattern': not a valid regular expression: %1")
                             .arg(QRegularExpression(plan.periodPattern).errorString()));
    if (const QString track = c.text(QStringLiteral("track")).trimmed(); !track.isEmpty()) {
        auto geometry = TrackGeometry::resolve(c.project().geometry(), track);
        if (!geometry) return makeError(QStringLiteral("parameter 'track': %1").arg(geometry.message()));
        plan.track = std::move(*geometry);
    }
    plan.splits.splitDistance = c.number(QStringLiteral("split_distance"));
    const Stream* positions = c.stream(0);
    if (positions->info().columnIndex(QStringLiteral("x")) < 0 ||
        positions->info().columnIndex(QStringLiteral("y")) < 0)
        return c.inputError(0, QStringLiteral("needs columns x and y (m); a gnss stream gets them from lat, lon on "
                                              "import (the project's geodetic origin)"));
    if (positions->info().kind == QLatin1String("trajectory") && plan.filterMode == QLatin1String("auto") &&
        positions->info().columnIndex(QStringLiteral("speed")) < 0)
        return c.inputError(0, QStringLiteral("a trajectory needs a speed column (position-filter's output has one)"));
    if (const Stream* imu = c.stream(1)) {
        for (const char* axis : {"acc_x", "acc_y", "acc_z"})
            if (imu->info().columnIndex(QLatin1String(axis)) < 0)
                return c.inputError(1, QStringLiteral("needs columns acc_x, acc_y, acc_z for PlayerLoad"));
    }
    return plan;
}

Status SessionMetricsProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> SessionMetricsProcessor::run(const RunContext& context) const {
    auto planOr = makePlan(context);
    if (!planOr) return planOr.error();
    Plan plan = std::move(*planOr);
    auto input = context.samples(0);
    if (!input) return input.error();

    // 1. The motion: smoothed fixes, a given trajectory, or raw fixes.
    QJsonObject attributes;
    MotionSeries series;
    const bool trajectory = input->info().kind == QLatin1String("trajectory");
    if (trajectory && plan.filterMode == QLatin1String("auto")) {
        series = trajectoryMotion(*input, plan.motion.maxGap);
        attributes.insert(QStringLiteral("filter"), QStringLiteral("input is a trajectory (not filtered again)"));
    } else {
        auto fixes = loadFixes(context, *input);
        if (!fixes) return fixes.error();
        plan.motion.filter = plan.filterMode == QLatin1String("auto");
        const Progress sub = context.progress().sub(0.0, 0.9);
        auto motion = motionFromPositions(*fixes, plan.motion, [&](double f) {
            sub.report(f, QStringLiteral("smoothing positions"));
            return !context.isCancelled();
        });
        if (!motion) return input->error(motion.message());
        if (motion->cancelled || context.isCancelled()) return cancelledError();
        series = std::move(motion->series);
        if (plan.motion.filter) {
            QJsonObject noise;
            for (const auto& [name, value] : motion->estimatedNoise) noise.insert(QString::fromStdString(name), value);
            attributes.insert(QStringLiteral("filter"), QStringLiteral("robust Kalman smoother (EKF + RTS)"));
            attributes.insert(QStringLiteral("estimated_noise"), noise);
            attributes.insert(QStringLiteral("outliers"), motion->outliers);
        } else {
            attributes.insert(QStringLiteral("filter"), QStringLiteral("none (raw positions)"));
        }
    }
    double tBegin = kInf, tEnd = -kInf;
    for (std::size_t k = 0; k < series.size(); ++k)
        if (series.valid[k]) {
            tBegin = std::min(tBegin, series.t[k]);
            tEnd = std::max(tEnd, series.t[k]);
        }
    if (!(tEnd > tBegin)) return input->error(QStringLiteral("no valid positions to compute metrics on"));

    // 2. Periods: the whole session, annotated periods, consecutive windows.
    const QString recordingName = ItemPath::parse(context.inputPath(0)).recording;
    const Recording* recording = context.project().recording(recordingName);
    const Annotations annotations = recording ? recording->annotations : Annotations{};
    std::vector<Period> periods{{QStringLiteral("whole"), tBegin, tEnd}};
    const QStringList periodLabels = plan.periods == QLatin1String("auto") ? QStringList{} : splitList(plan.periods);
    const QRegularExpression pattern(plan.periodPattern, QRegularExpression::CaseInsensitiveOption);
    auto isPeriod = [&](const Annotation& a) {
        if (!(a.tEnd > a.tStart)) return false;
        return plan.periods == QLatin1String("auto") ? pattern.match(a.label).hasMatch()
                                                     : periodLabels.contains(a.label, Qt::CaseInsensitive);
    };
    std::map<QString, int> labelUses;
    std::vector<const Annotation*> actions;
    for (const Annotation& a : annotations) {
        if (isPeriod(a)) {
            const int use = ++labelUses[a.label];
            periods.push_back({use > 1 ? QStringLiteral("%1 #%2").arg(a.label).arg(use) : a.label, a.tStart, a.tEnd});
        } else {
            actions.push_back(&a);
        }
    }
    if (plan.track)
        for (const TrackInterval& interval : TrackSplits::compute(series, *plan.track, plan.splits))
            periods.push_back({interval.name, interval.start, interval.end});
    if (plan.window > 0) {
        int index = 1;
        for (double a = tBegin; a < tEnd - 1e-9; a += plan.window, ++index)
            periods.push_back({QStringLiteral("window %1").arg(index), a, std::min(a + plan.window, tEnd)});
    }
    QStringList actionLabels;
    for (const Annotation* a : actions)
        if (!actionLabels.contains(a->label)) actionLabels.push_back(a->label);
    actionLabels.sort();

    // 3. PlayerLoad source.
    std::optional<AccelerationSeries> acc;
    double imuRate = 0.0;
    if (context.stream(1)) {
        auto imu = context.samples(1);
        if (!imu) return imu.error();
        const int ax = imu->info().columnIndex(QStringLiteral("acc_x")),
                  ay = imu->info().columnIndex(QStringLiteral("acc_y")),
                  az = imu->info().columnIndex(QStringLiteral("acc_z"));
        AccelerationSeries a;
        const StreamData& d = *imu->data;
        a.t = d.t;
        a.ax.resize(d.rows());
        a.ay.resize(d.rows());
        a.az.resize(d.rows());
        for (std::size_t k = 0; k < d.rows(); ++k) {
            a.ax[k] = d.at(k, ax);
            a.ay[k] = d.at(k, ay);
            a.az[k] = d.at(k, az);
        }
        auto dt = imu->samplingInterval();
        if (!dt) return dt.error();
        imuRate = 1.0 / *dt;
        acc = std::move(a);
    }

    // 4. The table.
    Table table;
    table.kind = QStringLiteral("session-metrics");
    auto numberColumn = [&](const QString& name, const QString& unit) {
        table.columns.push_back(TableColumn{name, unit, false, {}, {}});
        return table.columns.size() - 1;
    };
    table.columns.push_back(TableColumn{QStringLiteral("period"), QString(), true, {}, {}});
    const auto cStart = numberColumn(QStringLiteral("start"), QStringLiteral("s"));
    const auto cEnd = numberColumn(QStringLiteral("end"), QStringLiteral("s"));
    const auto cDuration = numberColumn(QStringLiteral("duration"), QStringLiteral("s"));
    const auto cDistance = numberColumn(QStringLiteral("distance"), QStringLiteral("m"));
    const auto cMaxSpeed = numberColumn(QStringLiteral("max_speed"), QStringLiteral("m/s"));
    const auto cZones = table.columns.size();
    for (std::size_t z = 0; z < plan.metrics.zoneEdges.size(); ++z)
        numberColumn(QStringLiteral("distance_zone%1").arg(z + 1), QStringLiteral("m"));
    const auto cHsr = numberColumn(QStringLiteral("hsr_distance"), QStringLiteral("m"));
    const auto cSprints = numberColumn(QStringLiteral("sprint_count"), QStringLiteral("1"));
    const auto cAcc = numberColumn(QStringLiteral("acceleration_count"), QStringLiteral("1"));
    const auto cDec = numberColumn(QStringLiteral("deceleration_count"), QStringLiteral("1"));
    const auto cPeaks = table.columns.size();
    for (double w : plan.metrics.peakWindows)
        numberColumn(QStringLiteral("peak_distance_%1").arg(windowName(w)), QStringLiteral("m"));
    const auto cEnergy = numberColumn(QStringLiteral("metabolic_energy"), QStringLiteral("J/kg"));
    const auto cPower = numberColumn(QStringLiteral("metabolic_power"), QStringLiteral("W/kg"));
    const auto cHighPower = numberColumn(QStringLiteral("high_power_distance"), QStringLiteral("m"));
    const auto cLoad = acc ? numberColumn(QStringLiteral("player_load"), QStringLiteral("AU")) : 0;
    const auto cActions = table.columns.size();
    for (const QString& label : actionLabels) numberColumn(actionColumn(label), QStringLiteral("1"));

    for (std::size_t i = 0; i < periods.size(); ++i) {
        if (context.isCancelled()) return cancelledError();
        context.report(0.9 + 0.1 * double(i) / double(periods.size()), QStringLiteral("metrics"));
        const Period& period = periods[i];
        const PeriodMetrics m = computePeriod(series, period.start, period.end, plan.metrics);
        table.columns[0].texts.push_back(period.name);
        auto put = [&](std::size_t column, double value) { table.columns[column].numbers.push_back(value); };
        put(cStart, period.start);
        put(cEnd, period.end);
        put(cDuration, m.duration);
        put(cDistance, m.distance);
        put(cMaxSpeed, m.maxSpeed);
        for (std::size_t z = 0; z < m.zoneDistance.size(); ++z) put(cZones + z, m.zoneDistance[z]);
        put(cHsr, m.hsrDistance);
        put(cSprints, m.sprintCount);
        put(cAcc, m.accelerationCount);
        put(cDec, m.decelerationCount);
        for (std::size_t w = 0; w < m.peakDistance.size(); ++w) put(cPeaks + w, m.peakDistance[w]);
        put(cEnergy, m.metabolicEnergy);
        put(cPower, m.metabolicPowerMean);
        put(cHighPower, m.highPowerDistance);
        if (acc) put(cLoad, playerLoad(*acc, period.start, period.end));
        for (int l = 0; l < actionLabels.size(); ++l) {
            int count = 0;
            for (const Annotation* a : actions)
                count += a->label == actionLabels[l] && a->tStart >= period.start && a->tStart <= period.end;
            put(cActions + l, count);
        }
    }

    QJsonArray zoneEdges;
    for (double e : plan.metrics.zoneEdges) zoneEdges.append(e);
    attributes.insert(QStringLiteral("zone_edges_mps"), zoneEdges);
    attributes.insert(QStringLiteral("metabolic_model"),
                      QStringLiteral("di Prampero et al. 2005 / Osgnach et al. 2010, KT = %1")
                          .arg(plan.metrics.metabolic.terrainFactor));
    if (acc)
        attributes.insert(
            QStringLiteral("player_load"),
            QStringLiteral("Boyd et al. 2011 formula at the IMU's %1 Hz (defined for 100 Hz)").arg(imuRate, 0, 'f', 1));
    table.attributes = attributes;

    StreamData motion(series.size(), 5);
    motion.t = series.t;
    for (std::size_t k = 0; k < series.size(); ++k) {
        motion.at(k, 0) = series.x[k];
        motion.at(k, 1) = series.y[k];
        motion.at(k, 2) = series.speed[k];
        motion.at(k, 3) = series.accel[k];
        motion.at(k, 4) = series.valid[k];
    }
    // GNSS x, y are East-North-Up about the project's origin, whatever the lat/lon frame is called.
    const QString frame = input->info().kind == QLatin1String("gnss") ? QStringLiteral("ENU") : input->info().frame;
    if (input->info().attributes.contains(QStringLiteral("enu_origin")))
        attributes.insert(QStringLiteral("enu_origin"), input->info().attributes.value(QStringLiteral("enu_origin")));
    Stream motionStream = outputStream(QStringLiteral("trajectory"), frame,
                                       columnsOf({QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("speed"),
                                                  QStringLiteral("accel"), QStringLiteral("valid")},
                                                 {QStringLiteral("m"), QStringLiteral("m"), QStringLiteral("m/s"),
                                                  QStringLiteral("m/s^2"), QStringLiteral("1")}),
                                       std::move(motion), attributes);

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(table)});
    outputs.push_back({QStringLiteral("motion"), std::move(motionStream)});
    return outputs;
}

}  // namespace athlos::metrics
