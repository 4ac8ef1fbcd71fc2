#include "plugins/team/SimulateTeamProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/team/TeamSimulator.h"

#include <limits>

namespace athlos::team {

namespace {
constexpr Translator tr{"athlos::team", "SimulateTeamProcessor"};
}  // namespace

QString SimulateTeamProcessor::name() const { return tr("Simulate team match"); }

QString SimulateTeamProcessor::description() const {
    return tr(
        "Simulates a football match: 22 players (two teams in a 4-4-2 with goalkeepers) on a 105 × 68 m "
        "pitch, with standing, walking, jogging, running and sprinting phases, bounded accelerations and "
        "the team blocks shifting with the ball. One position stream per player.");
}

ParameterSpecs SimulateTeamProcessor::parameters() const {
    const TeamSimulator::Params d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed (deterministic).")),
        PS::number(QStringLiteral("duration"), d.duration, 1.0, 4.0 * 3600.0, QStringLiteral("s"), tr("Playing time.")),
        PS::number(QStringLiteral("rate"), d.rate, 1.0, 100.0, QStringLiteral("Hz"),
                   tr("Sampling rate of the positions.")),
        PS::number(QStringLiteral("accel_max"), d.accelMax, 1.0, 12.0, QStringLiteral("m/s^2"),
                   tr("Largest acceleration of a player (vector norm).")),
        PS::number(QStringLiteral("top_speed_min"), d.topSpeedMin, 4.0, 11.0, QStringLiteral("m/s"),
                   tr("Slowest sprint speed among the players.")),
        PS::number(QStringLiteral("top_speed_max"), d.topSpeedMax, 4.0, 11.0, QStringLiteral("m/s"),
                   tr("Fastest sprint speed among the players.")),
        PS::number(QStringLiteral("intensity"), d.intensity, 0.1, 5.0, QString(),
                   tr("How readily players choose running and sprinting (1 = typical).")),
    };
}

QString SimulateTeamProcessor::suffixOf(const QString& team, int number) {
    return QStringLiteral("%1-%2").arg(team).arg(number, 2, 10, QLatin1Char('0'));
}

QList<OutputSpec> SimulateTeamProcessor::outputs() const {
    QList<OutputSpec> specs;
    for (const auto& player : TeamSimulator::roster()) {
        OutputSpec spec;  // by field: OutputSpec grows members
        spec.kind = QStringLiteral("lps-position");
        spec.suffix = suffixOf(player.team, player.number);
        spec.help = tr("Positions t, x, y (m) of player %1.").arg(player.label);
        specs << spec;
    }
    return specs;
}

Expected<std::vector<ProcessorOutput>> SimulateTeamProcessor::run(const RunContext& c) const {
    TeamSimulator::Params p;
    p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    p.duration = c.number(QStringLiteral("duration"));
    p.rate = c.number(QStringLiteral("rate"));
    p.accelMax = c.number(QStringLiteral("accel_max"));
    p.topSpeedMin = c.number(QStringLiteral("top_speed_min"));
    p.topSpeedMax = c.number(QStringLiteral("top_speed_max"));
    p.intensity = c.number(QStringLiteral("intensity"));
    if (p.topSpeedMax < p.topSpeedMin)
        return makeError(QStringLiteral("parameter 'top_speed_max' (%1) must be >= 'top_speed_min' (%2)")
                             .arg(p.topSpeedMax)
                             .arg(p.topSpeedMin));

    c.report(0.0, QStringLiteral("simulating"));
    if (c.isCancelled()) return cancelledError();
    const auto sim = TeamSimulator::simulate(p);
    if (c.isCancelled()) return cancelledError();

    std::vector<ProcessorOutput> outputs;
    for (std::size_t i = 0; i < sim.players.size(); ++i) {
        const auto& player = sim.players[i];
        const auto& track = sim.tracks[i];
        StreamData data(sim.t.size(), 2);
        data.t = sim.t;
        for (std::size_t k = 0; k < data.rows(); ++k) {
            data.at(k, 0) = track.x[k];
            data.at(k, 1) = track.y[k];
        }
        StreamInfo info;
        info.kind = QStringLiteral("lps-position");
        info.frame = QStringLiteral("pitch");
        info.columns = {{QStringLiteral("x"), QStringLiteral("m")}, {QStringLiteral("y"), QStringLiteral("m")}};
        info.attributes = QJsonObject{{QStringLiteral("simulated"), true},
                                      {QStringLiteral("sampling_rate"), p.rate},
                                      {QStringLiteral("label"), player.label},
                                      {QStringLiteral("team"), player.team},
                                      {QStringLiteral("number"), player.number},
                                      {QStringLiteral("role"), player.role},
                                      {QStringLiteral("top_speed"), player.topSpeed},
                                      {QStringLiteral("venue"), QStringLiteral("football")}};
        outputs.push_back({suffixOf(player.team, player.number), Stream(std::move(info), std::move(data))});
        c.report(double(i + 1) / double(sim.players.size()));
    }
    return outputs;
}

}  // namespace athlos::team
