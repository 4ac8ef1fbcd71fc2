#include "plugins/activity/SimulateRugbyProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/activity/RugbySimulator.h"

#include <limits>

namespace athlos::activity {

namespace {
constexpr Translator tr{"athlos::activity", "SimulateRugbyProcessor"};

QString suffixOf(const char* sensor, const RugbySimulator::Player& player) {
    return QStringLiteral("%1-%2-%3")
        .arg(QLatin1String(sensor), player.team)
        .arg(player.number, 2, 10, QLatin1Char('0'));
}

QJsonObject attributesOf(const RugbySimulator::Player& player, double rate) {
    return QJsonObject{{QStringLiteral("simulated"), true},
                       {QStringLiteral("sampling_rate"), rate},
                       {QStringLiteral("athlete"), player.label},
                       {QStringLiteral("label"), player.label},
                       {QStringLiteral("team"), player.team},
                       {QStringLiteral("number"), player.number},
                       {QStringLiteral("venue"), QStringLiteral("rugby")}};
}
}  // namespace

QString SimulateRugbyProcessor::name() const { return tr("Simulate rugby sevens match"); }

QString SimulateRugbyProcessor::description() const {
    return tr(
        "Simulates a rugby sevens match of 2 × 7 players: positions (~80 Hz) and an upper-back IMU (200 Hz) per "
        "player, with running play, tackles (two players collide and go to ground), contacts and falls that are not "
        "tackles, and scrums (the front rows "
        "bind with the torso pitched 60–90° forward). The true scrums and tackles are written as annotations.");
}

ParameterSpecs SimulateRugbyProcessor::parameters() const {
    const RugbySimulator::Params d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed (deterministic).")),
        PS::number(QStringLiteral("duration"), d.duration, 60.0, 7200.0, QStringLiteral("s"),
                   tr("Length of the match.")),
        PS::integer(QStringLiteral("scrums"), d.scrums, 0, 100, tr("Number of scrums.")),
        PS::integer(QStringLiteral("tackles"), d.tackles, 0, 400, tr("Number of tackles.")),
        PS::integer(QStringLiteral("contacts"), d.contacts, 0, 400,
                    tr("Collisions of two opponents who stay on their feet (not tackles, not annotated).")),
        PS::integer(QStringLiteral("falls"), d.falls, 0, 400,
                    tr("Players going to ground alone, away from opponents (not tackles, not annotated).")),
        PS::integer(QStringLiteral("scrum_players"), d.scrumPlayersPerTeam, 1, 6,
                    tr("Players of each team bound in a scrum (3 in sevens: the front row, seed 000 §5.1.1).")),
        PS::number(QStringLiteral("position_rate"), d.positionRate, 1.0, 200.0, QStringLiteral("Hz"),
                   tr("Sampling rate of the positions (the LPS's ~80 Hz, seed 000 §5.1.2).")),
        PS::number(QStringLiteral("imu_rate"), d.imuRate, 50.0, 1000.0, QStringLiteral("Hz"),
                   tr("Sampling rate of the IMU (200 Hz, seed 000 §5.1.2).")),
    };
}

QList<OutputSpec> SimulateRugbyProcessor::outputs() const {
    QList<OutputSpec> specs;
    for (const auto& player : RugbySimulator::roster()) {
        OutputSpec imu;
        imu.kind = QStringLiteral("imu");
        imu.suffix = suffixOf("imu", player);
        imu.help = tr("Upper-back IMU of player %1: acc_x..z (m/s²), gyr_x..z (rad/s).").arg(player.label);
        specs << imu;
        OutputSpec pos;
        pos.kind = QStringLiteral("lps-position");
        pos.suffix = suffixOf("pos", player);
        pos.help = tr("Positions t, x, y (m) of player %1.").arg(player.label);
        specs << pos;
    }
    OutputSpec truth;
    truth.annotations = true;
    truth.help = tr("The true scrums and tackles as annotations.");
    specs << truth;
    return specs;
}

Expected<std::vector<ProcessorOutput>> SimulateRugbyProcessor::run(const RunContext& c) const {
    RugbySimulator::Params p;
    p.seed = std::uint64_t(c.integer(QStringLiteral("seed")));
    p.duration = c.number(QStringLiteral("duration"));
    p.scrums = c.integer(QStringLiteral("scrums"));
    p.tackles = c.integer(QStringLiteral("tackles"));
    p.contacts = c.integer(QStringLiteral("contacts"));
    p.falls = c.integer(QStringLiteral("falls"));
    p.scrumPlayersPerTeam = c.integer(QStringLiteral("scrum_players"));
    p.positionRate = c.number(QStringLiteral("position_rate"));
    p.imuRate = c.number(QStringLiteral("imu_rate"));
    // Events are spread evenly after 15 s; a scrum needs up to 20 s (approach, binding), so ≥ 25 s each.
    const int events = p.scrums + p.tackles + p.contacts + p.falls;
    const double needed = 30.0 + 25.0 * double(events);
    if (p.duration < needed)
        return makeError(QStringLiteral("parameter 'duration' (%1 s) is too short for %2 events (scrums, tackles, "
                                        "contacts, falls; needs at least %3 s)")
                             .arg(p.duration)
                             .arg(events)
                             .arg(needed));
    c.report(0.0, QStringLiteral("simulating"));
    if (c.isCancelled()) return cancelledError();
    auto sim = RugbySimulator::simulate(p);
    if (c.isCancelled()) return cancelledError();

    std::vector<ProcessorOutput> outputs;
    const QStringList units{QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2"),
                            QStringLiteral("rad/s"), QStringLiteral("rad/s"), QStringLiteral("rad/s")};
    for (std::size_t i = 0; i < sim.players.size(); ++i) {
        const auto& player = sim.players[i];
        auto& track = sim.tracks[i];
        StreamInfo imu;
        imu.kind = QStringLiteral("imu");
        imu.columns = columnsOf(RugbySimulator::imuColumns(), units);
        imu.attributes = attributesOf(player, p.imuRate);
        imu.attributes.insert(QStringLiteral("placement"), QStringLiteral("upper back"));
        outputs.push_back({suffixOf("imu", player), Stream(std::move(imu), std::move(track.imu))});

        StreamData data(sim.tPosition.size(), 2);
        data.t = sim.tPosition;
        for (std::size_t k = 0; k < data.rows(); ++k) {
            data.at(k, 0) = track.x[k];
            data.at(k, 1) = track.y[k];
        }
        StreamInfo pos;
        pos.kind = QStringLiteral("lps-position");
        pos.frame = QStringLiteral("pitch");
        pos.columns = {{QStringLiteral("x"), QStringLiteral("m")}, {QStringLiteral("y"), QStringLiteral("m")}};
        pos.attributes = attributesOf(player, p.positionRate);
        outputs.push_back({suffixOf("pos", player), Stream(std::move(pos), std::move(data))});
        c.report(double(i + 1) / double(sim.players.size()));
    }
    outputs.push_back({QString(), std::move(sim.truth)});
    return outputs;
}

}  // namespace athlos::activity
