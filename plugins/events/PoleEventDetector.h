#pragma once
// Pole plant and pole lift from a pole IMU's acceleration norm (Fasel 2017 ch. 3, Table 3.1):
// a plant is the start of the shock pattern, found as the first sample whose vibration (the
// backward second difference of the norm) exceeds `onsetThreshold` within `onsetWindow` (100 ms)
// before each vibration maximum above `plantThreshold`; a lift is the maximum of the norm between
// `shockSkip` after a plant and the next plant (the sudden velocity increase when the pole leaves
// the snow).
#include <vector>

namespace athlos::events {

struct PoleEvents {
    double plant = 0, lift = 0;  // s
};

struct PoleEventParams {
    double plantThreshold = 10.0;  // m/s²: vibration maximum of a pole plant
    double onsetThreshold = 5.0;   // m/s²: vibration at the start of the shock
    double onsetWindow = 0.1;      // s before the maximum (Fasel 2017: 100 ms)
    double shockSkip = 0.15;       // s after a plant before the lift search
    double minCycle = 0.6;         // s between plants
    double maxContact = 1.5;       // s, longest pole contact
};

// t and the acceleration norm (m/s²) per sample.
std::vector<PoleEvents> detectPoleEvents(const std::vector<double>& t, const std::vector<double>& accNorm,
                                         const PoleEventParams& params);

}  // namespace athlos::events
