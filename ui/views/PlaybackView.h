#pragma once
// Team playback: every position stream of a recording (one per athlete) on a drawn venue, moving
// with the window's time cursor (TimeController), with trails of the last N seconds coloured by
// speed. The venue (football, rugby, 400 m track, rectangle, none) defaults to the project's pitch
// (a pitch placed from its corners, `athlos venue`), else a guess from the streams' "venue"
// attribute, the project's sport or the data extent; a choice is stored in the recording's
// metadata ("venue") and so persists with the project. With a pitch, the view shows the pitch frame
// (centre spot at the origin, x along the length): the pitch is drawn with its real length and
// width, and positions in the project's ENU frame (GNSS) are moved into the pitch frame. Tool "View → Team playback…" (a dock) and
// screenshot views "playback" and "team"; the built-in "trajectory" screenshot shows "team" when
// the project has a team.
#include "core/geometry/PitchGeometry.h"
#include "core/util/Expected.h"
#include "ui/venue/VenueDrawing.h"

#include <QPointer>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace athlos {
class Project;
}

namespace athlos::ui {

class PlaybackCanvas;
class TimeController;
class Workspace;

class PlaybackView : public QWidget {
    Q_OBJECT

public:
    static constexpr const char* kVenueKey = "venue";

    explicit PlaybackView(Project* project, QWidget* parent = nullptr);

    // Follows this controller's cursor (nullptr: stays where it is).
    void setTimeController(TimeController* controller);
    // Told after the view changed the project (venue stored), to refresh the window.
    void setWorkspace(Workspace* workspace) { workspace_ = workspace; }

    Status setRecording(const QString& recording);
    QString recording() const;
    void setVenue(VenueDrawing::Venue venue);
    VenueDrawing::Venue venue() const;
    void setTrailSeconds(double seconds);
    double trailSeconds() const;

    PlaybackCanvas* canvas() const { return canvas_; }
    QComboBox* venueCombo() const { return venueCombo_; }
    QDoubleSpinBox* trailSpin() const { return trailSpin_; }

    // The venue a recording is drawn on: its stored choice, else the guess (from the streams' venue
    // attribute, the recording's sport, the data extent — given, or read — and the project's sport).
    static VenueDrawing::Venue venueFor(const Project& project, const QString& recording,
                                        const QRectF* extent = nullptr);
    // Shows the playback of a recording as the current tab of the window, cursor in the middle of
    // the recording (screenshots).
    static Status showInWindow(Workspace& workspace, const QString& recording);

private:
    void onVenueChosen();
    void applyVenue(VenueDrawing::Venue venue);
    void refreshRecordings();

    Project* project_;
    std::optional<PitchGeometry> pitch_;  // the project's pitch, if one was placed
    QPointer<TimeController> time_;
    Workspace* workspace_ = nullptr;
    QComboBox* recordingCombo_ = nullptr;
    QComboBox* venueCombo_ = nullptr;
    QDoubleSpinBox* trailSpin_ = nullptr;
    QLabel* info_ = nullptr;
    PlaybackCanvas* canvas_ = nullptr;
    bool loading_ = false;
};

}  // namespace athlos::ui
