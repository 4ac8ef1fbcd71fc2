#pragma once
// Multi-athlete interaction features of a detected event (seed 000 §5.1.2 "Tackle Recognition";
// digest §7): a tackle involves an opponent in contact, so the thesis adds to the player's own IMU
// features the torso pitch and speed of the player and, for the k = 3 opponents nearest to him at
// the event (the interaction candidates; three rather than one because players cluster and the
// positions are inaccurate), their distance, speed and torso pitch. The feature selection of the
// thesis kept most often the player's torso pitch, the nearest opponent's torso pitch and the
// distance to him (§5.1.4).
//
// Per event at time t, window [t − window/2, t + window/2]:
//   own_pitch       mean torso pitch over the window (rad)
//   own_speed       speed over the second before t (m/s), from the positions
//   oppK_distance   distance at t to the K-th nearest opponent (m), K = 1..neighbours
//   oppK_speed      his speed over the second before t (m/s)
//   oppK_pitch      his mean torso pitch over the window (rad)
// Missing data (no positions, fewer opponents) give NaN, which the caller refuses or imputes.
#include <QString>
#include <QStringList>
#include <vector>

namespace athlos::activity {

class InteractionFeatures {
public:
    struct Params {
        int neighbours = 3;      // opponents considered (thesis: 3)
        double window = 4.0;     // s, the classification window (thesis: 4 s centred on the event)
        double speedSpan = 1.0;  // s before the event over which the speed is taken
    };

    struct Athlete {
        QString team;
        std::vector<double> tPos, x, y;     // s, m
        std::vector<double> tPitch, pitch;  // s, rad (TorsoPitch)
    };

    static QStringList names(const Params& params);
    // The features of athlete `player` at time t (names() order).
    static std::vector<double> compute(const std::vector<Athlete>& athletes, int player, double t,
                                       const Params& params);
};

}  // namespace athlos::activity
