#include "plugins/events/XcSkiingCyclesProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/events/PoleEventDetector.h"
#include "plugins/events/SkiImu.h"

#include <cmath>
#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "XcSkiingCyclesProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();
const QStringList kAxes{QStringLiteral("x"),  QStringLiteral("-x"), QStringLiteral("y"),
                        QStringLiteral("-y"), QStringLiteral("z"),  QStringLiteral("-z")};

Annotation annotation(const QString& label, double start, double end) {
    Annotation a;
    a.label = label;
    a.tStart = start;
    a.tEnd = end;
    return a;  // source and annotator are set by the runner
}
}  // namespace

TableColumn numberColumn(const QString& name, const QString& unit, std::vector<double> values) {
    return TableColumn{name, unit, false, std::move(values), {}};
}

std::vector<TableColumn> skiCycleColumns(const std::vector<SkiCycle>& cycles, const QString& phase, bool glide) {
    const auto column = [&](const QString& name, const QString& unit, double (*value)(const SkiCycle&)) {
        std::vector<double> v;
        v.reserve(cycles.size());
        for (const SkiCycle& c : cycles) v.push_back(value(c));
        return numberColumn(name, unit, std::move(v));
    };
    std::vector<double> index(cycles.size());
    for (std::size_t k = 0; k < index.size(); ++k) index[k] = double(k + 1);
    const QString s = QStringLiteral("s");
    std::vector<TableColumn> out{
        numberColumn(QStringLiteral("cycle"), QStringLiteral("1"), std::move(index)),
        column(phase + QStringLiteral("_start"), s, [](const SkiCycle& c) { return c.thrustStart; }),
        column(phase + QStringLiteral("_end"), s, [](const SkiCycle& c) { return c.thrustEnd; })};
    if (glide) out.push_back(column(QStringLiteral("glide_start"), s, [](const SkiCycle& c) { return c.glideStart; }));
    out.push_back(column(QStringLiteral("end"), s, [](const SkiCycle& c) { return c.end; }));
    out.push_back(column(QStringLiteral("duration"), s, [](const SkiCycle& c) { return c.duration; }));
    out.push_back(column(QStringLiteral("speed"), QStringLiteral("m/s"), [](const SkiCycle& c) { return c.speed; }));
    out.push_back(column(QStringLiteral("length"), QStringLiteral("m"), [](const SkiCycle& c) { return c.length; }));
    out.push_back(
        column(QStringLiteral("elevation"), QStringLiteral("m"), [](const SkiCycle& c) { return c.elevation; }));
    out.push_back(column(QStringLiteral("slope"), QStringLiteral("rad"), [](const SkiCycle& c) { return c.slope; }));
    return out;
}

