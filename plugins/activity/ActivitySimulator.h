#pragma once
// A wrist-worn IMU during continuous activities, with ground truth, for tests and the validation
// page. Several simulated people differ in movement amplitude, cadence, how the sensor sits on the
// wrist (rotation about the forearm and tilt), sensor noise and sampling rate.
//
// Model (world frame z up, sensor x along the forearm towards the hand): the forearm pitches about
// the lateral axis, θ(t) = θ0 + A sin(2π f t) (arm swing at the stride frequency f, Winter's
// pendulum model of arm swing), the wrist moves vertically at the step frequency 2f with an
// activity-specific waveform, the sensor sits at R_mount on the forearm; then
//   acc = R^T (a_world + [0, 0, g]),  gyr = R^T ω,  mag = R^T m_world,   R = Rz(ψ) Ry(θ) R_mount,
// with ψ the heading of the segment and m_world the Earth field (20, 0, −40) µT.
#include "core/model/StreamData.h"

#include <QStringList>
#include <vector>

namespace athlos::activity {

struct SimulatedPerson {
    double amplitude = 1.0;  // scale of movement amplitudes
    double cadence = 1.0;    // scale of step/stride frequencies
    double mountRoll = 0.0;  // rad, rotation of the sensor about the forearm
    double mountTilt = 0.0;  // rad, tilt of the sensor on the wrist
    double accNoise = 0.1;   // m/s² (white, per sample)
    double gyrNoise = 0.02;  // rad/s
    double rate = 50.0;      // Hz
    static SimulatedPerson random(unsigned seed);
};

struct SimulatedRecording {
    StreamData imu;      // t, acc_x..z (m/s²), gyr_x..z (rad/s), mag_x..z (T)
    QStringList labels;  // per sample
};

class ActivitySimulator {
public:
    static QStringList activities();  // walking, running, sitting, standing, stairs_up, stairs_down, cycling
    static QStringList columnNames();
    static QStringList columnUnits();

    // A recording of `segments` activity bouts of 20–60 s (every activity in turn, shuffled, then
    // repeated), seeded.
    static SimulatedRecording simulate(const SimulatedPerson& person, int segments, unsigned seed);
};

}  // namespace athlos::activity
