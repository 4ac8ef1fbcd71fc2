#pragma once
// The Qt plugin entry point of the `example` family. Its metadata (example.json) lists the ids of
// the processors processors() returns; the registry refuses a plugin where the two differ.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace example {

class ExamplePlugin : public QObject, public athlos::ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "example.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const athlos::Processor>> processors() const override;
};

}  // namespace example