ParameterSpecs skiCycleParameters(bool xc) {
    const SkiCycleParams d;
    ParameterSpecs specs{
        ParameterSpec::choice(QStringLiteral("forward_axis"), kAxes, QStringLiteral("x"),
                              tr("Sensor axis pointing forward along the ski.")),
        ParameterSpec::choice(QStringLiteral("ml_axis"), kAxes, QStringLiteral("y"),
                              tr("Sensor axis pointing to the skier's left (medio-lateral); the ski inclination is "
                                 "integrated from this gyroscope axis.")),
        ParameterSpec::number(QStringLiteral("zero_speed"), d.zeroSpeed, 0.001, 10.0, QStringLiteral("m/s"),
                              tr("Speed below which the ski is motionless (refined phases; Fasel 2017 ch. 4: "
                                 "0.1 m/s).")),
        ParameterSpec::number(QStringLiteral("min_cycle"), d.minCycle, 0.1, kInf, QStringLiteral("s"),
                              tr("Shortest cycle; closer motionless phases are not separate cycles.")),
        ParameterSpec::number(QStringLiteral("max_cycle"), xc ? d.maxCycle : 4.0, 0.2, kInf, QStringLiteral("s"),
                              tr("Longest cycle; longer gaps between motionless phases are not cycles.")),
        ParameterSpec::number(QStringLiteral("max_still"), d.maxThrust, 0.05, kInf, QStringLiteral("s"),
                              tr("Longest motionless phase that starts a cycle; longer ones are rests (used for the "
                                 "drift correction only).")),
    };
    if (xc) {
        specs << ParameterSpec::number(QStringLiteral("still_gyro"), d.stillGyro, 0.0, kInf, QStringLiteral("rad/s"),
                                       tr("Gyroscope norm below which the ski may be still (candidate thrust phases; "
                                          "Fasel 2017 ch. 3)."))
              << ParameterSpec::number(QStringLiteral("still_acc"), d.stillAcc, 0.0, kInf, QStringLiteral("m/s^2"),
                                       tr("|‖a‖ − g| below which the ski may be still (candidate thrust phases)."))
              << ParameterSpec::number(QStringLiteral("min_still"), d.minStill, 0.0, kInf, QStringLiteral("s"),
                                       tr("Shortest candidate thrust phase."))
              << ParameterSpec::number(QStringLiteral("zero_acc"), d.zeroAcc, 0.0, kInf, QStringLiteral("m/s^2"),
                                       tr("Inertial acceleration below which the ski is motionless (thrust start and "
                                          "end, Fasel 2017 Table 3.1)."));
        const PoleEventParams pd;
        specs << ParameterSpec::number(QStringLiteral("plant_threshold"), pd.plantThreshold, 0.0, kInf,
                                       QStringLiteral("m/s^2"),
                                       tr("Pole: vibration maximum (second difference of the acceleration norm) of a "
                                          "pole plant."))
              << ParameterSpec::number(QStringLiteral("onset_threshold"), pd.onsetThreshold, 0.0, kInf,
                                       QStringLiteral("m/s^2"),
                                       tr("Pole: vibration at the start of the plant shock, searched up to 100 ms "
                                          "before the maximum (Fasel 2017 ch. 3)."));
    } else {
        specs << ParameterSpec::number(QStringLiteral("initial_still"), d.initialStill, 0.05, kInf, QStringLiteral("s"),
                                       tr("The ski stands still for this long at the start of the recording (first "
                                          "inclination and gyroscope bias)."));
    }
    return specs;
}

QString XcSkiingCyclesProcessor::name() const { return tr("Cross-country skiing cycles"); }

QString XcSkiingCyclesProcessor::description() const {
    return tr(
        "Diagonal-stride cycles from a ski IMU (Fasel 2017 ch. 3): motionless thrust phases, ski inclination from the "
        "medio-lateral gyroscope re-anchored in each thrust, speed from the forward acceleration with zero-velocity "
        "updates, thrust start and end, gliding start (maximum speed), cycle duration, speed, length, elevation and "
        "slope; with a pole IMU also pole plant (start of the shock) and pole lift (acceleration peak). Writes a "
        "per-cycle table and predicted annotations.");
}

QList<InputSpec> XcSkiingCyclesProcessor::inputs() const {
    return {InputSpec{QStringLiteral("ski"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Ski-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).")},
            InputSpec{QStringLiteral("pole"),
                      {QStringLiteral("imu")},
                      false,
                      true,
                      tr("Pole-mounted IMU of the same side (optional): pole plant and lift.")}};
}

QList<OutputSpec> XcSkiingCyclesProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("ski-cycles"), true, QString(),
                       tr("Per cycle: thrust_start, thrust_end, glide_start, end (s), duration (s), speed (m/s), "
                          "length (m), elevation (m), slope (rad), pole_plant, pole_lift (s).")},
            OutputSpec{QString(), false, QString(),
                       tr("Cycles, thrust phases, gliding starts and pole pushes as predicted annotations."), true}};
}

ParameterSpecs XcSkiingCyclesProcessor::parameters() const { return skiCycleParameters(true); }

