#include "plugins/signal/SignalPlugin.h"

#include "plugins/signal/ButterworthProcessor.h"
#include "plugins/signal/ResampleProcessor.h"

namespace athlos::signal {

std::vector<std::shared_ptr<const Processor>> SignalPlugin::processors() const {
    return {std::make_shared<ResampleProcessor>(), std::make_shared<ButterworthProcessor>()};
}

}  // namespace athlos::signal
