#pragma once
// A simulated rugby sevens match of two teams of seven (seed 000 §5.1; digest §7) with ground truth
// for the scrum detector, the torso pitch and multi-athlete features:
//  - positions at ~80 Hz (the LPS rate; x, y in m in a pitch frame centred at the origin, 100 × 70 m)
//    and an upper-back IMU at 200 Hz per player (acc in m/s², gyr in rad/s), the sensor mounted with
//    a small per-player misalignment (up to ±8° per axis) whose sensor→earth orientation is known,
//    so the true torso pitch (angle between the torso's long axis and the vertical) is known;
//  - the first 5 s all players stand upright (the standing period the torso pitch takes its
//    sensor reference from); then running play around a moving ball with phases of walking,
//    jogging and running, and occasional single players bending to pick up the ball (60–75°);
//  - tackles: a carrier and an opponent run into each other, a 15–30 m/s² collision, both go to
//    ground (torso pitch ~70–85°) for 2–3 s; annotated `tackle` [t − 1, t + 1] s;
//  - events that are not tackles but look like one to a single IMU: contacts (two opponents collide
//    at 10–25 m/s² and stay on their feet) and falls (the player farthest from every opponent goes
//    to ground alone after a 15–30 m/s² deceleration: a slip or a dive); not annotated;
//  - scrums: `scrumPlayersPerTeam` players of each team (3 in sevens: the front row, thesis
//    §5.1.1) walk to the mark, bind within ~2 m of each other with the front rows facing each
//    other, torso pitched forward 60–90° from upright for 4–10 s; annotated `scrum` over the binding.
// Deterministic for a seed (std::mt19937_64).
#include "core/model/Annotation.h"
#include "core/model/StreamData.h"

#include <Eigen/Geometry>

#include <QString>
#include <cstdint>
#include <vector>

namespace athlos::activity {

class RugbySimulator {
public:
    static constexpr int kPlayersPerTeam = 7;
    static constexpr int kPlayers = 2 * kPlayersPerTeam;

    struct Params {
        std::uint64_t seed = 1;
        double duration = 600.0;      // s
        double positionRate = 80.0;   // Hz
        double imuRate = 200.0;       // Hz
        int scrums = 4;               // scrums in the match
        int tackles = 8;              // tackles in the match
        int contacts = 8;             // collisions of two opponents who stay on their feet (not tackles)
        int falls = 4;                // a player going to ground alone (slip, dive), no opponent near
        int scrumPlayersPerTeam = 3;  // 3 in sevens (thesis §5.1.1), up to 6
        double positionNoise = 0.05;  // m, SD of the position noise (filtered LPS)
    };

    struct Player {
        QString team;  // "home", "away"
        int number = 0;
        QString label;  // "H1", "A7"
    };

    struct Track {
        std::vector<double> x, y;   // m, at Result::tPosition
        StreamData imu;             // t, acc_x..z (m/s²), gyr_x..z (rad/s)
        std::vector<double> pitch;  // rad, true torso pitch at imu.t
        Eigen::Quaterniond mount;   // sensor → torso
    };

    struct Interval {
        double tStart = 0.0, tEnd = 0.0;
    };

    struct Tackle {
        double t = 0.0;  // the collision
        int carrier = 0, tackler = 0;
    };

    struct Result {
        std::vector<double> tPosition;  // s, shared by all tracks
        std::vector<Player> players;    // home 1..7, away 1..7
        std::vector<Track> tracks;      // same order as players
        std::vector<Interval> scrums;
        std::vector<Tackle> tackles;
        std::vector<Tackle> contacts;  // not tackles: both stay on their feet
        std::vector<Tackle> falls;     // not tackles: carrier alone, tackler −1
        Annotations truth;             // `scrum` and `tackle`, source "import"
    };

    static std::vector<Player> roster();
    static QStringList imuColumns();  // acc_x..z, gyr_x..z
    static Result simulate(const Params& params);
};

}  // namespace athlos::activity
