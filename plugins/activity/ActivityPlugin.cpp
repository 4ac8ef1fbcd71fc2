#include "plugins/activity/ActivityPlugin.h"

#include "plugins/activity/ClassifyActionsProcessor.h"
#include "plugins/activity/DetectScrumsProcessor.h"
#include "plugins/activity/SimulateRugbyProcessor.h"

namespace athlos::activity {

std::vector<std::shared_ptr<const Processor>> ActivityPlugin::processors() const {
    return {std::make_shared<ClassifyActionsProcessor>(), std::make_shared<SimulateRugbyProcessor>(),
            std::make_shared<DetectScrumsProcessor>()};
}

}  // namespace athlos::activity
