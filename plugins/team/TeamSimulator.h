#pragma once
// A simulated football match: 22 player tracks (two teams of 11 in a 4-4-2, goalkeepers included)
// on a 105 × 68 m pitch centred at the origin, x along the length (home attacks +x), sampled at a
// fixed rate. Ground truth for views and benchmarks, not a tactical model. The parts:
//  - the ball (the focus of play): passes of 5–35 m biased towards the attacked goal, dribbles,
//    turnovers and shots; after a shot the defending goalkeeper restarts;
//  - each team's block shifts with the ball along x and y and is compressed across the pitch;
//    the team in possession pushes up, the other drops; one outfield player per team presses the ball;
//  - each player's target is his formation slot in the block plus a slow individual roaming offset
//    (Ornstein–Uhlenbeck), kept 1 m inside the lines;
//  - intensity phases (standing, walking, jogging, running, sprinting) as a Markov chain per player
//    whose choice depends on how far the target is, giving the speed cap (0, 1.4, 3.0, 5.0 m/s,
//    sprint = the player's top speed of 7.8–9.0 m/s);
//  - arrival control v_des = min(cap, √(2·a_plan·distance)) towards the target, with per-axis braking
//    before the lines, then a limit on the change of velocity: |a| ≤ accel_max (vector) and the
//    forward part of it ≤ accel_max·(1 − v/v_top) (human sprint profile), semi-implicit Euler.
// The second difference of the sampled positions equals the applied acceleration, so the bounds
// hold exactly in the data. Deterministic for a seed (std::mt19937_64).
#include <Eigen/Core>

#include <QString>
#include <cstdint>
#include <vector>

namespace athlos::team {

class TeamSimulator {
public:
    static constexpr int kPlayersPerTeam = 11;
    static constexpr int kPlayers = 2 * kPlayersPerTeam;

    struct Params {
        std::uint64_t seed = 1;
        double duration = 5400.0;    // s of play
        double rate = 10.0;          // Hz
        double pitchLength = 105.0;  // m (x)
        double pitchWidth = 68.0;    // m (y)
        double accelMax = 6.0;       // m/s², bound of |a|
        double topSpeedMin = 7.8;    // m/s, range of the players' sprint speed
        double topSpeedMax = 9.0;
        double intensity = 1.0;  // scales how readily players choose faster phases
    };

    struct Player {
        QString label;   // "H7", "A1"
        QString team;    // "home", "away"
        int number = 0;  // shirt number
        QString role;    // "GK", "DF", "MF", "FW"
        double topSpeed = 0.0;
    };

    struct Track {
        std::vector<double> x, y;  // m, one per time stamp
    };

    struct Result {
        std::vector<double> t;  // s, shared by all tracks
        std::vector<Player> players;
        std::vector<Track> tracks;  // kPlayers, same order as players
        std::vector<double> ballX, ballY;
    };

    // Players in output order: home 1..11 then away 1..11 (shirt numbers).
    static std::vector<Player> roster();
    static Result simulate(const Params& params);
};

}  // namespace athlos::team
