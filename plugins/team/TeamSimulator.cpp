#include "plugins/team/TeamSimulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace athlos::team {

namespace {

using Vec2 = Eigen::Vector2d;

enum Phase { Stand, Walk, Jog, Run, Sprint, PhaseCount };

constexpr std::array<double, PhaseCount> kPhaseMeanDuration{5.0, 10.0, 5.0, 3.0, 2.5};  // s
constexpr double kPlanDecel = 2.5;     // m/s², braking assumed when planning arrival and lines
constexpr double kBallSpeed = 14.0;    // m/s of a pass
constexpr double kLineMargin = 1.0;    // m, targets stay this far inside the lines
constexpr double kRoamSd = 3.5;        // m, individual roaming offset (stationary SD)
constexpr double kRoamTau = 20.0;      // s
constexpr double kBurstEvery = 300.0;  // s, mean time between an outfield player's sprint runs

// 4-4-2 slots in the frame of a team attacking +x: shirt number → (x, y). Right side is −y.
struct Slot {
    int number;
    const char* role;
    double x, y;
};
constexpr std::array<Slot, TeamSimulator::kPlayersPerTeam> kFormation{{
    {1, "GK", -47.0, 0.0},
    {2, "DF", -30.0, -24.0},
    {3, "DF", -30.0, 24.0},
    {4, "DF", -32.0, -8.0},
    {5, "DF", -32.0, 8.0},
    {6, "MF", -14.0, -7.0},
    {7, "MF", -12.0, -22.0},
    {8, "MF", -14.0, 7.0},
    {9, "FW", 3.0, -7.0},
    {10, "FW", 3.0, 7.0},
    {11, "MF", -12.0, 22.0},
}};

// The focus of play: passes, dribbles, turnovers and shots.
class Ball {
public:
    Ball(double halfLength, double halfWidth) : hl_(halfLength), hw_(halfWidth) {}

    Vec2 position = Vec2::Zero();
    int possession = 0;  // 0 home (attacks +x), 1 away

    void step(double dt, std::mt19937_64& rng) {
        std::uniform_real_distribution<double> uni(0.0, 1.0);
        if (travelling_) {
            const Vec2 d = target_ - position;
            const double dist = d.norm();
            if (dist <= kBallSpeed * dt) {
                position = target_;
                travelling_ = false;
                if (turnover_) possession = 1 - possession;
                if (restart_) {  // the goalkeeper of the defending side restarts
                    const double s = possession == 0 ? 1.0 : -1.0;
                    position = Vec2(-s * (hl_ - 6.0), 0.0);
                    restart_ = false;
                }
                hold_ = 1.0 + 3.0 * uni(rng);
                const double s = possession == 0 ? 1.0 : -1.0;
                dribble_ = Vec2(s * (1.0 + 2.5 * uni(rng)), 1.5 * (uni(rng) - 0.5));
            } else {
                position += d / dist * kBallSpeed * dt;
            }
            return;
        }
        // Dribbling while held.
        position += dribble_ * dt;
        position.x() = std::clamp(position.x(), -hl_ + kLineMargin, hl_ - kLineMargin);
        position.y() = std::clamp(position.y(), -hw_ + kLineMargin, hw_ - kLineMargin);
        hold_ -= dt;
        if (hold_ > 0.0) return;

        const double s = possession == 0 ? 1.0 : -1.0;
        const double goalX = s * hl_;
        std::normal_distribution<double> gauss(0.0, 1.0);
        if (std::abs(position.x() - goalX) < 22.0 && std::abs(position.y()) < 20.0 && uni(rng) < 0.35) {
            target_ = Vec2(goalX, 3.0 * (2.0 * uni(rng) - 1.0));  // shot
            turnover_ = true;
            restart_ = true;
        } else {
            // Mostly short passes, forward-biased; the odd one backwards.
            const double length = 5.0 + 30.0 * std::pow(uni(rng), 1.7);
            const double angle = 0.9 * gauss(rng) + (uni(rng) < 0.15 ? 3.14159 : 0.0);
            target_ = position + length * Vec2(s * std::cos(angle), std::sin(angle));
            target_.x() = std::clamp(target_.x(), -hl_ + kLineMargin, hl_ - kLineMargin);
            target_.y() = std::clamp(target_.y(), -hw_ + kLineMargin, hw_ - kLineMargin);
            turnover_ = uni(rng) < 0.22;
            restart_ = false;
        }
        travelling_ = true;
    }

private:
    double hl_, hw_;
    Vec2 target_ = Vec2::Zero();
    Vec2 dribble_ = Vec2::Zero();
    double hold_ = 1.0;
    bool travelling_ = false;
    bool turnover_ = false;
    bool restart_ = false;
};

struct PlayerState {
    Vec2 p = Vec2::Zero();
    Vec2 v = Vec2::Zero();
    Vec2 roam = Vec2::Zero();
    Phase phase = Walk;
    double phaseLeft = 0.0;
    double topSpeed = 8.5;
    Vec2 burstTarget = Vec2::Zero();  // a run in behind or a recovery run, at full speed
    double burstLeft = 0.0;
};

// Next intensity phase given the distance to the target: far targets call for running.
Phase choosePhase(double distance, double intensity, std::mt19937_64& rng) {
    std::array<double, PhaseCount> w;
    if (distance < 2.0)
        w = {0.50, 0.45, 0.05, 0.0, 0.0};
    else if (distance < 6.0)
        w = {0.20, 0.55, 0.20, 0.05, 0.0};
    else if (distance < 15.0)
        w = {0.0, 0.30, 0.35, 0.25, 0.10};
    else
        w = {0.0, 0.0, 0.15, 0.40, 0.45};
    w[Run] *= intensity;
    w[Sprint] *= intensity;
    std::discrete_distribution<int> pick(w.begin(), w.end());
    return Phase(pick(rng));
}

double phaseCap(Phase phase, double topSpeed) {
    switch (phase) {
        case Stand:
            return 0.0;
        case Walk:
            return 1.5;
        case Jog:
            return 3.2;
        case Run:
            return 5.2;
        default:
            return topSpeed;
    }
}

}  // namespace