Expected<std::vector<ProcessorOutput>> XcSkiingCyclesProcessor::run(const RunContext& c) const {
    auto axes = skiAxesOf(c);
    if (!axes) return axes.error();
    auto ski = imuRowsOf(c, 0);
    if (!ski) return ski.error();
    SkiCycleParams p;
    p.zeroSpeed = c.number(QStringLiteral("zero_speed"));
    p.minCycle = c.number(QStringLiteral("min_cycle"));
    p.maxCycle = c.number(QStringLiteral("max_cycle"));
    p.maxThrust = c.number(QStringLiteral("max_still"));
    p.stillGyro = c.number(QStringLiteral("still_gyro"));
    p.stillAcc = c.number(QStringLiteral("still_acc"));
    p.minStill = c.number(QStringLiteral("min_still"));
    p.zeroAcc = c.number(QStringLiteral("zero_acc"));
    if (p.maxCycle <= p.minCycle)
        return makeError(
            QStringLiteral("max_cycle: %1 s must be longer than min_cycle (%2 s)").arg(p.maxCycle).arg(p.minCycle));
    c.report(0.1, QStringLiteral("integrating the ski"));
    const SkiCycleResult r =
        SkiCycleAnalyzer(p).analyze(toSkiFrame(ski->t, ski->acc, ski->gyr, axes->first, axes->second));
    if (c.isCancelled()) return cancelledError();
    if (r.cycles.empty())
        return c.inputError(0, QStringLiteral("no cross-country cycle found: %1 motionless phase(s) (still_gyro = %2 "
                                              "rad/s, still_acc = %3 m/s^2, zero_speed = %4 m/s); is it a ski IMU "
                                              "during diagonal stride with the axes set by forward_axis/ml_axis?")
                                   .arg(r.phases.size())
                                   .arg(p.stillGyro)
                                   .arg(p.stillAcc)
                                   .arg(p.zeroSpeed));

    std::vector<PoleEvents> pole;
    const bool hasPole = c.inputCount() > 1 && c.stream(1);
    if (hasPole) {
        auto rows = imuRowsOf(c, 1);
        if (!rows) return rows.error();
        std::vector<double> norm(rows->t.size());
        for (std::size_t i = 0; i < norm.size(); ++i)
            norm[i] = std::sqrt(rows->acc[3 * i] * rows->acc[3 * i] + rows->acc[3 * i + 1] * rows->acc[3 * i + 1] +
                                rows->acc[3 * i + 2] * rows->acc[3 * i + 2]);
        PoleEventParams pp;
        pp.plantThreshold = c.number(QStringLiteral("plant_threshold"));
        pp.onsetThreshold = c.number(QStringLiteral("onset_threshold"));
        pp.minCycle = p.minCycle;
        pole = detectPoleEvents(rows->t, norm, pp);
        if (pole.empty())
            return c.inputError(1, QStringLiteral("no pole plant found (plant_threshold = %1 m/s^2): is it a pole IMU?")
                                       .arg(pp.plantThreshold));
    }

    std::vector<double> plant, lift;
    Annotations annotations;
    for (const SkiCycle& cy : r.cycles) {
        // The pole plant nearest the thrust start, within half a cycle.
        double bestPlant = std::nan(""), bestLift = std::nan("");
        for (const PoleEvents& e : pole)
            if (std::abs(e.plant - cy.thrustStart) < 0.5 * cy.duration &&
                (std::isnan(bestPlant) || std::abs(e.plant - cy.thrustStart) < std::abs(bestPlant - cy.thrustStart))) {
                bestPlant = e.plant;
                bestLift = e.lift;
            }
        plant.push_back(bestPlant);
        lift.push_back(bestLift);
        annotations.push_back(annotation(QStringLiteral("xc cycle"), cy.thrustStart, cy.end));
        annotations.push_back(annotation(QStringLiteral("thrust"), cy.thrustStart, cy.thrustEnd));
        annotations.push_back(annotation(QStringLiteral("glide start"), cy.glideStart, cy.glideStart));
    }
    for (const PoleEvents& e : pole) annotations.push_back(annotation(QStringLiteral("pole push"), e.plant, e.lift));

    Table table;
    table.kind = QStringLiteral("ski-cycles");
    double total = 0.0;
    for (const SkiCycle& cy : r.cycles) total += cy.length;
    table.attributes = QJsonObject{{QStringLiteral("cycles"), int(r.cycles.size())},
                                   {QStringLiteral("distance"), total},
                                   {QStringLiteral("pole"), hasPole}};
    table.columns = skiCycleColumns(r.cycles, QStringLiteral("thrust"), true);
    if (hasPole) {
        table.columns.push_back(numberColumn(QStringLiteral("pole_plant"), QStringLiteral("s"), plant));
        table.columns.push_back(numberColumn(QStringLiteral("pole_lift"), QStringLiteral("s"), lift));
    }
    c.report(1.0);
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(table)});
    out.push_back({QString(), std::move(annotations)});
    return out;
}

}  // namespace athlos::events
