#include "plugins/events/AlpineTurnsProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/events/SkiImu.h"
#include "plugins/events/TurnSwitchDetector.h"
#include "plugins/events/XcSkiingCyclesProcessor.h"

#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "AlpineTurnsProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

QString AlpineTurnsProcessor::name() const { return tr("Alpine turn switches"); }

QString AlpineTurnsProcessor::description() const {
    return tr(
        "Turn switches of alpine skiing from a trunk or sacrum IMU (Fasel 2017 ch. 2 and 11): the angular velocity "
        "about the trunk's longitudinal axis changes sign at each switch; positive is a left turn. Writes the turns "
        "(switch to switch) as predicted annotations \"turn left\" / \"turn right\" and a per-turn table.");
}

ParameterSpecs AlpineTurnsProcessor::parameters() const {
    const TurnSwitchParams d;
    return {
        ParameterSpec::choice(QStringLiteral("vertical_axis"),
                              {QStringLiteral("auto"), QStringLiteral("x"), QStringLiteral("-x"), QStringLiteral("y"),
                               QStringLiteral("-y"), QStringLiteral("z"), QStringLiteral("-z")},
                              QStringLiteral("auto"),
                              tr("Sensor axis along the trunk pointing up; auto: the axis nearest the mean "
                                 "acceleration.")),
        ParameterSpec::number(QStringLiteral("smoothing"), d.smoothing, 0.0, 5.0, QStringLiteral("s"),
                              tr("Moving-average window (applied twice) on the yaw rate.")),
        ParameterSpec::number(QStringLiteral("threshold"), d.threshold, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("Yaw rate a turn must exceed; smaller sign changes are not switches.")),
        ParameterSpec::number(QStringLiteral("min_turn"), d.minTurn, 0.05, kInf, QStringLiteral("s"),
                              tr("Shortest turn.")),
        ParameterSpec::number(QStringLiteral("max_turn"), d.maxTurn, 0.1, kInf, QStringLiteral("s"),
                              tr("Longest turn; longer intervals (straight running, stops) are not turns.")),
    };
}

QList<InputSpec> AlpineTurnsProcessor::inputs() const {
    return {InputSpec{QStringLiteral("trunk"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Sacrum or trunk IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).")}};
}

QList<OutputSpec> AlpineTurnsProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("alpine-turns"), true, QString(),
                       tr("Per turn: start, end, duration (s), side (left/right), peak_rate (rad/s).")},
            OutputSpec{QString(), false, QString(),
                       tr("Turns as predicted annotations \"turn left\" / \"turn right\"."), true}};
}

Expected<std::vector<ProcessorOutput>> AlpineTurnsProcessor::run(const RunContext& c) const {
    auto rows = imuRowsOf(c, 0);
    if (!rows) return rows.error();
    TurnSwitchParams p;
    p.smoothing = c.number(QStringLiteral("smoothing"));
    p.threshold = c.number(QStringLiteral("threshold"));
    p.minTurn = c.number(QStringLiteral("min_turn"));
    p.maxTurn = c.number(QStringLiteral("max_turn"));
    if (p.maxTurn <= p.minTurn)
        return makeError(
            QStringLiteral("max_turn: %1 s must be longer than min_turn (%2 s)").arg(p.maxTurn).arg(p.minTurn));
    const QString axis = c.text(QStringLiteral("vertical_axis"));
    if (axis != QLatin1String("auto")) p.axis = skiAxis(axis);
    const auto turns = detectTurns(rows->t, rows->gyr, rows->acc, p);
    if (c.isCancelled()) return cancelledError();
    if (turns.empty())
        return c.inputError(0, QStringLiteral("no turn switch found (threshold = %1 rad/s, vertical_axis = %2): is it "
                                              "a trunk IMU during alpine skiing?")
                                   .arg(p.threshold)
                                   .arg(axis));
    std::vector<double> index, start, end, dur, peak;
    TableColumn side{QStringLiteral("side"), QString(), true, {}, {}};
    Annotations annotations;
    for (std::size_t k = 0; k < turns.size(); ++k) {
        const Turn& t = turns[k];
        index.push_back(double(k + 1));
        start.push_back(t.start);
        end.push_back(t.end);
        dur.push_back(t.end - t.start);
        peak.push_back(t.peakRate);
        side.texts << (t.left ? QStringLiteral("left") : QStringLiteral("right"));
        Annotation a;
        a.label = t.left ? QStringLiteral("turn left") : QStringLiteral("turn right");
        a.tStart = t.start;
        a.tEnd = t.end;
        annotations.push_back(a);
    }
    Table table;
    table.kind = QStringLiteral("alpine-turns");
    table.attributes = QJsonObject{{QStringLiteral("turns"), int(turns.size())}};
    table.columns = {numberColumn(QStringLiteral("turn"), QStringLiteral("1"), index),
                     numberColumn(QStringLiteral("start"), QStringLiteral("s"), start),
                     numberColumn(QStringLiteral("end"), QStringLiteral("s"), end),
                     numberColumn(QStringLiteral("duration"), QStringLiteral("s"), dur),
                     side,
                     numberColumn(QStringLiteral("peak_rate"), QStringLiteral("rad/s"), peak)};
    c.report(1.0);
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(table)});
    out.push_back({QString(), std::move(annotations)});
    return out;
}

}  // namespace athlos::events
