#pragma once
// The `body` processor family: the athlete's body model and the centre of mass (issue #18 items 1–2).
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::body {

class BodyPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "body.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::body
