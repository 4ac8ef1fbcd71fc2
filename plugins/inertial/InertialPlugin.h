#pragma once
// The `inertial` processor family: orientation, imu-calibration, gnss-imu, simulate-imu-gnss.
#include "core/processing/ProcessorPlugin.h"

#include <QObject>

namespace athlos::inertial {

class InertialPlugin : public QObject, public ProcessorPlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID AthlosProcessorPlugin_iid FILE "inertial.json")
    Q_INTERFACES(athlos::ProcessorPlugin)

public:
    std::vector<std::shared_ptr<const Processor>> processors() const override;
};

}  // namespace athlos::inertial
