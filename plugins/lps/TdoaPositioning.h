#pragma once
// Positioning of a whole TDoA recording: per instant, beacon selection + fix (BeaconSelection,
// TdoaSolver), warm-started from the previous fix, with the fix history the field-of-view rule needs.
//
// Heading for the field-of-view rule (φ_body in Eqn. 3.8):
//   Track:       running direction of the track at m̂_ini (core/geometry/TrackGeometry, counter-
//                clockwise unless clockwise is set); the LPS frame must be the track's (lps-align).
//   Orientation: a caller-supplied function of time (e.g. yaw of an IMU orientation stream).
//   Motion:      direction of travel over the last fixes (needs no track and no IMU).
#include "core/geometry/TrackGeometry.h"
#include "core/util/Progress.h"
#include "plugins/lps/BeaconSelection.h"
#include "plugins/lps/TdoaScreening.h"

#include <functional>

namespace athlos::lps {

class TdoaPositioning {
public:
    enum class HeadingSource { Track, Orientation, Motion };
    using HeadingFunction = std::function<std::optional<double>(double t)>;

    struct Params {
        TdoaSolver::Params solver;
        BeaconSelection::Params selection;
        TdoaScreening::Params screening;  // whole-recording screening before the fixes (run() only)
        HeadingSource heading = HeadingSource::Track;
        bool clockwise = false;        // running direction on the track
        double maxWarmStartGap = 2.0;  // s; older fixes do not seed the solver or the history
    };

    TdoaPositioning(const Params& params, BeaconLayout layout, TrackGeometry track = {},
                    HeadingFunction orientationHeading = {});

    // One instant. Invalid fixes (fewer than B_min readings, no convergence) come back with valid = false.
    TagFix update(const TdoaEpoch& epoch);
    // Batch over a recording (screened first when params.screening says so); empty optional when cancelled.
    std::optional<std::vector<TagFix>> run(const std::vector<TdoaEpoch>& epochs, const Progress& progress = {});

    // The body view at time t from the history and the heading source, if available.
    std::optional<BeaconSelection::View> view(double t) const;
    void reset();
    // Readings the screening dropped in the last run().
    int screened() const { return screened_; }

private:
    Params params_;
    BeaconLayout layout_;
    TrackGeometry track_;
    HeadingFunction orientationHeading_;
    std::vector<double> referenceDistance_;
    TdoaSolver solver_;
    BeaconSelection selection_;
    // State
    FixInput input_;
    TagFix last_;
    FixHistory history_;
    int screened_ = 0;
};

}  // namespace athlos::lps
