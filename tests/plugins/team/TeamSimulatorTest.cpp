// The football match simulator and its processor: rate and duration, pitch bounds, speed and
// acceleration bounds measured on the sampled positions, plausible running loads and speed zones,
// formation shape, determinism by seed, and the 22 named streams with their metadata.
#include "core/processing/ProcessorRunner.h"
#include "plugins/team/SimulateTeamProcessor.h"
#include "plugins/team/TeamSimulator.h"

#include <QDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;
using namespace athlos::team;

namespace {

const TeamSimulator::Result& fullMatch() {
    static const TeamSimulator::Result result = [] {
        TeamSimulator::Params p;
        p.seed = 7;
        return TeamSimulator::simulate(p);
    }();
    return result;
}

double speedAt(const TeamSimulator::Track& tr, std::size_t k, double dt) {
    return std::hypot(tr.x[k + 1] - tr.x[k], tr.y[k + 1] - tr.y[k]) / dt;
}

}  // namespace

TEST(TeamSimulator, RateAndDuration) {
    const auto& r = fullMatch();
    ASSERT_EQ(r.t.size(), std::size_t(5400 * 10 + 1));
    EXPECT_DOUBLE_EQ(r.t.front(), 0.0);
    EXPECT_NEAR(r.t.back(), 5400.0, 1e-9);
    for (std::size_t k = 1; k < r.t.size(); k += 997) EXPECT_NEAR(r.t[k] - r.t[k - 1], 0.1, 1e-9);
    ASSERT_EQ(r.tracks.size(), std::size_t(22));
    for (const auto& tr : r.tracks) ASSERT_EQ(tr.x.size(), r.t.size());

    TeamSimulator::Params p;
    p.duration = 60.0;
    p.rate = 25.0;
    const auto short25 = TeamSimulator::simulate(p);
    EXPECT_EQ(short25.t.size(), std::size_t(60 * 25 + 1));
    EXPECT_NEAR(short25.t[1], 0.04, 1e-12);
}

TEST(TeamSimulator, StaysOnThePitch) {
    for (const auto& tr : fullMatch().tracks)
        for (std::size_t k = 0; k < tr.x.size(); ++k) {
            ASSERT_LE(std::abs(tr.x[k]), 52.5) << k;
            ASSERT_LE(std::abs(tr.y[k]), 34.0) << k;
        }
}

TEST(TeamSimulator, SpeedAndAccelerationBounds) {
    const auto& r = fullMatch();
    const double dt = 0.1, aMax = TeamSimulator::Params().accelMax;
    for (std::size_t i = 0; i < r.tracks.size(); ++i) {
        const auto& tr = r.tracks[i];
        double vPeak = 0.0, aPeak = 0.0;
        for (std::size_t k = 1; k + 1 < tr.x.size(); ++k) {
            vPeak = std::max(vPeak, speedAt(tr, k, dt));
            // Second difference of the positions = the acceleration applied during the step.
            const double ax = (tr.x[k + 1] - 2 * tr.x[k] + tr.x[k - 1]) / (dt * dt);
            const double ay = (tr.y[k + 1] - 2 * tr.y[k] + tr.y[k - 1]) / (dt * dt);
            aPeak = std::max(aPeak, std::hypot(ax, ay));
        }
        EXPECT_LE(vPeak, r.players[i].topSpeed + 1e-6) << i;
        EXPECT_LE(vPeak, 9.0 + 1e-6) << i;
        EXPECT_LE(aPeak, aMax + 1e-6) << i;
        // Accelerations and sprints are used, not just allowed.
        EXPECT_GT(aPeak, 0.6 * aMax) << i;
        if (r.players[i].role != QLatin1String("GK")) {
            EXPECT_GT(vPeak, 6.5) << i;
        }
    }
}

// Match loads as GPS studies report them: outfield players ~9–13 km per 90 min, goalkeepers far less,
// most of the time below 2 m/s (standing, walking), a few per cent above 7 m/s.
TEST(TeamSimulator, PlausibleLoadsAndSpeedZones) {
    const auto& r = fullMatch();
    const double dt = 0.1;
    for (std::size_t i = 0; i < r.tracks.size(); ++i) {
        const auto& tr = r.tracks[i];
        double distance = 0.0;
        std::size_t slow = 0, sprint = 0, moving = 0;
        for (std::size_t k = 0; k + 1 < tr.x.size(); ++k) {
            const double v = speedAt(tr, k, dt);
            distance += v * dt;
            slow += v < 2.0;
            sprint += v > 7.0;
            moving += v > 0.2;
        }
        const double steps = double(tr.x.size() - 1);
        if (r.players[i].role == QLatin1String("GK")) {
            EXPECT_GT(distance, 1500.0) << i;
            EXPECT_LT(distance, 7000.0) << i;
        } else {
            EXPECT_GT(distance, 8000.0) << i;
            EXPECT_LT(distance, 14000.0) << i;
            EXPECT_GT(slow / steps, 0.4) << i;
            EXPECT_LT(slow / steps, 0.85) << i;
            EXPECT_GT(sprint / steps, 0.002) << i;
            EXPECT_LT(sprint / steps, 0.03) << i;
        }
        EXPECT_GT(moving / steps, 0.5) << i;  // nobody stands still for most of the match
    }
}

