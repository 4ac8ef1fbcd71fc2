#pragma once
// Torso pitch from gravity (seed 000 §5.1.2, Fig. 5.5; digest §7): the angle α between the torso's
// long axis and the vertical, from an upper-back accelerometer. The low-passed acceleration is the
// direction of gravity in the sensor frame (the player's own accelerations average out below the
// cut-off); α is the angle between it and the sensor's upright reference, the gravity direction
// while the player stands upright. That reference corrects the sensor's misalignment on the back
// (the thesis's "sensor alignment correction"); it is taken as the mean low-passed acceleration
// of a standing period (refused when the player was not still there) or given as a sensor axis.
#include "core/model/Stream.h"
#include "core/util/Expected.h"

#include <Eigen/Core>
#include <QString>
#include <vector>

namespace athlos::activity {

class TorsoPitch {
public:
    struct Params {
        double cutoff = 0.5;                   // Hz, low-pass of each axis (zero-phase Butterworth, order 2)
        double referenceStart = 0.0;           // s, the standing period [start, start + duration]
        double referenceDuration = 3.0;        // s; 0: use upAxis instead
        QString upAxis = QStringLiteral("z");  // "x", "-x", "y", "-y", "z", "-z": the sensor axis up when upright
        double stillness = 1.0;                // m/s², largest SD of |a| in the standing period (else refused)
    };

    // The sensor's upright gravity direction (unit vector) from the parameters.
    static Expected<Eigen::Vector3d> reference(const StreamInfo& info, const StreamData& data, const Params& params);
    // Torso pitch (rad, 0 upright, π/2 horizontal) per row of data.
    static Expected<std::vector<double>> compute(const StreamInfo& info, const StreamData& data, const Params& params);
};

}  // namespace athlos::activity
