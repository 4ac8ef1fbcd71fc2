#pragma once
// The `activity` processor family: activity recognition with classifiers trained in the project
// (classify-actions; training is `athlos train`).
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::activity {

class ActivityPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "activity.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::activity
