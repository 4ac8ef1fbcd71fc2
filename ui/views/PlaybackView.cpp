#include "ui/views/PlaybackView.h"

#include "core/model/Project.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"
#include "ui/views/PlaybackCanvas.h"
#include "ui/views/PlaybackTracks.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace athlos::ui {

namespace {

QString trView(const char* text) { return QCoreApplication::translate("athlos::ui::PlaybackView", text); }

std::optional<VenueDrawing::Venue> venueOfSport(const QString& sport) {
    const QString s = sport.toLower();
    if (s.contains(QLatin1String("football")) || s.contains(QLatin1String("soccer")))
        return VenueDrawing::Venue::Football;
    if (s.contains(QLatin1String("rugby"))) return VenueDrawing::Venue::Rugby;
    if (s.contains(QLatin1String("athletics")) || s.contains(QLatin1String("track"))) return VenueDrawing::Venue::Track;
    return std::nullopt;
}

}  // namespace

PlaybackView::PlaybackView(Project* project, QWidget* parent) : QWidget(parent), project_(project) {
    recordingCombo_ = new QComboBox(this);
    recordingCombo_->setObjectName(QStringLiteral("recordingCombo"));
    venueCombo_ = new QComboBox(this);
    venueCombo_->setObjectName(QStringLiteral("venueCombo"));
    for (const QString& id : VenueDrawing::ids())
        venueCombo_->addItem(VenueDrawing::displayName(*VenueDrawing::fromId(id)), id);
    trailSpin_ = new QDoubleSpinBox(this);
    trailSpin_->setObjectName(QStringLiteral("trailSpin"));
    trailSpin_->setRange(0.0, 600.0);
    trailSpin_->setDecimals(0);
    trailSpin_->setSingleStep(5.0);
    trailSpin_->setSuffix(tr(" s"));
    trailSpin_->setValue(10.0);
    auto* fit = new QToolButton(this);
    fit->setText(tr("Fit"));
    fit->setToolTip(tr("Frame the venue again (or double-click the view)."));
    info_ = new QLabel(this);
    canvas_ = new PlaybackCanvas(this);
    canvas_->setObjectName(QStringLiteral("playbackCanvas"));
    canvas_->setTrailSeconds(trailSpin_->value());

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Recording:"), this));
    controls->addWidget(recordingCombo_);
    controls->addWidget(new QLabel(tr("Venue:"), this));
    controls->addWidget(venueCombo_);
    controls->addWidget(new QLabel(tr("Trail:"), this));
    controls->addWidget(trailSpin_);
    controls->addWidget(fit);
    controls->addWidget(info_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(canvas_, 1);

    refreshRecordings();
    connect(recordingCombo_, &QComboBox::currentTextChanged, this, [this](const QString& rec) {
        if (loading_ || rec.isEmpty()) return;
        if (Status status = setRecording(rec); !status) info_->setText(status.message());
    });
    connect(venueCombo_, &QComboBox::currentIndexChanged, this, &PlaybackView::onVenueChosen);
    connect(trailSpin_, &QDoubleSpinBox::valueChanged, canvas_, &PlaybackCanvas::setTrailSeconds);
    connect(fit, &QToolButton::clicked, canvas_, &PlaybackCanvas::frameAll);
}

void PlaybackView::refreshRecordings() {
    loading_ = true;
    recordingCombo_->clear();
    if (project_)
        for (const QString& name : project_->recordingNames())
            if (!PlaybackTracks::positionStreams(*project_, name).isEmpty()) recordingCombo_->addItem(name);
    loading_ = false;
}

void PlaybackView::setTimeController(TimeController* controller) {
    if (time_) disconnect(time_, nullptr, canvas_, nullptr);
    time_ = controller;
    if (!time_) return;
    connect(time_, &TimeController::cursorChanged, canvas_, &PlaybackCanvas::setTime);
    canvas_->setTime(time_->cursor());
}

Status PlaybackView::setRecording(const QString& recording) {
    if (!project_ || !project_->recording(recording))
        return makeError(tr("no recording '%1' in this project").arg(recording));
    pitch_ = PitchGeometry::firstOf(project_->geometry());
    auto tracks = std::make_shared<std::vector<AthleteTrack>>(
        PlaybackTracks::readRecording(*project_, recording, pitch_ ? &*pitch_ : nullptr));
    if (tracks->empty())
        return makeError(
            tr("recording '%1' has no position stream (lps-position, trajectory or gnss with x, y)").arg(recording));
    loading_ = true;
    recordingCombo_->setCurrentText(recording);
    const QRectF extent = PlaybackTracks::extent(*tracks);
    const VenueDrawing::Venue venue = venueFor(*project_, recording, &extent);
    venueCombo_->setCurrentIndex(venueCombo_->findData(VenueDrawing::id(venue)));
    loading_ = false;
    double begin = tracks->front().t.empty() ? 0 : tracks->front().t.front(), end = begin;
    for (const AthleteTrack& tr : *tracks)
        if (!tr.t.empty()) begin = std::min(begin, tr.t.front()), end = std::max(end, tr.t.back());
    // The surveyed pitch is named with its real size in the venue list (its kind's standard entry).
    for (int i = 0; i < venueCombo_->count(); ++i) {
        const auto v = VenueDrawing::fromId(venueCombo_->itemData(i).toString());
        if (!v) continue;
        const bool surveyed = pitch_ && VenueDrawing::ofPitch(pitch_->kind()) == *v;
        venueCombo_->setItemText(i, surveyed ? tr("Pitch '%1' %2 × %3 m")
                                                   .arg(pitch_->name())
                                                   .arg(pitch_->length(), 0, 'f', 1)
                                                   .arg(pitch_->width(), 0, 'f', 1)
                                             : VenueDrawing::displayName(*v));
    }
    info_->setText(tr("%n athlete(s)", nullptr, int(tracks->size())));
    applyVenue(venue);
    canvas_->setTracks(std::move(tracks));
    canvas_->frameAll();
    // The cursor can only reach the recording if the window's time range covers it: plot one of its
    // streams then (the window takes its time range from the plotted stream).
    if (workspace_ && time_ && (time_->end() < begin || time_->begin() > end))
        workspace_->showItem(PlaybackTracks::positionStreams(*project_, recording).front());
    return {};
}

QString PlaybackView::recording() const { return recordingCombo_->currentText(); }

void PlaybackView::setVenue(VenueDrawing::Venue venue) {
    venueCombo_->setCurrentIndex(venueCombo_->findData(VenueDrawing::id(venue)));
}

VenueDrawing::Venue PlaybackView::venue() const { return canvas_->venue(); }

void PlaybackView::setTrailSeconds(double seconds) { trailSpin_->setValue(seconds); }

double PlaybackView::trailSeconds() const { return canvas_->trailSeconds(); }

void PlaybackView::onVenueChosen() {
    const auto venue = VenueDrawing::fromId(venueCombo_->currentData().toString());
    if (!venue) return;
    applyVenue(*venue);
    canvas_->frameAll();
    if (loading_ || !project_) return;
    // A choice of the user is kept with the recording.
    Recording* rec = project_->recording(recording());
    if (!rec || rec->metadata.value(QLatin1String(kVenueKey)).toString() == VenueDrawing::id(*venue)) return;
    rec->metadata[QLatin1String(kVenueKey)] = VenueDrawing::id(*venue);
    project_->setModified();
    if (workspace_) workspace_->projectModified();
}

void PlaybackView::applyVenue(VenueDrawing::Venue venue) {
    // The surveyed pitch has its real size when it is the venue shown.
    const bool real = pitch_ && VenueDrawing::ofPitch(pitch_->kind()) == venue;
    canvas_->setVenue(venue);
    canvas_->setVenueSize(real ? VenueDrawing::Size{pitch_->length(), pitch_->width()} : VenueDrawing::Size{});
}

VenueDrawing::Venue PlaybackView::venueFor(const Project& project, const QString& recording, const QRectF* extent) {
    const Recording* rec = project.recording(recording);
    if (!rec) return VenueDrawing::Venue::None;
    if (auto stored = VenueDrawing::fromId(rec->metadata.value(QLatin1String(kVenueKey)).toString())) return *stored;
    // A pitch placed from its corners is where the project's sessions are.
    if (const auto pitch = PitchGeometry::firstOf(project.geometry())) return VenueDrawing::ofPitch(pitch->kind());
    // The streams' own word (a simulator or an import that knows the venue), by majority.
    std::map<QString, int> votes;
    for (const QString& path : PlaybackTracks::positionStreams(project, recording))
        if (const QString v = project.stream(path)->info().attributes.value(QLatin1String(kVenueKey)).toString();
            !v.isEmpty())
            ++votes[v];
    const auto top =
        std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    if (top != votes.end())
        if (auto v = VenueDrawing::fromId(top->first)) return *v;
    if (auto v = venueOfSport(rec->metadata.value(QStringLiteral("sport")).toString())) return *v;
    // The data extent; the project's sport (it may hold several kinds of session) only if that says nothing.
    const auto guessed = VenueDrawing::guess(
        extent ? *extent : PlaybackTracks::extent(PlaybackTracks::readRecording(project, recording)));
    if (guessed != VenueDrawing::Venue::None) return guessed;
    return venueOfSport(project.meta().sport).value_or(VenueDrawing::Venue::None);
}

Status PlaybackView::showInWindow(Workspace& workspace, const QString& recording) {
    Project* project = workspace.project();
    const QStringList streams = project ? PlaybackTracks::positionStreams(*project, recording) : QStringList();
    if (streams.isEmpty())
        return makeError(
            trView("no position stream (lps-position, trajectory or gnss with x, y) in recording '%1'").arg(recording));
    // The window's time range comes from the plotted stream.
    workspace.selectItem(streams.front());
    workspace.waitForPlots();
    auto* view = new PlaybackView(project);
    if (Status status = view->setRecording(recording); !status) {
        delete view;
        return status;
    }
    view->setTimeController(workspace.timeController());
    workspace.addView(view, trView("Playback"));
    TimeController* time = workspace.timeController();
    time->setCursor(time->begin() + 0.5 * (time->end() - time->begin()));
    QCoreApplication::processEvents();
    view->canvas()->frameAll();
    return {};
}

namespace {

void launchPlayback(Workspace& workspace) {
    Project* project = workspace.project();
    if (!project) return;
    const QString title = trView("Team playback");
    if (auto* existing = workspace.window()->findChild<QDockWidget*>(QStringLiteral("playbackDock"))) {
        existing->show();
        existing->raise();
        return;
    }
    const QString recording = PlaybackTracks::teamRecording(*project, 0);
    if (recording.isEmpty()) {
        QMessageBox::information(
            workspace.window(), title,
            trView("This project has no position streams (lps-position, trajectory or gnss with x, y)."));
        return;
    }
    auto* dock = new QDockWidget(title);
    dock->setObjectName(QStringLiteral("playbackDock"));
    dock->setAttribute(Qt::WA_DeleteOnClose);
    auto* view = new PlaybackView(project, dock);
    view->setWorkspace(&workspace);
    view->setTimeController(workspace.timeController());
    dock->setWidget(view);
    workspace.addDock(dock, Qt::RightDockWidgetArea);
    if (Status status = view->setRecording(recording); !status) {
        QMessageBox::warning(workspace.window(), title, status.message());
        dock->close();
        return;
    }
    // The view reads the project it was opened on: close it when the window swaps projects (the
    // signal also comes after changes of the same project, e.g. the venue stored by this view).
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, [dock, &workspace, project] {
        if (workspace.project() != project) dock->close();
    });
}

Status preparePlaybackView(Workspace& workspace) {
    const QString recording = workspace.project() ? PlaybackTracks::teamRecording(*workspace.project(), 0) : QString();
    if (recording.isEmpty())
        return makeError(
            trView("no position stream (lps-position, trajectory or gnss with x, y) in this project; "
                   "run simulate-team or import positions first"));
    return PlaybackView::showInWindow(workspace, recording);
}

// A team: a recording with the position streams of two or more athletes. The built-in screenshot
// `trajectory` shows it through this view when the project has one.
bool hasTeam(const Project& project) { return !PlaybackTracks::teamRecording(project, 2).isEmpty(); }

Status prepareTeamView(Workspace& workspace) {
    const QString team = workspace.project() ? PlaybackTracks::teamRecording(*workspace.project(), 2) : QString();
    if (team.isEmpty())
        return makeError(
            trView("no team in this project (a recording with the position streams of two or more "
                   "athletes); run simulate-team first"));
    return PlaybackView::showInWindow(workspace, team);
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("team-playback"), QT_TRANSLATE_NOOP("Tools", "Team playback…"),
                      QT_TRANSLATE_NOOP("Tools", "View"), launchPlayback});
ATHLOS_REGISTER_VIEW({QStringLiteral("playback"), preparePlaybackView});
ATHLOS_REGISTER_VIEW({QStringLiteral("team"), prepareTeamView, hasTeam});

}  // namespace athlos::ui
