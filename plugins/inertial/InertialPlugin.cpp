#include "plugins/inertial/InertialPlugin.h"

#include "plugins/inertial/DriftReductionProcessor.h"
#include "plugins/inertial/FunctionalCalibrationProcessor.h"
#include "plugins/inertial/GnssImuProcessor.h"
#include "plugins/inertial/ImuCalibrationProcessor.h"
#include "plugins/inertial/JointAnglesProcessor.h"
#include "plugins/inertial/OrientationProcessor.h"
#include "plugins/inertial/SegmentCalibrationProcessor.h"
#include "plugins/inertial/SimulateBodyProcessor.h"
#include "plugins/inertial/SimulateImuGnssProcessor.h"
#include "plugins/inertial/SimulateLimbProcessor.h"
#include "plugins/inertial/VelocityResetProcessor.h"

namespace athlos::inertial {

std::vector<std::shared_ptr<const Processor>> InertialPlugin::processors() const {
    return {std::make_shared<OrientationProcessor>(),
            std::make_shared<ImuCalibrationProcessor>(),
            std::make_shared<GnssImuProcessor>(),
            std::make_shared<SimulateImuGnssProcessor>(),
            std::make_shared<JointAnglesProcessor>(),
            std::make_shared<SimulateLimbProcessor>(),
            std::make_shared<SegmentCalibrationProcessor>(),
            std::make_shared<SimulateBodyProcessor>(),
            std::make_shared<DriftReductionProcessor>(),
            std::make_shared<FunctionalCalibrationProcessor>(),
            std::make_shared<VelocityResetProcessor>()};
}

}  // namespace athlos::inertial
