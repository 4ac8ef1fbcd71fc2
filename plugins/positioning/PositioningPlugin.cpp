#include "plugins/positioning/PositioningPlugin.h"

#include "plugins/positioning/NoiseProfileProcessor.h"
#include "plugins/positioning/PositionFilterProcessor.h"
#include "plugins/positioning/SimulateTrackRunProcessor.h"

namespace athlos::positioning {

std::vector<std::shared_ptr<const Processor>> PositioningPlugin::processors() const {
    return {std::make_shared<PositionFilterProcessor>(), std::make_shared<SimulateTrackRunProcessor>(),
            std::make_shared<NoiseProfileProcessor>()};
}

}  // namespace athlos::positioning
