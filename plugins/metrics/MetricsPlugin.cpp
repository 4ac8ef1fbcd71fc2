#include "plugins/metrics/MetricsPlugin.h"

#include "plugins/metrics/SessionMetricsProcessor.h"

namespace athlos::metrics {

std::vector<std::shared_ptr<const Processor>> MetricsPlugin::processors() const {
    return {std::make_shared<SessionMetricsProcessor>()};
}

}  // namespace athlos::metrics
