#pragma once
// The `positioning` processor family: position-filter and simulate-track-run.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::positioning {

class PositioningPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "positioning.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::positioning
