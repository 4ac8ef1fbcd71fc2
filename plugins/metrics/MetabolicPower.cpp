#include "plugins/metrics/MetabolicPower.h"

#include <cmath>

namespace athlos::metrics {

double energyCost(double forwardAccel, const MetabolicParams& params) {
    const double es = forwardAccel / params.gravity;  // eq. 2
    const double em = std::sqrt(es * es + 1.0);       // eq. 3
    // eq. 4, Horner form of 155.4 ES⁵ − 30.4 ES⁴ − 43.3 ES³ + 46.3 ES² + 19.5 ES + 3.6
    const double cost = ((((155.4 * es - 30.4) * es - 43.3) * es + 46.3) * es + 19.5) * es + 3.6;
    return cost * em * params.terrainFactor;
}

double metabolicPower(double speed, double forwardAccel, const MetabolicParams& params) {
    return energyCost(forwardAccel, params) * speed;  // eq. 5
}

}  // namespace athlos::metrics