std::vector<TeamSimulator::Player> TeamSimulator::roster() {
    std::vector<Player> players;
    for (int team = 0; team < 2; ++team)
        for (const Slot& slot : kFormation) {
            Player p;
            p.team = team == 0 ? QStringLiteral("home") : QStringLiteral("away");
            p.number = slot.number;
            p.label = (team == 0 ? QStringLiteral("H") : QStringLiteral("A")) + QString::number(slot.number);
            p.role = QString::fromLatin1(slot.role);
            players.push_back(p);
        }
    return players;
}

TeamSimulator::Result TeamSimulator::simulate(const Params& params) {
    std::mt19937_64 rng(params.seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const double dt = 1.0 / params.rate;
    const double hl = 0.5 * params.pitchLength, hw = 0.5 * params.pitchWidth;
    const std::size_t n = std::size_t(std::floor(params.duration * params.rate + 1e-9)) + 1;

    Result result;
    result.players = roster();
    result.t.resize(n);
    result.tracks.assign(kPlayers, Track{});
    for (auto& track : result.tracks) {
        track.x.resize(n);
        track.y.resize(n);
    }
    result.ballX.resize(n);
    result.ballY.resize(n);

    Ball ball(hl, hw);
    std::array<PlayerState, kPlayers> states;
    for (int i = 0; i < kPlayers; ++i) {
        states[i].topSpeed = params.topSpeedMin + (params.topSpeedMax - params.topSpeedMin) * uni(rng);
        result.players[std::size_t(i)].topSpeed = states[i].topSpeed;
        states[i].roam = Vec2(kRoamSd * gauss(rng), kRoamSd * gauss(rng));
        states[i].phaseLeft = kPhaseMeanDuration[Walk] * uni(rng);
    }

    // Target of player i (team frame first, then pitch frame: the away team's frame is turned 180°).
    auto targetOf = [&](int i) -> Vec2 {
        const int team = i / kPlayersPerTeam;
        const Slot& slot = kFormation[std::size_t(i % kPlayersPerTeam)];
        const double s = team == 0 ? 1.0 : -1.0;
        const Vec2 b = s * ball.position;  // ball in the team frame
        const bool inPossession = ball.possession == team;
        Vec2 q;
        if (slot.number == 1) {
            q = Vec2(-hl + 2.5 + std::clamp((b.x() + hl) * 0.12, 0.0, 14.0), std::clamp(0.2 * b.y(), -8.0, 8.0));
        } else {
            q = Vec2(std::clamp(slot.x + 0.45 * b.x() + (inPossession ? 8.0 : -2.0), -hl + 4.0, hl - 4.0),
                     0.7 * slot.y + 0.3 * b.y());
            q += states[std::size_t(i)].roam;
        }
        Vec2 p = s * q;
        p.x() = std::clamp(p.x(), -hl + kLineMargin, hl - kLineMargin);
        p.y() = std::clamp(p.y(), -hw + kLineMargin, hw - kLineMargin);
        return p;
    };

    // Kick-off: everybody on his target in his own half, standing.
    for (int i = 0; i < kPlayers; ++i) {
        Vec2 p = targetOf(i);
        const double s = i < kPlayersPerTeam ? 1.0 : -1.0;
        if (s * p.x() > -1.0) p.x() = -s * 1.0;
        states[std::size_t(i)].p = p;
    }

    std::array<int, 2> presser{1, kPlayersPerTeam + 1};
    const int pressEvery = std::max(1, int(std::lround(params.rate)));  // re-chosen once a second
    const double roamKeep = 1.0 - dt / kRoamTau, roamNoise = kRoamSd * std::sqrt(2.0 * dt / kRoamTau);

    for (std::size_t k = 0; k < n; ++k) {
        result.t[k] = double(k) * dt;
        for (int i = 0; i < kPlayers; ++i) {
            result.tracks[std::size_t(i)].x[k] = states[std::size_t(i)].p.x();
            result.tracks[std::size_t(i)].y[k] = states[std::size_t(i)].p.y();
        }
        result.ballX[k] = ball.position.x();
        result.ballY[k] = ball.position.y();
        if (k + 1 == n) break;

        ball.step(dt, rng);
        if (k % std::size_t(pressEvery) == 0) {
            for (int team = 0; team < 2; ++team) {
                double best = 1e300;
                for (int j = 1; j < kPlayersPerTeam; ++j) {
                    const int i = team * kPlayersPerTeam + j;
                    const double d = (states[std::size_t(i)].p - ball.position).squaredNorm();
                    if (d < best) best = d, presser[std::size_t(team)] = i;
                }
            }
        }

        for (int i = 0; i < kPlayers; ++i) {
            PlayerState& st = states[std::size_t(i)];
            st.roam = roamKeep * st.roam + roamNoise * Vec2(gauss(rng), gauss(rng));
            const bool pressing = presser[0] == i || presser[1] == i;
            const bool outfield = i % kPlayersPerTeam != 0;
            // Sprint runs: forward behind the defence in possession, back towards goal without.
            if (outfield && !pressing && st.burstLeft <= 0.0 && uni(rng) < dt / kBurstEvery) {
                const double s = i < kPlayersPerTeam ? 1.0 : -1.0;
                const double forward = ball.possession == i / kPlayersPerTeam ? s : -s;
                const double length = 25.0 + 10.0 * uni(rng), angle = 0.5 * gauss(rng);
                st.burstTarget = st.p + length * Vec2(forward * std::cos(angle), std::sin(angle));
                st.burstLeft = 4.0 + 2.0 * uni(rng);
            }
            st.burstLeft -= dt;
            const bool bursting = st.burstLeft > 0.0;
            Vec2 target = bursting ? st.burstTarget : pressing ? ball.position : targetOf(i);
            target.x() = std::clamp(target.x(), -hl + kLineMargin, hl - kLineMargin);
            target.y() = std::clamp(target.y(), -hw + kLineMargin, hw - kLineMargin);
            const Vec2 toTarget = target - st.p;
            const double distance = toTarget.norm();

            st.phaseLeft -= dt;
            // A player far from his target reacts within about a second instead of finishing a stroll.
            const bool late = distance > 12.0 && st.phase <= Walk && uni(rng) < 0.1;
            if (st.phaseLeft <= 0.0 || late) {
                st.phase = choosePhase(distance, params.intensity, rng);
                st.phaseLeft = -kPhaseMeanDuration[st.phase] * std::log(1.0 - uni(rng) * 0.999);
            }
            Phase phase = st.phase;
            if (pressing && distance > 3.0) phase = std::max(phase, distance > 8.0 ? Sprint : Run);
            if (bursting) phase = Sprint;

            // Arrival control: the speed that still lets the player stop at the target, capped by the phase.
            Vec2 vDes = Vec2::Zero();
            if (distance > 0.3) {
                const double speed =
                    std::min(phaseCap(phase, st.topSpeed), std::sqrt(2.0 * kPlanDecel * (distance - 0.3)));
                vDes = toTarget / distance * speed;
            }
            // Brake in time before each line.
            const double room[4] = {hl - 0.3 - st.p.x(), st.p.x() + hl - 0.3, hw - 0.3 - st.p.y(), st.p.y() + hw - 0.3};
            auto brake = [&](double r) { return std::sqrt(2.0 * kPlanDecel * std::max(r, 0.0)); };
            vDes.x() = std::clamp(vDes.x(), -brake(room[1]), brake(room[0]));
            vDes.y() = std::clamp(vDes.y(), -brake(room[3]), brake(room[2]));

            // Acceleration limits: |a| ≤ accelMax, speeding up ≤ accelMax·(1 − v/v_top).
            Vec2 dv = vDes - st.v;
            const double v = st.v.norm();
            if (v > 0.1) {
                const Vec2 u = st.v / v;
                const double along = dv.dot(u);
                const double forward = params.accelMax * std::max(0.0, 1.0 - v / st.topSpeed) * dt;
                if (along > forward) dv -= (along - forward) * u;
            }
            const double dvMax = params.accelMax * dt;
            if (dv.norm() > dvMax) dv *= dvMax / dv.norm();
            st.v += dv;
            // Projection onto the ball |v| ≤ v_top is non-expansive: the acceleration bound still holds.
            if (st.v.norm() > st.topSpeed) st.v *= st.topSpeed / st.v.norm();
            st.p += st.v * dt;
            // Safety net (the braking above keeps players inside; this only guards against rounding).
            st.p.x() = std::clamp(st.p.x(), -hl, hl);
            st.p.y() = std::clamp(st.p.y(), -hw, hw);
        }
    }
    return result;
}

}  // namespace athlos::team
