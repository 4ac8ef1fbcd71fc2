#pragma once
// Simulated discrete actions with ground truth, for the event detectors' tests and the validation
// page (seed 000 §5.1, §5.2; digest §7, §8):
//  - volleyball(): a wrist accelerometer (BMA280-like: ~39 Hz, ±16 g) of one player: the nine
//    actions of the thesis (serves, sets, attacks, block, dig), each a swing (a half-sine burst of
//    class-specific direction, duration and height, with the arm held up, forward or down) ending in
//    the ball contact (a decaying 12 Hz ring-down along the hit direction), jump actions with a
//    take-off push; between them Null motions: walking, arm swings without a hit, claps, landings.
//  - rugby(): an upper-back IMU at 200 Hz of one player: running with steps (2.6–3.2 Hz), sprints and
//    decelerations, hard contacts that are not tackles (the detector's false alarms) and tackles: a
//    0.4–0.8 s collision of 15–30 m/s² followed by the torso pitching towards the ground.
// Player variation: amplitudes, timing, directions and how the sensor sits differ per player.
#include "core/model/Annotation.h"
#include "core/model/StreamData.h"

#include <QStringList>
#include <vector>

namespace athlos::activity {

struct SimulatedEvents {
    StreamData imu;             // t, acc_x..z (m/s²)[, gyr_x..z (rad/s) for rugby]
    Annotations annotations;    // one per action, [t − half, t + half], source "import"
    std::vector<double> times;  // the action instants (ball contact, collision)
};

class EventSimulator {
public:
    static QStringList volleyballActions();
    static SimulatedEvents volleyball(unsigned player, int actions, unsigned seed);
    static QStringList rugbyColumns();  // acc_x..z, gyr_x..z
    static SimulatedEvents rugby(unsigned player, int tackles, unsigned seed);
};

}  // namespace athlos::activity
