#pragma once
// The Qt plugin interface a processor family implements (one shared library per plugins/<family>).
#include "core/processing/Processor.h"

#include <QtPlugin>
#include <memory>
#include <vector>

namespace athlos {

class ProcessorPlugin {
public:
    virtual ~ProcessorPlugin() = default;
    virtual std::vector<std::shared_ptr<const Processor>> processors() const = 0;
};

}  // namespace athlos

#define AthlosProcessorPlugin_iid "org.athlos.ProcessorPlugin/1.0"
Q_DECLARE_INTERFACE(athlos::ProcessorPlugin, AthlosProcessorPlugin_iid)
