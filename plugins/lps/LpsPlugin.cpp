#include "plugins/lps/LpsPlugin.h"

#include "plugins/lps/LpsAlignProcessor.h"
#include "plugins/lps/LpsCalibrationProcessor.h"
#include "plugins/lps/LpsPositioningProcessor.h"
#include "plugins/lps/SimulateLpsProcessor.h"

namespace athlos::lps {

std::vector<std::shared_ptr<const Processor>> LpsPlugin::processors() const {
    return {std::make_shared<LpsPositioningProcessor>(), std::make_shared<LpsCalibrationProcessor>(),
            std::make_shared<LpsAlignProcessor>(), std::make_shared<SimulateLpsProcessor>()};
}

}  // namespace athlos::lps
