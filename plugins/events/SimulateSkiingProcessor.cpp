#include "plugins/events/SimulateSkiingProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/events/SkiingSimulator.h"
#include "plugins/events/XcSkiingCyclesProcessor.h"

#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "SimulateSkiingProcessor"};

Stream imuStream(const std::vector<double>& t, const std::vector<double>& rows, const QString& sensor,
                 const QJsonObject& attributes) {
    StreamData d(t.size(), 6);
    d.t = t;
    d.values = rows;
    QJsonObject a = attributes;
    a.insert(QStringLiteral("sensor"), sensor);
    return outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                        columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
                                  {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s"}),
                        std::move(d), a);
}

Table cycleTruth(const SkiCycleRecording& rec, const QJsonObject& attributes) {
    Table t;
    t.kind = QStringLiteral("ski-cycles-truth");
    t.attributes = attributes;
    std::vector<double> v[11];
    for (const SkiCycleTruth& c : rec.truth) {
        const double row[11] = {c.thrustStart, c.thrustEnd, c.glideStart, c.end,   c.end - c.thrustStart,
                                c.speed,       c.length,    c.elevation,  c.slope, c.polePlant,
                                c.poleLift};
        for (int k = 0; k < 11; ++k) v[k].push_back(row[k]);
    }
    const char* names[11] = {"thrust_start", "thrust_end", "glide_start", "end",        "duration", "speed",
                             "length",       "elevation",  "slope",       "pole_plant", "pole_lift"};
    const char* units[11] = {"s", "s", "s", "s", "s", "m/s", "m", "m", "rad", "s", "s"};
    for (int k = 0; k < 11; ++k)
        t.columns.push_back(numberColumn(QLatin1String(names[k]), QLatin1String(units[k]), std::move(v[k])));
    return t;
}
}  // namespace

QString SimulateSkiingProcessor::name() const { return tr("Simulate skiing IMUs"); }

QString SimulateSkiingProcessor::description() const {
    return tr(
        "Skiing IMU recordings with ground truth: cross-country diagonal stride (ski IMU at <output>, pole IMU at "
        "<output>-pole; motionless thrusts, hilly track), a ski-mountaineering ascent (ski IMU, 18° track) or an "
        "alpine run (sacrum IMU, turns 22–32 m apart at 20 m/s on a 26° slope). The true cycles or turns are at "
        "<output>-truth.");
}

ParameterSpecs SimulateSkiingProcessor::parameters() const {
    return {
        ParameterSpec::choice(QStringLiteral("scenario"),
                              {QStringLiteral("xc"), QStringLiteral("skimo"), QStringLiteral("alpine")},
                              QStringLiteral("xc"), tr("Discipline.")),
        ParameterSpec::integer(QStringLiteral("seed"), 3, 0, std::numeric_limits<int>::max(), tr("Random seed.")),
        ParameterSpec::integer(QStringLiteral("count"), 30, 3, 10000, tr("Number of cycles (xc, skimo) or turns.")),
    };
}

QList<OutputSpec> SimulateSkiingProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("imu"), false, QString(), tr("Ski IMU (xc, skimo) or sacrum IMU (alpine).")},
            OutputSpec{QStringLiteral("imu"), false, QStringLiteral("pole"), tr("Pole IMU (xc only).")},
            OutputSpec{QString(), true, QStringLiteral("truth"),
                       tr("True cycles (thrust_start … pole_lift) or turns (start, end, side).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateSkiingProcessor::run(const RunContext& c) const {
    const QString scenario = c.text(QStringLiteral("scenario"));
    const auto seed = static_cast<unsigned>(c.integer(QStringLiteral("seed")));
    const int count = c.integer(QStringLiteral("count"));
    const QJsonObject attrs{{QStringLiteral("simulated"), true},
                            {QStringLiteral("scenario"), scenario},
                            {QStringLiteral("seed"), double(seed)}};
    c.report(0.1, QStringLiteral("simulating"));
    std::vector<ProcessorOutput> out;
    if (scenario == QLatin1String("alpine")) {
        AlpineSimConfig config;
        config.seed = seed;
        config.turns = count;
        const AlpineRecording rec = simulateAlpine(config);
        out.push_back({QString(), imuStream(rec.t, rec.sacrum, QStringLiteral("sacrum"), attrs)});
        Table t;
        t.kind = QStringLiteral("alpine-turns-truth");
        t.attributes = attrs;
        std::vector<double> start, end;
        TableColumn side{QStringLiteral("side"), QString(), true, {}, {}};
        for (const AlpineTurnTruth& turn : rec.turns) {
            start.push_back(turn.start);
            end.push_back(turn.end);
            side.texts << (turn.left ? QStringLiteral("left") : QStringLiteral("right"));
        }
        t.columns = {numberColumn(QStringLiteral("start"), QStringLiteral("s"), start),
                     numberColumn(QStringLiteral("end"), QStringLiteral("s"), end), side};
        out.push_back({QStringLiteral("truth"), std::move(t)});
    } else {
        SkiCycleSimConfig config = scenario == QLatin1String("skimo") ? skimoConfig(seed) : SkiCycleSimConfig{};
        config.seed = seed;
        config.cycles = count;
        const SkiCycleRecording rec = simulateSkiCycles(config);
        out.push_back({QString(), imuStream(rec.t, rec.ski, QStringLiteral("left ski"), attrs)});
        if (!rec.pole.empty())
            out.push_back({QStringLiteral("pole"), imuStream(rec.t, rec.pole, QStringLiteral("left pole"), attrs)});
        out.push_back({QStringLiteral("truth"), cycleTruth(rec, attrs)});
    }
    c.report(1.0);
    return out;
}

}  // namespace athlos::events
