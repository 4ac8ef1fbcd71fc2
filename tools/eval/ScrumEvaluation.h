#pragma once
// Scrum detection on the simulated rugby sevens match (RugbySimulator.h) scored against its truth:
// torso pitch of every player from its upper-back accelerometer (TorsoPitch, reference from the
// standing period at the start) against the true pitch, then the top-6 scrum detector
// (ScrumDetector) against the true scrums. Shared by athlos-eval-scrums and the validation test.
#include "plugins/activity/RugbySimulator.h"
#include "plugins/activity/ScrumDetector.h"
#include "plugins/activity/TorsoPitch.h"

namespace athlos::activity {

struct ScrumScore {
    int scrums = 0;                 // true scrums
    int found = 0;                  // true scrums overlapped by a detection
    int detections = 0;             // detections
    int correct = 0;                // detections that overlap a true scrum
    double pitchRmse = 0.0;         // rad, torso pitch of all players (rows after the standing period)
    double pitchRmseRunning = 0.0;  // rad, the same outside scrums and tackles
    double minTopInScrum = 0.0;     // rad, smallest top-6 mean in the middle of a true scrum
    double maxTopOutside = 0.0;     // rad, largest top-6 mean more than 2 s away from every scrum
    double startError = 0.0;        // s, mean |detected − true start| of the found scrums
    double endError = 0.0;          // s, the same for the ends
};

ScrumScore evaluateScrums(const RugbySimulator::Result& sim, const TorsoPitch::Params& pitch,
                          const ScrumDetector::Params& detector);

}  // namespace athlos::activity
