#include "plugins/activity/ActivityPlugin.h"

#include "plugins/activity/ClassifyActionsProcessor.h"

namespace athlos::activity {

std::vector<std::shared_ptr<const Processor>> ActivityPlugin::processors() const {
    return {std::make_shared<ClassifyActionsProcessor>()};
}

}  // namespace athlos::activity
