#include "plugins/activity/RugbySimulator.h"

#include <QStringList>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::activity {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;
constexpr double kHalfLength = 50.0;  // m, sevens pitch 100 × 70 m (without in-goal areas)
constexpr double kHalfWidth = 35.0;
constexpr double kStanding = 5.0;  // s, everyone stands upright at the start (pitch reference)

double halfSine(double t, double start, double duration) {
    if (t < start || t > start + duration) return 0.0;
    return std::sin(kPi * (t - start) / duration);
}

double ringDown(double t, double t0, double tau, double frequency) {
    if (t < t0) return 0.0;
    return std::exp(-(t - t0) / tau) * std::cos(2.0 * kPi * frequency * (t - t0));
}

Eigen::Vector2d clampToPitch(Eigen::Vector2d p, double margin) {
    p.x() = std::clamp(p.x(), -kHalfLength + margin, kHalfLength - margin);
    p.y() = std::clamp(p.y(), -kHalfWidth + margin, kHalfWidth - margin);
    return p;
}

struct Event {
    enum Kind { Tackle, Scrum, Contact, Fall } kind = Tackle;
    bool scrum = false;
    double t = 0.0;         // scrum: binding starts; others: collision
    double duration = 0.0;  // scrum: binding time; tackle, fall: time on the ground
    double approach = 4.0;  // s before t: scrum: walking to the mark; tackle, contact: the chase
    Eigen::Vector2d mark{0.0, 0.0};
    bool started = false;  // the mark / the tackle pair is chosen when the approach starts
    int carrier = -1, tackler = -1;
    double size = 0.0;          // m/s², collision
    std::vector<double> pitch;  // rad, per player (scrum binding or going to ground)
};

struct PlayerState {
    Eigen::Vector2d p{0.0, 0.0}, v{0.0, 0.0}, roam{0.0, 0.0}, offset{0.0, 0.0};
    double heading = 0.0, pitch = 0.0, stepPhase = 0.0, cap = 1.5, nextPhase = 0.0;
    double cadence = 2.8, stepImpact = 6.0, bendUntil = -1.0, bendPitch = 0.0;
    Eigen::Matrix3d rPrev = Eigen::Matrix3d::Identity();
};
}  // namespace

std::vector<RugbySimulator::Player> RugbySimulator::roster() {
    std::vector<Player> out;
    for (int team = 0; team < 2; ++team)
        for (int n = 1; n <= kPlayersPerTeam; ++n)
            out.push_back({team == 0 ? QStringLiteral("home") : QStringLiteral("away"), n,
                           QStringLiteral("%1%2").arg(team == 0 ? QLatin1Char('H') : QLatin1Char('A')).arg(n)});
    return out;
}

QStringList RugbySimulator::imuColumns() {
    return {QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z"),
            QStringLiteral("gyr_x"), QStringLiteral("gyr_y"), QStringLiteral("gyr_z")};
}

