#pragma once
// The swing search of the gait processors. gait-events (GaitEventParams) and gait-parameters
// (StrideSegmentationParams) find a stride by its mid-swing peak of the medio-lateral angular velocity
// and search toe-off before it and initial contact after it in the same windows, so they declare and
// read these five parameters here: swing_threshold, min_stride, max_stride, tc_window, ic_window.
#include "core/processing/Processor.h"

namespace athlos::events {

struct SwingSearch {
    double swingThreshold = 0.0;  // rad/s: minimum mid-swing ω_ml
    double minStrideTime = 0.0;   // s: closer swing peaks are one swing
    double maxStrideTime = 0.0;   // s: longer intervals are gaps (what that means: maxStrideHelp)
    double tcWindow = 0.0;        // s before the swing peak searched for toe-off
    double icWindow = 0.0;        // s after the swing peak searched for initial contact

    // The five fields of either processor's parameters, by name.
    template <class Params>
    static SwingSearch of(const Params& p) {
        return {p.swingThreshold, p.minStrideTime, p.maxStrideTime, p.tcWindow, p.icWindow};
    }
    template <class Params>
    void applyTo(Params& p) const {
        p.swingThreshold = swingThreshold;
        p.minStrideTime = minStrideTime;
        p.maxStrideTime = maxStrideTime;
        p.tcWindow = tcWindow;
        p.icWindow = icWindow;
    }
};

// The declarations, defaults from `d`; max_stride's help is the processor's (what a longer gap does).
ParameterSpecs swingSearchParameters(const SwingSearch& d, const QString& maxStrideHelp);

// The values of a run; an error naming max_stride when it is not longer than min_stride.
Expected<SwingSearch> readSwingSearch(const RunContext& c);

}  // namespace athlos::events
