#include "ExamplePlugin.h"

#include "ScaleProcessor.h"

namespace example {

std::vector<std::shared_ptr<const athlos::Processor>> ExamplePlugin::processors() const {
    return {std::make_shared<ScaleProcessor>()};
}

}  // namespace example
