#pragma once
// Whole-body truth on top of the eight-segment BodySimulator (issue #18 item 5): head and arms riding on the
// thorax with a small swing (arms: shoulder flexion 20° ± 12°, elbow 60° ± 8°, abduction ± 4°; head nod ± 6°),
// the TRUE centre of mass from the anthropometric table, and a helmet antenna position stream with GNSS-like
// noise (white + a slowly varying offset, spec §10's 50 Hz dGNSS with ≈ 0.04 m error by default).
//
// The truth is computed here from the simulator's own joint centres (hips, knees, ankles, lumbar joint) and
// true segment orientations, not through BodyCom, so a wrong chain in BodyCom shows as an error.
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
};

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
};

WholeBodySimulation simulateWholeBody(const WholeBodyParams& params);

}  // namespace athlos::body