TEST(TeamSimulator, KeepsShapeAndGoalkeepersAtHome) {
    const auto& r = fullMatch();
    for (int team = 0; team < 2; ++team) {
        const double s = team == 0 ? 1.0 : -1.0;  // home attacks +x
        const auto& gk = r.tracks[std::size_t(team * 11)];
        double defenders = 0, forwards = 0;
        for (std::size_t k = 0; k < gk.x.size(); ++k) {
            ASSERT_LT(s * gk.x[k], -30.0) << "goalkeeper left his area at sample " << k;
            for (int j : {1, 2, 3, 4}) defenders += s * r.tracks[std::size_t(team * 11 + j)].x[k];
            for (int j : {8, 9}) forwards += s * r.tracks[std::size_t(team * 11 + j)].x[k];
        }
        const double n = double(gk.x.size());
        EXPECT_LT(defenders / (4 * n) + 15.0, forwards / (2 * n)) << team;
        // Kick-off: each team in its own half.
        for (int j = 0; j < 11; ++j) EXPECT_LT(s * r.tracks[std::size_t(team * 11 + j)].x[0], 0.0);
    }
}

TEST(TeamSimulator, DeterministicBySeed) {
    TeamSimulator::Params p;
    p.duration = 300.0;
    p.seed = 3;
    const auto a = TeamSimulator::simulate(p), b = TeamSimulator::simulate(p);
    p.seed = 4;
    const auto c = TeamSimulator::simulate(p);
    bool differs = false;
    for (std::size_t i = 0; i < a.tracks.size(); ++i) {
        EXPECT_EQ(a.tracks[i].x, b.tracks[i].x);
        EXPECT_EQ(a.tracks[i].y, b.tracks[i].y);
        differs |= a.tracks[i].x != c.tracks[i].x;
    }
    EXPECT_TRUE(differs);
}

TEST(SimulateTeamProcessor, WritesOneNamedStreamPerPlayer) {
    auto project = Project::create(QDir::temp().filePath(QStringLiteral("athlos-team-test.athlos")));
    SimulateTeamProcessor processor;
    const auto out = runProcessor(*project, processor,
                                  {QStringLiteral("simulate-team"),
                                   {},
                                   QStringLiteral("match/player"),
                                   {{QStringLiteral("seed"), 2}, {QStringLiteral("duration"), 120}}});
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
    ASSERT_EQ(out->written.size(), 22);
    EXPECT_EQ(out->written.front(), QStringLiteral("match/player-home-01"));
    EXPECT_EQ(out->written.back(), QStringLiteral("match/player-away-11"));
    EXPECT_EQ(processor.outputs().size(), 22);
    const Stream* s = project->stream(QStringLiteral("match/player-away-07"));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->kind(), QStringLiteral("lps-position"));
    EXPECT_EQ(s->info().columnNames(), (QStringList{QStringLiteral("x"), QStringLiteral("y")}));
    EXPECT_EQ(s->info().columns[0].unit, QStringLiteral("m"));
    EXPECT_EQ(s->info().rows, 1201);
    const QJsonObject a = s->info().attributes;
    EXPECT_EQ(a.value(QStringLiteral("label")).toString(), QStringLiteral("A7"));
    EXPECT_EQ(a.value(QStringLiteral("team")).toString(), QStringLiteral("away"));
    EXPECT_EQ(a.value(QStringLiteral("number")).toInt(), 7);
    EXPECT_EQ(a.value(QStringLiteral("venue")).toString(), QStringLiteral("football"));
    EXPECT_EQ(s->info().provenance.processorId, QStringLiteral("simulate-team"));

    const auto bad = runProcessor(*project, processor,
                                  {QStringLiteral("simulate-team"),
                                   {},
                                   QStringLiteral("match/p"),
                                   {{QStringLiteral("top_speed_min"), 9.0}, {QStringLiteral("top_speed_max"), 8.0}}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("top_speed_max")));
}
