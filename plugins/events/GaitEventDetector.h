#pragma once
// Gait events from one foot-mounted IMU's gyroscope (Salarian et al. 2004, Rampp et al. 2015):
// the medio-lateral angular velocity ω_ml, signed so that the swing phase is positive, shows one
// large positive peak per stride (mid-swing). Around it:
//  - terminal contact (toe-off, TC): the negative peak of ω_ml before the swing peak (push-off,
//    the foot plantar-flexes fastest as the toes leave the ground);
//  - initial contact (IC): the negative peak of ω_ml after the swing peak (the foot stops rotating
//    forward just before the heel hits the ground);
//  - minimum velocity (mid-stance): the minimum of the smoothed gyroscope norm between IC and the
//    next TC (the foot is flat and still).
// A stride runs from one IC to the next IC of the same foot.
//
// All parameters are in seconds and rad/s, so the detector is independent of the sampling rate.
// update() runs per sample with a fixed delay (events come out once the windows after them have
// been seen); updateBatch() runs a whole recording and flushes.
#include <Eigen/Core>

#include <deque>
#include <utility>
#include <vector>

namespace athlos::events {

enum class GaitEventType { TerminalContact, InitialContact, MinimumVelocity };

struct GaitEvent {
    double t = 0.0;  // s
    GaitEventType type = GaitEventType::InitialContact;
};

struct GaitStride {
    double tStart = 0.0;     // IC (s)
    double tEnd = 0.0;       // next IC (s)
    double tMinVel = 0.0;    // mid-stance after tStart (s)
    double tTc = 0.0;        // toe-off within the stride (s)
    double swingPeak = 0.0;  // ω_ml at mid-swing (rad/s)
    double restGyr = 0.0;    // smoothed gyroscope norm at mid-stance (rad/s)
    double confidence = 0.0;
};

// Parameters of GaitEventDetector (outside the class so that `Params params = {}` works as a
// default argument).
struct GaitEventParams {
    double swingThreshold = 1.5;        // rad/s: minimum mid-swing ω_ml (walking ≈ 4–7, slow gait ≈ 2)
    double minStrideTime = 0.5;         // s: swing peaks closer than this are one swing
    double maxStrideTime = 2.5;         // s: longer IC-to-IC intervals are gaps (stops, turns), no stride
    double tcWindow = 0.4;              // s before the swing peak searched for TC
    double icWindow = 0.35;             // s after the swing peak searched for IC
    double restWindow = 0.1;            // s: moving average of the gyroscope norm for mid-stance
    double restScale = 1.0;             // rad/s: mid-stance norm at which the rest quality is 1/e
    double regularityTolerance = 0.15;  // relative change of stride time that costs 1 σ of quality
};

class GaitEventDetector {
public:
    using Params = GaitEventParams;

    struct State {
        struct Sample {
            double t, w, norm;
        };
        std::deque<Sample> buffer;                         // recent samples (w = signed ω_ml, norm = smoothed |ω|)
        std::deque<std::pair<double, double>> normWindow;  // (t, raw norm) of the last restWindow
        double normSum = 0.0;
        double lastPeakT = -1e300;
        double checkedUntil = -1e300;  // samples up to here were judged as swing peaks
        bool havePreviousIc = false;
        double previousIcT = 0.0;
        double previousStrideTime = 0.0;  // 0: none yet
        std::vector<GaitEvent> events;
        std::vector<GaitStride> strides;
    };

    // swingSign: +1 or −1, the sign of the ML gyroscope axis during swing (see swingSign()).
    explicit GaitEventDetector(Params params = {}, int swingSign = 1);

    // One sample: time (s), ML angular velocity (rad/s) and the gyroscope norm (rad/s).
    void update(double t, double gyrMl, double gyrNorm);
    // Whole recording: gyr points at x,y,z of the first sample, `stride` doubles between samples;
    // ω_ml = mlAxis · ω (a unit vector in the sensor frame, see MediolateralAxis.h). Ends with finish().
    void updateBatch(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                     const Eigen::Vector3d& mlAxis);
    // Evaluates the peaks still waiting for their trailing windows (end of data).
    void finish();

    const std::vector<GaitEvent>& events() const { return state_.events; }
    const std::vector<GaitStride>& strides() const { return state_.strides; }
    const Params& params() const { return params_; }
    const State& state() const { return state_; }
    void reset();

    // The sign of the ML axis during swing: the sign of the larger extreme of ω_ml averaged over
    // 0.25 s (the swing is the longest sustained rotation of a stride; push-off and impact are short).
    static int swingSign(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                         const Eigen::Vector3d& mlAxis);

private:
    void evaluate(bool flushing);
    void confirmPeak(std::size_t peak);
    double delay() const;

    Params params_;
    int sign_;
    State state_;
};

const char* gaitEventName(GaitEventType type);  // "tc", "ic", "min_vel"

}  // namespace athlos::events
