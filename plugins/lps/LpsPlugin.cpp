#include "plugins/lps/LpsPlugin.h"

#include "plugins/lps/AlignProcessor.h"
#include "plugins/lps/CalibrationProcessor.h"
#include "plugins/lps/PositioningProcessor.h"
#include "plugins/lps/SimulateProcessor.h"

namespace athlos::lps {

std::vector<std::shared_ptr<const Processor>> LpsPlugin::processors() const {
    return {std::make_shared<PositioningProcessor>(), std::make_shared<CalibrationProcessor>(),
            std::make_shared<AlignProcessor>(), std::make_shared<SimulateProcessor>()};
}

}  // namespace athlos::lps
