#pragma once
// Scrum detection by the top-6 torso pitch (seed 000 §5.1.2 "Scrum Recognition", Fig. 5.6, §5.1.4;
// digest §7): in a scrum the bound players bend forward far more than when standing or running.
// At each instant of a common time grid the torso pitch of all players is sorted in descending
// order and the six largest are averaged; the scrum is where this mean exceeds a threshold (the
// thesis fitted it by grid search so that no scrum was missed and reached 100 % sensitivity and
// specificity). Added here: a minimum duration (a scrum lasts several seconds, a tackle or a player
// bending for the ball does not bend six players at once for long) and, when positions are given,
// the six players must stand close together (bound players are within ~2 m of each other).
#include "core/model/Annotation.h"
#include "core/util/Expected.h"

#include <vector>

namespace athlos::activity {

class ScrumDetector {
public:
    struct Params {
        int players = 6;              // the top-k pitches averaged (thesis: 6, the players of a sevens scrum)
        double threshold = 0.959931;  // rad (55°): between running (< 25°) and binding (60–90°), Fig. 5.6
        double minDuration = 2.0;     // s, shorter episodes are not scrums
        double maxSpread = 4.0;       // m, largest distance of the top-k players from their centroid; 0: not checked
        double gridRate = 10.0;       // Hz, the common time grid
        double mergeGap = 1.0;        // s, episodes closer than this are one scrum
    };

    struct Player {
        std::vector<double> t, pitch;    // s, rad (TorsoPitch)
        std::vector<double> tPos, x, y;  // s, m; empty: no positions
    };

    struct Result {
        Annotations scrums;       // label "scrum", confidence from the margin over the threshold
        std::vector<double> t;    // the grid
        std::vector<double> top;  // rad, mean of the top-k pitches on the grid
    };

    static Expected<Result> detect(const std::vector<Player>& players, const Params& params);
};

}  // namespace athlos::activity
