#include "plugins/team/TeamPlugin.h"

#include "plugins/team/SimulateTeamProcessor.h"

namespace athlos::team {

std::vector<std::shared_ptr<const Processor>> TeamPlugin::processors() const {
    return {std::make_shared<SimulateTeamProcessor>()};
}

}  // namespace athlos::team
