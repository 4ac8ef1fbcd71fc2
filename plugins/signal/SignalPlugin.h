#pragma once
// The `signal` processor family: resample and butterworth.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::signal {

class SignalPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "signal.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::signal
