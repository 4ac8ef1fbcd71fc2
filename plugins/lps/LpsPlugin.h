#pragma once
// The `lps` processor family: lps-positioning, lps-calibration, lps-align, simulate-lps.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::lps {

class LpsPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "lps.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::lps
