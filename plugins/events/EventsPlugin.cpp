#include "plugins/events/EventsPlugin.h"

#include "plugins/events/GaitEventsProcessor.h"
#include "plugins/events/GaitParametersProcessor.h"
#include "plugins/events/GaitSummaryProcessor.h"
#include "plugins/events/AlpineTurnsProcessor.h"
#include "plugins/events/SimulateSkiingProcessor.h"
#include "plugins/events/SkimoPhasesProcessor.h"
#include "plugins/events/XcSkiingCyclesProcessor.h"
#include "plugins/events/SimulateWristWalkProcessor.h"
#include "plugins/events/WristCadenceProcessor.h"
#include "plugins/events/WristSpeedProcessor.h"

namespace athlos::events {

std::vector<std::shared_ptr<const Processor>> EventsPlugin::processors() const {
    return {std::make_shared<GaitEventsProcessor>(),     std::make_shared<GaitParametersProcessor>(),
            std::make_shared<GaitSummaryProcessor>(),    std::make_shared<XcSkiingCyclesProcessor>(),
            std::make_shared<SkimoPhasesProcessor>(),    std::make_shared<AlpineTurnsProcessor>(),
            std::make_shared<SimulateSkiingProcessor>(), std::make_shared<SimulateWristWalkProcessor>(),
            std::make_shared<WristCadenceProcessor>(),   std::make_shared<WristSpeedTrainProcessor>(),
            std::make_shared<WristSpeedProcessor>()};
}

}  // namespace athlos::events
