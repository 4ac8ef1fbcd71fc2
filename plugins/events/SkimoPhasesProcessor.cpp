#include "plugins/events/SkimoPhasesProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/events/SkiImu.h"
#include "plugins/events/XcSkiingCyclesProcessor.h"

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "SkimoPhasesProcessor"};
}

QString SkimoPhasesProcessor::name() const { return tr("Ski-mountaineering phases"); }

QString SkimoPhasesProcessor::description() const {
    return tr(
        "Ski-mountaineering ascent from a ski IMU (Fasel 2017 ch. 4): motionless phases at the minima of the speed "
        "integrated without resets, speed with the drift on the central 50 % of each phase removed, phases refined "
        "where the speed is below zero_speed; per cycle duration, speed, length, elevation gain and slope angle. "
        "The recording must start with the ski still.");
}

ParameterSpecs SkimoPhasesProcessor::parameters() const { return skiCycleParameters(false); }

QList<InputSpec> SkimoPhasesProcessor::inputs() const {
    return {InputSpec{QStringLiteral("ski"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Ski-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).")}};
}

QList<OutputSpec> SkimoPhasesProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("skimo-cycles"), true, QString(),
                   tr("Per cycle: still_start, still_end, end (s), duration (s), speed (m/s), length (m), "
                      "elevation (m), slope (rad); attribute elevation_gain (m).")},
        OutputSpec{QString(), false, QString(), tr("Cycles and motionless phases as predicted annotations."), true}};
}

Expected<std::vector<ProcessorOutput>> SkimoPhasesProcessor::run(const RunContext& c) const {
    auto axes = skiAxesOf(c);
    if (!axes) return axes.error();
    auto ski = imuRowsOf(c, 0);
    if (!ski) return ski.error();
    SkiCycleParams p;
    p.mode = SkiCycleParams::Mode::Mountaineering;
    p.zeroSpeed = c.number(QStringLiteral("zero_speed"));
    p.minCycle = c.number(QStringLiteral("min_cycle"));
    p.maxCycle = c.number(QStringLiteral("max_cycle"));
    p.maxThrust = c.number(QStringLiteral("max_still"));
    p.initialStill = c.number(QStringLiteral("initial_still"));
    if (p.maxCycle <= p.minCycle)
        return makeError(
            QStringLiteral("max_cycle: %1 s must be longer than min_cycle (%2 s)").arg(p.maxCycle).arg(p.minCycle));
    const SkiImu imu = toSkiFrame(ski->t, ski->acc, ski->gyr, axes->first, axes->second);
    // The first pass needs the ski still at the start: refuse a moving start rather than integrate it.
    const SkiCycleAnalyzer analyzer(p);
    const auto n0 = std::size_t(p.initialStill * double(imu.size() - 1) / std::max(1e-9, imu.t.back() - imu.t.front()));
    for (std::size_t i = 0; i < std::min(n0, imu.size()); ++i)
        if (imu.gyrNorm[i] > 0.5)
            return c.inputError(0, QStringLiteral("the ski is not still in the first initial_still = %1 s (gyroscope "
                                                  "norm %2 rad/s at %3 s); skimo-phases needs a still start")
                                       .arg(p.initialStill)
                                       .arg(imu.gyrNorm[i], 0, 'g', 3)
                                       .arg(imu.t[i], 0, 'g', 4));
    c.report(0.1, QStringLiteral("integrating the ski"));
    const SkiCycleResult r = analyzer.analyze(imu);
    if (c.isCancelled()) return cancelledError();
    if (r.cycles.empty())
        return c.inputError(0, QStringLiteral("no motionless phase found between moving phases (%1 phase(s), "
                                              "zero_speed = %2 m/s, min_cycle = %3 s, max_cycle = %4 s); is it a ski "
                                              "IMU during an ascent with the axes set by forward_axis/ml_axis?")
                                   .arg(r.phases.size())
                                   .arg(p.zeroSpeed)
                                   .arg(p.minCycle)
                                   .arg(p.maxCycle));
    Annotations annotations;
    double gain = 0.0;
    for (const SkiCycle& cy : r.cycles) {
        gain += std::max(0.0, cy.elevation);
        Annotation a;
        a.label = QStringLiteral("skimo cycle");
        a.tStart = cy.thrustStart;
        a.tEnd = cy.end;
        annotations.push_back(a);
        a.label = QStringLiteral("motionless");
        a.tEnd = cy.thrustEnd;
        annotations.push_back(a);
    }
    Table table;
    table.kind = QStringLiteral("skimo-cycles");
    table.attributes = QJsonObject{{QStringLiteral("cycles"), int(r.cycles.size())},
                                   {QStringLiteral("elevation_gain"), gain},
                                   {QStringLiteral("elevation_gain_unit"), QStringLiteral("m")}};
    table.columns = skiCycleColumns(r.cycles, QStringLiteral("still"), false);
    c.report(1.0);
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(table)});
    out.push_back({QString(), std::move(annotations)});
    return out;
}

}  // namespace athlos::events
