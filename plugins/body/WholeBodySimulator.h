#pragma once
// Whole-body truth on top of the eight-segment BodySimulator (issue #18 item 5): head and arms riding on the
// thorax with a small swing (arms: shoulder flexion 20° ± 12°, elbow 60° ± 8°, abduction ± 4°; head nod ± 6°),
// the TRUE centre of mass from the anthropometric table, and a helmet antenna position stream with GNSS-like
// noise (white + a slowly varying offset, spec §10's 50 Hz dGNSS with ≈ 0.04 m error by default).
//
// The truth is computed here from the simulator's own joint centres (hips, knees, ankles, lumbar joint) and
// true segment orientations, not through BodyCom, so a wrong chain in BodyCom shows as an error.
//
// Upper-body IMUs (issue #17 item 4): head, upper back (T2–C7, on the thorax; Fasel §6.2.3), upper arms and
// forearms (wrists; Fasel §7.2.2), each off the joint axes with a misaligned mount, with BodySimulator's
// IMU construction and error model (inertial::ImuErrorSource; their own random stream, so the body's
// sensors and the GNSS noise stay as they were). With `calibrationPosture` the head and arms follow the
// functional protocol (spec §4) instead of swinging from the start: still, arms hanging, in the upright;
// head flexion in the squats (Fasel Table 6.2: "knee, hip, trunk, head flexion"); head and arms turning
// with the trunk in its rotations; and in the optional arm-swing block (BodySimulatorParams::armSwings)
// the grip of a horizontal pole with both thumbs pointing medially (the forearms pronated by 90° from the
// upright's palms-on-the-thighs), sagittal swings with straight elbows, and the release (Fasel §7.2.2).
// The forearm's anatomical frame is the one of the upright posture (X anterior, Y along the forearm,
// Z to the right, as the other segments), so the 90° pronation turns the swing axis onto its X.
#include "plugins/body/Anthropometry.h"
#include "plugins/inertial/BodySimulator.h"

#include <vector>

namespace athlos::body {

struct WholeBodyParams {
    inertial::BodySimulatorParams body;
    BspTable table = BspTable::Dumas2007;
    Sex sex = Sex::Male;
    double height = 1.78;  // m (the simulator's thigh 0.42 m and shank 0.40 m fit a 1.75–1.80 m athlete)
    double mass = 75.0;    // kg
    std::array<double, kSegments> equipment{};  // kg per segment
    double shoulderFlexion = 20.0 * 0.017453292519943295, shoulderSwing = 12.0 * 0.017453292519943295;
    double elbowFlexion = 60.0 * 0.017453292519943295, elbowSwing = 8.0 * 0.017453292519943295;
    double abductionSwing = 4.0 * 0.017453292519943295, headNod = 6.0 * 0.017453292519943295;
    double swingFrequency = 0.8;                // Hz
    Vec3 antennaOffset = Vec3(0.0, 0.03, 0.0);  // helmet antenna: above the head vertex, head coordinates (m)
    double gnssRate = 50.0;                     // Hz
    double gnssNoise = 0.02;                    // m, white, per axis
    double gnssWander = 0.03;                   // m, amplitude of the slowly varying offset per axis
    // The functional-calibration posture of head and arms before the motion (header); off: the arms swing
    // and the head nods from the start. The motion's swing fades in over 2 s after the motion begins.
    bool calibrationPosture = false;
    double headSquatFlexion = 20.0 * 0.017453292519943295;   // rad of neck flexion at the deepest squat
    double armSwingAmplitude = 90.0 * 0.017453292519943295;  // rad of shoulder flexion (the pole to shoulder height)
    double armSwingAbduction = 2.0 * 0.017453292519943295;   // rad, abduction coupled with the swing
};

// The upper-body sensors (header).
enum class UpperSensor { Head = 0, UpperBack, RightUpperArm, RightForearm, LeftUpperArm, LeftForearm };
inline constexpr int kUpperSensors = 6;
// "head", "upper-back", "right-upper-arm", "right-forearm", "left-upper-arm", "left-forearm" (the segment
// names of Anthropometry.h and the functional calibration; the upper back is a sensor on the thorax).
QString upperSensorName(UpperSensor sensor);
// The model segment a sensor sits on (Thorax for the upper back).
Segment upperSensorSegment(UpperSensor sensor);

struct WholeBodySimulation {
    inertial::BodySimulation body;
    Anthropometry geometry;
    std::array<double, kSegments> mass{};              // kg, equipment included
    std::vector<std::array<Quat, kSegments>> segment;  // all 15 segment orientations (segment → ENU)
    std::vector<Vec3> lumbar;                          // true lumbar joint centre, ENU (m)
    std::vector<Vec3> com;                             // true CoM relative to the lumbar joint centre, ENU axes (m)
    std::vector<Vec3> antenna;                         // true antenna position, ENU (m)
    std::vector<double> gnssT;                         // antenna stream
    std::vector<Vec3> gnss;                            // measured antenna position, ENU (m)
    // Upper-body IMUs on body.t: mount (truth), acc/gyr, true sensor and segment orientations, position.
    std::array<inertial::BodySensor, kUpperSensors> sensors;
    const inertial::BodySensor& operator[](UpperSensor s) const { return sensors[static_cast<int>(s)]; }
};

WholeBodySimulation simulateWholeBody(const WholeBodyParams& params);

}  // namespace athlos::body
