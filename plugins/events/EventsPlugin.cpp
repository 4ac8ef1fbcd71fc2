#include "plugins/events/EventsPlugin.h"

#include "plugins/events/GaitEventsProcessor.h"
#include "plugins/events/GaitParametersProcessor.h"

namespace athlos::events {

std::vector<std::shared_ptr<const Processor>> EventsPlugin::processors() const {
    return {std::make_shared<GaitEventsProcessor>(), std::make_shared<GaitParametersProcessor>()};
}

}  // namespace athlos::events
