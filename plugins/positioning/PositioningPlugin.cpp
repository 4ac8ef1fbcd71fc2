#include "plugins/positioning/PositioningPlugin.h"

#include "plugins/positioning/NoiseProfileProcessor.h"
#include "plugins/positioning/PositionFilterProcessor.h"
#include "plugins/positioning/SimulateTrackRunProcessor.h"
#include "plugins/positioning/AnchorSmootherProcessor.h"
#include "plugins/positioning/SimulateGatesProcessor.h"
#include "plugins/positioning/AnchorGateAverageProcessor.h"

namespace athlos::positioning {

std::vector<std::shared_ptr<const Processor>> PositioningPlugin::processors() const {
    return {std::make_shared<PositionFilterProcessor>(), std::make_shared<SimulateTrackRunProcessor>(),
            std::make_shared<NoiseProfileProcessor>(),   std::make_shared<AnchorSmootherProcessor>(),
            std::make_shared<SimulateGatesProcessor>(),  std::make_shared<AnchorGateAverageProcessor>()};
}

}  // namespace athlos::positioning
