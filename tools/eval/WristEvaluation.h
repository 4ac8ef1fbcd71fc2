#pragma once
// Scoring wrist-cadence and wrist-speed against the wrist-walking simulator's truth (docs/validation/
// wrist-walking.md): shared by athlos-eval-wrist-walking and the events family's tests.
#include "plugins/events/WristCadence.h"
#include "plugins/events/WristSpeedModel.h"
#include "plugins/events/WristWalkSimulator.h"

#include <vector>

namespace athlos::events {

struct WristSubject {
    unsigned seed = 1;
    double height = 1.75;  // m
};

// One simulated walker with the cadence windows and, per window fully inside a walking bout, the
// truth (mean over the window).
struct WristTrial {
    WristSubject subject;
    WristWalkRecording recording;
    std::vector<CadenceWindow> windows;
    std::vector<double> trueCadence;   // steps/min per window; NaN unless the whole window is walking
    std::vector<double> trueSpeed;     // m/s, likewise
    std::vector<char> trueNonWalking;  // 1 when no sample of the window is walking
};

WristTrial simulateWristTrial(const WristSubject& subject, const WristWalkParams& base = {},
                              const WristCadenceParams& cadence = {});

struct ErrorSummary {
    std::size_t n = 0;
    double median = 0.0, q25 = 0.0, q75 = 0.0;  // relative error (%), signed
    double medianAbs = 0.0;                     // median |relative error| (%)
};
ErrorSummary summarize(std::vector<double> relativeErrorsPercent);

struct CadenceScore {
    std::vector<double> errors;  // % per walking window detected as walking
    int walkingDetected = 0, walkingMissed = 0, pauseAsWalking = 0, pauseRejected = 0;
};
void scoreCadence(const WristTrial& trial, CadenceScore& score);

// Training rows (features and window-mean true speed) of the walking windows of the trials.
void speedRows(const std::vector<WristTrial>& trials, std::vector<WristFeatures>& x, std::vector<double>& v,
               std::vector<double>* cadenceTruth = nullptr);

}  // namespace athlos::events
