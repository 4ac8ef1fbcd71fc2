#pragma once
// Event detectors that cut discrete actions out of a stream before classification (seed 000 §5.1,
// §5.2; digest §7, §8):
//  - ImpactDetector (beach volleyball, wrist accelerometer): 8 Hz high-pass of each axis → L1 norm →
//    3 Hz low-pass → threshold ε_impact = 5.1 m/s² → the next local maximum is the event; its height
//    is the impact indicator, the mean |a| over the 200 ms before it the swing indicator.
//  - TackleDetector (rugby, upper-back IMU): 1 Hz low-pass of each axis → L2 norm → threshold → next
//    local maximum; the threshold is fitted on annotated data so that a target share of the
//    annotated events is detected (the thesis sets it so that every labelled tackle is found).
// Both filters are zero-phase Butterworth (order 2), so the peak is not delayed.
#include "core/model/Annotation.h"
#include "core/model/Stream.h"
#include "core/util/Expected.h"

#include <QStringList>
#include <vector>

namespace athlos::activity {

struct DetectedEvent {
    double t = 0;         // s, time of the peak
    std::size_t row = 0;  // its row in the stream
    double impact = 0;    // detector signal at the peak (m/s²)
    double swing = 0;     // impact detector: mean |a| over the swing window before the peak (m/s²)
};

// The columns acc_x, acc_y, acc_z of a stream (the error names the missing one).
Expected<std::vector<int>> accelerometerColumns(const StreamInfo& info);

class ImpactDetector {
public:
    struct Params {
        double highPass = 8.0;     // Hz, removes gravity and slow arm movement (seed 000 §5.2)
        double lowPass = 3.0;      // Hz, smooths the L1 norm into one hump per impact (§5.2)
        double threshold = 5.1;    // m/s², ε_impact (§5.2)
        double swingWindow = 0.2;  // s before the peak averaged for the swing indicator (§5.2)
    };
    // The low-passed L1 norm of the high-passed acceleration, one value per row.
    static Expected<std::vector<double>> signal(const StreamInfo& info, const StreamData& data, const Params& params);
    static Expected<std::vector<DetectedEvent>> detect(const StreamInfo& info, const StreamData& data,
                                                       const Params& params);
};

class TackleDetector {
public:
    struct Params {
        double lowPass = 1.0;        // Hz (seed 000 §5.1)
        double threshold = 0.0;      // m/s²; 0: not fitted yet
        double targetRecall = 1.0;   // share of annotated events the fitted threshold must reach (§5.1: all)
        double margin = 0.95;        // the fitted threshold is this share of the weakest event kept
        double minSeparation = 1.0;  // s between two candidates (one tackle, one candidate)
    };
    // The low-passed acceleration norm (gravity included), one value per row.
    static Expected<std::vector<double>> signal(const StreamInfo& info, const StreamData& data, const Params& params);
    static Expected<std::vector<DetectedEvent>> detect(const StreamInfo& info, const StreamData& data,
                                                       const Params& params);
    // The threshold that detects `targetRecall` of the annotated events (each: the signal's maximum inside
    // its interval), times the margin. `peaks`: those maxima over all training recordings.
    static Expected<double> fitThreshold(std::vector<double> peaks, const Params& params);
    // The signal's maximum inside each annotation (NaN when the annotation holds no sample).
    static std::vector<double> annotationPeaks(const StreamData& data, const std::vector<double>& signal,
                                               const Annotations& annotations);
};

// Events from a detector signal: each upward crossing of `threshold` → the next local maximum; a new
// crossing counts only after the signal fell below the threshold and at least minSeparation s after
// the previous event.
std::vector<DetectedEvent> peaksAfterCrossings(const StreamData& data, const std::vector<double>& signal,
                                               double threshold, double minSeparation);

// Recall of `events` against annotated intervals: the share of annotations with an event inside
// [tStart − tolerance, tEnd + tolerance].
double eventRecall(const std::vector<DetectedEvent>& events, const Annotations& annotations, double tolerance);

}  // namespace athlos::activity
