#pragma once
// The `metrics` processor family: session-metrics (the coach's metrics per period).
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::metrics {

class MetricsPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "metrics.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::metrics