RugbySimulator::Result RugbySimulator::simulate(const Params& params) {
    std::mt19937_64 rng(params.seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const int perTeam = std::clamp(params.scrumPlayersPerTeam, 1, 6);

    Result out;
    out.players = roster();
    out.tracks.resize(kPlayers);
    std::vector<PlayerState> st(kPlayers);
    for (int i = 0; i < kPlayers; ++i) {
        const bool home = i < kPlayersPerTeam;
        const int n = i % kPlayersPerTeam;
        PlayerState& s = st[std::size_t(i)];
        s.offset = {(home ? -1.0 : 1.0) * (3.0 + 4.0 * (n % 3)), (n - 3) * 7.0};
        s.p = clampToPitch(s.offset + Eigen::Vector2d(0.0, 0.0), 1.0);
        s.heading = home ? 0.0 : kPi;
        s.cadence = 2.6 + 0.6 * u(rng);
        s.stepImpact = 5.0 + 5.0 * u(rng);
        s.nextPhase = kStanding + 3.0 * u(rng);
        const Eigen::Vector3d tilt(8.0, 8.0, 8.0);  // degrees, largest mounting error per axis
        auto angle = [&](double deg) { return (2.0 * u(rng) - 1.0) * deg * kPi / 180.0; };
        Track& track = out.tracks[std::size_t(i)];
        track.mount = Eigen::AngleAxisd(angle(tilt.z()), Eigen::Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(angle(tilt.y()), Eigen::Vector3d::UnitY()) *
                      Eigen::AngleAxisd(angle(tilt.x()), Eigen::Vector3d::UnitX());
        track.imu.columns = 6;
    }

    // Events evenly spread over the match after the standing period, in random order.
    std::vector<Event> events;
    for (int k = 0; k < params.scrums; ++k) {
        Event e;
        e.kind = Event::Scrum;
        e.scrum = true;
        e.approach = 10.0;
        events.push_back(e);
    }
    for (int k = 0; k < params.contacts + params.falls; ++k) {
        Event e;
        e.kind = k < params.contacts ? Event::Contact : Event::Fall;
        events.push_back(e);
    }
    for (int k = 0; k < params.tackles; ++k) events.push_back(Event());
    std::shuffle(events.begin(), events.end(), rng);
    const double first = kStanding + 10.0, last = params.duration - 15.0;
    const double spacing = events.empty() ? 0.0 : (last - first) / double(events.size());
    for (std::size_t k = 0; k < events.size(); ++k) {
        Event& e = events[k];
        e.t = first + spacing * (double(k) + 0.45 + 0.1 * u(rng));
        e.duration = e.scrum ? 4.0 + 6.0 * u(rng) : 2.0 + 1.0 * u(rng);
        e.size = e.kind == Event::Contact ? 10.0 + 15.0 * u(rng) : 15.0 + 15.0 * u(rng);
        e.pitch.resize(kPlayers);
        for (double& p : e.pitch)
            p = e.scrum ? (62.0 + 26.0 * u(rng)) * kPi / 180.0 : (70.0 + 15.0 * u(rng)) * kPi / 180.0;
    }

    Eigen::Vector2d ball(0.0, 0.0), ballTarget(0.0, 0.0);
    double nextBall = kStanding;
    const double dt = 1.0 / params.imuRate;
    const std::size_t samples = std::size_t(std::floor(params.duration * params.imuRate)) + 1;
    std::vector<std::vector<Eigen::Vector2d>> path(kPlayers);
    for (auto& p : path) p.reserve(samples);
    for (auto& t : out.tracks) {
        t.imu.t.reserve(samples);
        t.imu.values.reserve(samples * 6);
        t.pitch.reserve(samples);
    }

    for (std::size_t k = 0; k < samples; ++k) {
        const double now = double(k) * dt;
        // The ball: a point of play that moves to a new spot every 4–8 s.
        if (now >= nextBall) {
            ballTarget = clampToPitch({(2.0 * u(rng) - 1.0) * 40.0, (2.0 * u(rng) - 1.0) * 28.0}, 5.0);
            nextBall = now + 4.0 + 4.0 * u(rng);
        }
        if (now >= kStanding) {
            const Eigen::Vector2d d = ballTarget - ball;
            if (d.norm() > 1e-9) ball += d.normalized() * std::min(d.norm(), 5.0 * dt);
        }
        // The event in progress (at most one: events are ≥ 20 s apart).
        Event* active = nullptr;
        for (Event& e : events)
            if (now >= e.t - e.approach && now <= e.t + e.duration) active = &e;
        if (active && !active->started) {
            active->started = true;
            if (active->scrum) {
                active->mark = clampToPitch(ball, 8.0);
                ball = ballTarget = active->mark;
            } else if (active->kind == Event::Fall) {  // the player farthest from every opponent
                double farthest = -1.0;
                for (int i = 0; i < kPlayers; ++i) {
                    double nearest = 1e300;
                    for (int j = 0; j < kPlayers; ++j)
                        if ((i < kPlayersPerTeam) != (j < kPlayersPerTeam))
                            nearest = std::min(nearest, (st[std::size_t(j)].p - st[std::size_t(i)].p).norm());
                    if (nearest > farthest) farthest = nearest, active->carrier = i;
                }
                active->mark = st[std::size_t(active->carrier)].p;
            } else {  // the carrier and his nearest opponent
                active->carrier = int(u(rng) * kPlayers) % kPlayers;
                const bool home = active->carrier < kPlayersPerTeam;
                double best = 1e300;
                for (int j = home ? kPlayersPerTeam : 0; j < (home ? kPlayers : kPlayersPerTeam); ++j) {
                    const double dist = (st[std::size_t(j)].p - st[std::size_t(active->carrier)].p).norm();
                    if (dist < best) best = dist, active->tackler = j;
                }
            }
        }
        if (active && active->scrum) ball = active->mark;

        for (int i = 0; i < kPlayers; ++i) {
            PlayerState& s = st[std::size_t(i)];
            const bool home = i < kPlayersPerTeam;
            const int n = i % kPlayersPerTeam;
            // Intensity phases: walking, jogging, running, sprinting.
            if (now >= s.nextPhase) {
                const double r = u(rng);
                s.cap = r < 0.3 ? 1.5 : r < 0.65 ? 3.0 : r < 0.9 ? 5.0 : 7.5;
                s.nextPhase = now + 2.0 + 6.0 * u(rng);
            }
            s.roam += (-s.roam * dt / 5.0) + std::sqrt(2.0 * dt / 5.0) * 3.0 * Eigen::Vector2d(gauss(rng), gauss(rng));
            Eigen::Vector2d target = clampToPitch(ball + s.offset + s.roam, 1.0);
            double cap = now < kStanding ? 0.0 : s.cap, pitchTarget = now < kStanding ? 0.0 : 0.05, gain = 1.0;
            bool bound = false, ground = false, fixedHeading = false;
            double fixed = 0.0;
            if (active && active->scrum) {
                const bool inScrum = n < perTeam;
                if (inScrum) {
                    const double row = double(n / 3), col = double(n % 3) - 1.0;
                    target = active->mark + Eigen::Vector2d((home ? -1.0 : 1.0) * (0.45 + 1.0 * row), 0.6 * col);
                    cap = 5.0;
                    if (now >= active->t) {
                        bound = true;
                        fixedHeading = true;
                        fixed = home ? 0.0 : kPi;
                        pitchTarget = active->pitch[std::size_t(i)];
                        gain = 3.0;
                    }
                } else {  // the backs wait behind their scrum
                    target = active->mark + Eigen::Vector2d((home ? -1.0 : 1.0) * (6.0 + 3.0 * (n % 3)),
                                                            (n % 2 ? 1.0 : -1.0) * (4.0 + 3.0 * n));
                    target = clampToPitch(target, 1.0);
                    cap = std::min(cap, 3.0);
                }
            } else if (active && active->kind == Event::Fall && i == active->carrier) {
                // Like the pair of a tackle, who meet and stop before the collision: to a spot, then down.
                if (now < active->t) {
                    target = active->mark;
                    cap = 7.0;
                    gain = 2.0;
                } else {
                    ground = true;
                    pitchTarget = active->pitch[std::size_t(i)];
                }
            } else if (active && (i == active->carrier || i == active->tackler)) {
                const PlayerState& other = st[std::size_t(i == active->carrier ? active->tackler : active->carrier)];
                if (now < active->t) {
                    target = 0.5 * (s.p + other.p);
                    cap = 7.0;
                    gain = 2.0;
                } else if (active->kind == Event::Tackle) {
                    ground = true;
                    pitchTarget = active->pitch[std::size_t(i)];
                }
            }
            // A single player bending to pick up the ball (not a scrum: one player only).
            if (!active && now > kStanding && s.bendUntil < now && u(rng) < dt / 60.0) {
                s.bendUntil = now + 0.8 + 0.6 * u(rng);
                s.bendPitch = (60.0 + 15.0 * u(rng)) * kPi / 180.0;
            }
            if (now < s.bendUntil) pitchTarget = std::max(pitchTarget, s.bendPitch);

            // Velocity towards the target with an arrival profile and bounded acceleration.
            const Eigen::Vector2d d = target - s.p;
            Eigen::Vector2d vDes = Eigen::Vector2d::Zero();
            if (!ground && cap > 0.0 && d.norm() > 1e-6) {
                const double speed =
                    bound ? std::min(gain * d.norm(), 5.0) : std::min(cap, std::sqrt(2.0 * 3.0 * gain * d.norm()));
                vDes = d.normalized() * speed;
            }
            const double aMax = ground ? 10.0 : 4.0;  // m/s², hard accelerations of field-sport players
            Eigen::Vector2d dv = vDes - s.v;
            if (dv.norm() > aMax * dt) dv *= aMax * dt / dv.norm();
            const Eigen::Vector2d aWorld2 = dv / dt;
            s.v += dv;
            s.p += s.v * dt;
            const double speed = s.v.norm();
            if (!ground && now >= kStanding && pitchTarget < 0.3) pitchTarget = 0.05 + 0.025 * speed;

            // Heading: along the velocity (rate-limited), fixed while bound.
            double want = s.heading;
            if (fixedHeading)
                want = fixed;
            else if (speed > 0.7)
                want = std::atan2(s.v.y(), s.v.x());
            const double turn = std::remainder(want - s.heading, 2.0 * kPi);
            s.heading += std::clamp(turn, -4.0 * dt, 4.0 * dt);
            s.pitch += (pitchTarget - s.pitch) * std::min(1.0, dt / 0.25);
            if (speed > 0.5) s.stepPhase += 2.0 * kPi * s.cadence * dt;
            const double roll = speed > 0.5 ? 0.04 * std::sin(0.5 * s.stepPhase) : 0.0;

            const Eigen::Matrix3d body = (Eigen::AngleAxisd(s.heading, Eigen::Vector3d::UnitZ()) *
                                          Eigen::AngleAxisd(s.pitch, Eigen::Vector3d::UnitY()) *
                                          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                             .toRotationMatrix();
            Track& track = out.tracks[std::size_t(i)];
            const Eigen::Matrix3d sensor = body * track.mount.toRotationMatrix();
            // Specific force: the applied acceleration, gravity, step impacts, collisions, landings.
            Eigen::Vector3d f(aWorld2.x(), aWorld2.y(), kG);
            if (speed > 0.5)
                f.z() += s.stepImpact * std::min(1.0, speed / 6.0) *
                         (std::pow(std::max(0.0, std::sin(s.stepPhase)), 6) - 0.15625);
            if (active && !active->scrum && (i == active->carrier || i == active->tackler)) {
                const Eigen::Vector3d forward = body.col(0);
                f -= active->size * halfSine(now, active->t - 0.25, 0.5) * forward;
                if (active->kind != Event::Contact) f.z() += 12.0 * ringDown(now, active->t + 0.7, 0.08, 5.0);
            }
            const Eigen::Vector3d acc = sensor.transpose() * f;
            Eigen::Vector3d gyr = Eigen::Vector3d::Zero();
            if (k > 0) {
                const Eigen::AngleAxisd rel(s.rPrev.transpose() * sensor);
                gyr = rel.axis() * rel.angle() / dt;
            }
            s.rPrev = sensor;
            track.imu.t.push_back(now);
            for (int c = 0; c < 3; ++c) track.imu.values.push_back(acc[c] + 0.2 * gauss(rng));
            for (int c = 0; c < 3; ++c) track.imu.values.push_back(gyr[c] + 0.02 * gauss(rng));
            // True torso pitch: the angle between the torso's long axis and the vertical.
            track.pitch.push_back(std::acos(std::clamp(body(2, 2), -1.0, 1.0)));
            path[std::size_t(i)].push_back(s.p);
        }
    }

    // Positions at the LPS rate: linear interpolation of the path plus noise.
    const std::size_t positions = std::size_t(std::floor(params.duration * params.positionRate)) + 1;
    out.tPosition.resize(positions);
    for (std::size_t k = 0; k < positions; ++k) out.tPosition[k] = double(k) / params.positionRate;
    for (int i = 0; i < kPlayers; ++i) {
        Track& track = out.tracks[std::size_t(i)];
        track.x.resize(positions);
        track.y.resize(positions);
        const auto& pth = path[std::size_t(i)];
        for (std::size_t k = 0; k < positions; ++k) {
            const double s = out.tPosition[k] * params.imuRate;
            const std::size_t j = std::min(std::size_t(s), pth.size() - 2);
            const double w = std::clamp(s - double(j), 0.0, 1.0);
            const Eigen::Vector2d p = (1.0 - w) * pth[j] + w * pth[j + 1];
            track.x[k] = p.x() + params.positionNoise * gauss(rng);
            track.y[k] = p.y() + params.positionNoise * gauss(rng);
        }
    }

    for (const Event& e : events) {
        Annotation an;
        an.source = QStringLiteral("import");
        if (e.kind == Event::Contact || e.kind == Event::Fall) {
            (e.kind == Event::Contact ? out.contacts : out.falls).push_back({e.t, e.carrier, e.tackler});
            continue;
        }
        if (e.scrum) {
            out.scrums.push_back({e.t, e.t + e.duration});
            an.label = QStringLiteral("scrum");
            an.tStart = e.t;
            an.tEnd = e.t + e.duration;
        } else {
            out.tackles.push_back({e.t, e.carrier, e.tackler});
            an.label = QStringLiteral("tackle");
            an.tStart = e.t - 1.0;
            an.tEnd = e.t + 1.0;
        }
        out.truth.push_back(an);
    }
    std::sort(out.truth.begin(), out.truth.end(),
              [](const Annotation& a, const Annotation& b) { return a.tStart < b.tStart; });
    std::sort(out.scrums.begin(), out.scrums.end(),
              [](const Interval& a, const Interval& b) { return a.tStart < b.tStart; });
    std::sort(out.tackles.begin(), out.tackles.end(), [](const Tackle& a, const Tackle& b) { return a.t < b.t; });
    return out;
}

}  // namespace athlos::activity
