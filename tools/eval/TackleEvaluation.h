#pragma once
// Tackle classification with and without the multi-athlete interaction features (seed 000 §5.1;
// digest §7) on simulated rugby sevens matches (RugbySimulator.h): tackle candidates from the
// 1 Hz low-pass acceleration-norm detector of every player (threshold fitted on the training
// matches so that every tackle there is found), 4 s windows centred on them, a random forest
// trained on the training matches and tested on the others (different matches, players and
// mountings): IMU features only, IMU + interaction features (InteractionFeatures.h), and the
// interaction features alone. A candidate is a tackle when its player is the carrier or the
// tackler of a true tackle less than 1 s away.
#include <QString>
#include <vector>

namespace athlos::activity {

struct TackleComparison {
    struct Row {
        QString features;
        int featureCount = 0;
        double sensitivity = 0.0, specificity = 0.0, balancedAccuracy = 0.0;
    };
    double threshold = 0.0;  // m/s², fitted on the training matches
    int trainCandidates = 0, trainTackles = 0;
    int testPlayerTackles = 0;  // (player, tackle) pairs in the test matches: two per tackle
    int testFound = 0;          // of them with a candidate
    int testCandidates = 0, testPositives = 0;
    std::vector<Row> rows;
};

TackleComparison compareTackleFeatures(int trainMatches, int testMatches, double duration = 600.0, int trees = 100);

}  // namespace athlos::activity
