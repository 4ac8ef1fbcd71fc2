#pragma once
// The `events` processor family: event detectors that write predicted annotations (gait-events).
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::events {

class EventsPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "events.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::events
