#include "plugins/body/BodyPlugin.h"

#include "plugins/body/BodyComProcessor.h"
#include "plugins/body/BodyModelProcessor.h"

namespace athlos::body {

std::vector<std::shared_ptr<const Processor>> BodyPlugin::processors() const {
    return {std::make_shared<BodyModelProcessor>(), std::make_shared<BodyComProcessor>()};
}

}  // namespace athlos::body
