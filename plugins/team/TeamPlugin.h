#pragma once
// The `team` processor family: simulate-team.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::team {

class TeamPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "team.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::team
