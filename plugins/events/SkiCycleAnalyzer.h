#pragma once
// Ski cycles from a ski-mounted IMU (Fasel 2017 ch. 3 and 4; spec §2, §8): motionless phases,
// ski inclination from the medio-lateral gyroscope re-anchored to the accelerometer's static
// inclination in each motionless phase, gravity removed, forward acceleration integrated to speed
// with the drift (the mean velocity on the central 50 % of each phase) removed between phases,
// then phases refined where the speed (and, cross-country, the inertial acceleration) is below
// small thresholds, and cycles from one thrust start to the next.
//
// Candidate phases: cross-country, where the gyroscope norm and |‖a‖ − g| are small (the ski stands
// still during the thrust); ski mountaineering, at the local minima of the speed integrated without
// resets ("drifting speed", Fasel 2017 ch. 4), which needs the ski still at the start of the recording.
#include <cstddef>
#include <vector>

namespace athlos::events {

// A ski IMU in the ski frame (forward, left, up): accelerometer in m/s², left gyroscope in rad/s.
struct SkiImu {
    std::vector<double> t;
    std::vector<double> accForward, accLeft, accUp;
    std::vector<double> gyrLeft, gyrNorm;
    std::size_t size() const { return t.size(); }
};

struct SkiPhase {
    std::size_t begin = 0, end = 0;  // samples [begin, end)
};

struct SkiCycle {
    double thrustStart = 0, thrustEnd = 0, glideStart = 0, end = 0;  // s
    double duration = 0;                                             // s
    double length = 0;                                               // m travelled (∫ |v| dt)
    double speed = 0;                                                // m/s, length / duration
    double elevation = 0;                                            // m, ∫ v_z dt
    double slope = 0;                                                // rad, atan2(Δz, Δx)
    double maxSpeed = 0;                                             // m/s
};

struct SkiCycleParams {
    enum class Mode { CrossCountry, Mountaineering };
    Mode mode = Mode::CrossCountry;
    double stillGyro = 0.2;     // rad/s: gyroscope norm of a still ski (XC candidates)
    double stillAcc = 1.0;      // m/s²: |‖a‖ − g| of a still ski (XC candidates)
    double minStill = 0.08;     // s: shortest candidate phase
    double zeroSpeed = 0.1;     // m/s: refined phase (Fasel 2017 ch. 4: speed < 0.1 m/s)
    double zeroAcc = 1.0;       // m/s²: refined XC phase, inertial acceleration below
    double minCycle = 0.6;      // s
    double maxCycle = 3.0;      // s: longer gaps between thrusts are not cycles
    double maxThrust = 1.0;     // s: a longer phase is a rest, not a thrust
    double initialStill = 0.5;  // s: still at the start (mountaineering first pass)
    double gravity = 9.81;      // m/s²
};

struct SkiCycleResult {
    std::vector<SkiPhase> phases;  // refined, all (rests included)
    std::vector<SkiCycle> cycles;
    std::vector<double> speed, vx, vz, inclination;  // per sample; inclination nose-up positive (rad)
};

class SkiCycleAnalyzer {
public:
    explicit SkiCycleAnalyzer(SkiCycleParams params) : p_(params) {}
    // Empty cycles when nothing was found; the caller refuses that with the reason.
    SkiCycleResult analyze(const SkiImu& imu) const;

    std::vector<SkiPhase> stillPhases(const SkiImu& imu) const;
    std::vector<SkiPhase> speedMinimumPhases(const SkiImu& imu) const;
    // Inclination and drift-corrected velocity with the given phases as anchors.
    void integrate(const SkiImu& imu, const std::vector<SkiPhase>& phases, SkiCycleResult& out) const;
    std::vector<SkiPhase> refine(const SkiImu& imu, const std::vector<SkiPhase>& phases, const SkiCycleResult& r) const;

private:
    SkiCycleParams p_;
};

}  // namespace athlos::events
