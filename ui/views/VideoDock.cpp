#include "ui/views/VideoDock.h"

#include "core/model/Project.h"
#include "core/video/VideoReader.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"
#include "ui/views/VideoDecodeWorker.h"
#include "ui/views/VideoFrameView.h"
#include "ui/views/VideoOffsetCommand.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QThread>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace athlos::ui {

namespace {

QString formatSeconds(double t) { return QString::number(t, 'f', 3); }

}  // namespace

VideoDock::VideoDock(Workspace& workspace, QWidget* parent) : QDockWidget(tr("Video"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("videoDock"));
    auto* body = new QWidget(this);
    recordingCombo_ = new QComboBox(body);
    recordingCombo_->setObjectName(QStringLiteral("videoRecordingCombo"));
    fileLabel_ = new QLabel(body);
    fileLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    view_ = new VideoFrameView(body);
    positionLabel_ = new QLabel(body);
    positionLabel_->setObjectName(QStringLiteral("videoPositionLabel"));
    auto* back = new QPushButton(tr("◀ Frame"), body);
    back->setToolTip(tr("One video frame back"));
    auto* forward = new QPushButton(tr("Frame ▶"), body);
    forward->setToolTip(tr("One video frame forward"));
    offsetBox_ = new QDoubleSpinBox(body);
    offsetBox_->setObjectName(QStringLiteral("videoOffsetBox"));
    offsetBox_->setDecimals(3);
    offsetBox_->setRange(-1e6, 1e6);
    offsetBox_->setSingleStep(0.001);
    offsetBox_->setSuffix(tr(" s"));
    offsetBox_->setKeyboardTracking(false);
    offsetBox_->setToolTip(tr("Offset of the video: t_recording = t_video + offset"));
    markVideoButton_ = new QPushButton(tr("Mark event in video"), body);
    markVideoButton_->setToolTip(tr("The event (clap, take-off…) is in the frame shown now"));
    markSignalButton_ = new QPushButton(tr("Mark event in signal"), body);
    markSignalButton_->setToolTip(tr("The same event is at the cursor in the signal (e.g. the acceleration spike)"));
    syncLabel_ = new QLabel(body);
    syncLabel_->setWordWrap(true);
    undoStack_ = new QUndoStack(this);
    auto* undo = new QPushButton(tr("Undo"), body);
    auto* redo = new QPushButton(tr("Redo"), body);
    connect(undoStack_, &QUndoStack::canUndoChanged, undo, &QWidget::setEnabled);
    connect(undoStack_, &QUndoStack::canRedoChanged, redo, &QWidget::setEnabled);
    undo->setEnabled(false);
    redo->setEnabled(false);
    connect(undo, &QPushButton::clicked, undoStack_, &QUndoStack::undo);
    connect(redo, &QPushButton::clicked, undoStack_, &QUndoStack::redo);

    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Recording:"), body));
    top->addWidget(recordingCombo_);
    top->addWidget(fileLabel_, 1);
    auto* transport = new QHBoxLayout;
    transport->addWidget(back);
    transport->addWidget(forward);
    transport->addWidget(positionLabel_, 1);
    auto* sync = new QHBoxLayout;
    sync->addWidget(new QLabel(tr("Offset:"), body));
    sync->addWidget(offsetBox_);
    sync->addWidget(markVideoButton_);
    sync->addWidget(markSignalButton_);
    sync->addWidget(undo);
    sync->addWidget(redo);
    sync->addStretch(1);
    auto* layout = new QVBoxLayout(body);
    layout->addLayout(top);
    layout->addWidget(view_, 1);
    layout->addLayout(transport);
    layout->addLayout(sync);
    layout->addWidget(syncLabel_);
    setWidget(body);

    connect(back, &QPushButton::clicked, this, [this] { stepFrame(-1); });
    connect(forward, &QPushButton::clicked, this, [this] { stepFrame(+1); });
    connect(markVideoButton_, &QPushButton::clicked, this, &VideoDock::markVideoEvent);
    connect(markSignalButton_, &QPushButton::clicked, this, &VideoDock::markSignalEvent);
    connect(offsetBox_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (link_ && std::abs(value - link_->offset) >= 5e-4) setOffset(value);
    });
    connect(recordingCombo_, &QComboBox::activated, this,
            [this] { (void)setRecording(recordingCombo_->currentText()); });
    if (TimeController* time = workspace_.timeController())
        connect(time, &TimeController::cursorChanged, this, &VideoDock::onCursor);
    // The dock reads the project it was opened on: follow the window when it swaps projects.
    connect(workspace_.notifier(), &WorkspaceNotifier::projectChanged, this, &VideoDock::reloadProject);
    projectSeen_ = workspace_.project();
    reloadProject();
}

VideoDock::~VideoDock() = default;

void VideoDock::reloadProject() {
    Project* project = workspace_.project();
    const QSignalBlocker blocker(recordingCombo_);
    recordingCombo_->clear();
    if (project) recordingCombo_->addItems(project->recordingNames());
    if (project != projectSeen_) {
        projectSeen_ = project;
        undoStack_->clear();
        recording_.clear();
    }
    if (!project) {
        worker_.reset();
        info_.reset();
        link_.reset();
        showPlaceholder(tr("No project"));
        return;
    }
    QString name = recording_;
    if (name.isEmpty() || !project->recording(name)) name = VideoLink::firstLinkedRecording(*project);
    if (name.isEmpty()) {
        worker_.reset();
        info_.reset();
        link_.reset();
        recording_.clear();
        showPlaceholder(tr("No recording of this project has a video. Use View → Video… to attach one."));
        return;
    }
    // Same recording and same link: keep the open reader; only the offset may have changed.
    const auto link = VideoLink::of(*project, name);
    if (name == recording_ && link && link_ && link->storedPath == link_->storedPath &&
        link->fpsOverride == link_->fpsOverride) {
        recordingCombo_->setCurrentText(name);
        if (link->offset != link_->offset) applyOffset(link->offset);
        return;
    }
    (void)setRecording(name);
}

Status VideoDock::setRecording(const QString& recording) {
    worker_.reset();
    info_.reset();
    link_.reset();
    markedVideo_.reset();
    markedSignal_.reset();
    syncLabel_->clear();
    recording_ = recording;
    {
        const QSignalBlocker blocker(recordingCombo_);
        recordingCombo_->setCurrentText(recording);
    }
    Project* project = workspace_.project();
    auto link = project ? VideoLink::of(*project, recording) : std::nullopt;
    if (!link) {
        fileLabel_->clear();
        const QString message = tr("Recording '%1' has no video. Use View → Video… to attach one.").arg(recording);
        showPlaceholder(message);
        return makeError(message);
    }
    link_ = link;
    {
        const QSignalBlocker blocker(offsetBox_);
        offsetBox_->setValue(link_->offset);
    }
    fileLabel_->setText(link_->storedPath);
    auto file = VideoLink::resolve(*project, recording);
    if (!file) {
        showPlaceholder(file.message());
        return file.error();
    }
    VideoReader::Params params;
    params.fpsOverride = link_->fpsOverride;
    auto reader = VideoReader::open(*file, params);
    if (!reader) {
        showPlaceholder(reader.message());
        return reader.error();
    }
    const VideoInfo& vi = (*reader)->info();
    info_ = Info{vi.fps, vi.frames, vi.file, vi.codec};
    fileLabel_->setText(
        tr("%1 (%2, %3 fps, %4 frames)").arg(link_->storedPath, vi.codec).arg(vi.fps, 0, 'g', 6).arg(vi.frames));
    worker_ = std::make_unique<VideoDecodeWorker>(
        std::move(*reader), [this](quint64 serial, long long index, const QImage& image, const QString& error) {
            QMetaObject::invokeMethod(
                this, [this, serial, index, image, error] { onDecoded(serial, index, image, error); },
                Qt::QueuedConnection);
        });
    shownIndex_ = -1;
    if (TimeController* time = workspace_.timeController()) onCursor(time->cursor());
    return {};
}

double VideoDock::offset() const { return link_ ? link_->offset : 0.0; }

void VideoDock::setOffset(double offset) {
    if (!link_ || !std::isfinite(offset)) return;
    const double before = link_->offset;
    if (offset == before) return;
    undoStack_->push(new VideoOffsetCommand([this](double value) { applyOffset(value); }, before, offset,
                                            tr("Video offset %1 s").arg(formatSeconds(offset))));
}

void VideoDock::applyOffset(double offset) {
    if (!link_) return;
    link_->offset = offset;
    {
        const QSignalBlocker blocker(offsetBox_);
        offsetBox_->setValue(offset);
    }
    if (Project* project = workspace_.project()) {
        if (VideoLink::setOffset(*project, recording_, offset)) {
            // projectModified() makes the window emit projectChanged; reloadProject() then sees
            // the same link and offset and keeps the reader.
            workspace_.projectModified();
        }
    }
    if (TimeController* time = workspace_.timeController()) onCursor(time->cursor());
}

void VideoDock::markVideoEvent() {
    if (!info_ || shownIndex_ < 0 || wanted_ < 0) {
        syncLabel_->setText(tr("Put the cursor where the video shows the event first."));
        return;
    }
    // The event happens in the frame on screen: its start time on the video clock.
    markedVideo_ = double(wanted_) / info_->fps;
    if (completeSync()) return;
    syncLabel_->setText(tr("Event marked in the video at %1 s (frame %2). Now put the cursor on the same event in a "
                           "signal and press \"Mark event in signal\".")
                            .arg(formatSeconds(*markedVideo_))
                            .arg(wanted_));
}

bool VideoDock::completeSync() {
    if (!markedVideo_ || !markedSignal_) return false;
    const double offset = VideoLink::offsetFromEvent(*markedVideo_, *markedSignal_);
    syncLabel_->setText(tr("Synchronised: video %1 s = recording %2 s, offset %3 s.")
                            .arg(formatSeconds(*markedVideo_), formatSeconds(*markedSignal_), formatSeconds(offset)));
    markedVideo_.reset();
    markedSignal_.reset();
    setOffset(offset);
    return true;
}

void VideoDock::markSignalEvent() {
    TimeController* time = workspace_.timeController();
    if (!info_ || !time) return;
    markedSignal_ = time->cursor();
    if (completeSync()) return;
    syncLabel_->setText(tr("Event marked in the signal at %1 s. Now put the cursor where the video shows the same "
                           "event and press \"Mark event in video\".")
                            .arg(formatSeconds(*markedSignal_)));
}

void VideoDock::stepFrame(int frames) {
    TimeController* time = workspace_.timeController();
    if (!info_ || !time || !link_) return;
    long long index = wanted_;
    if (index < 0) index = static_cast<long long>(std::floor(link_->videoTime(time->cursor()) * info_->fps + 1e-6));
    index = std::clamp<long long>(index + frames, 0, info_->frames - 1);
    time->setCursor(link_->recordingTime(double(index) / info_->fps));
}

void VideoDock::onCursor(double t) {
    if (!info_ || !link_ || !worker_) return;
    const double tv = link_->videoTime(t);
    const double duration = double(info_->frames) / info_->fps;
    long long index = tv >= 0 ? static_cast<long long>(std::floor(tv * info_->fps + 1e-6)) : -1;
    if (index >= info_->frames) index = -1;
    wanted_ = index;
    if (index < 0) {
        ++serial_;  // a decode still under way is stale now
        showPlaceholder(tr("No video at %1 s: the video covers %2 … %3 s of the recording (offset %4 s).")
                            .arg(formatSeconds(t), formatSeconds(link_->recordingTime(0)),
                                 formatSeconds(link_->recordingTime(duration)), formatSeconds(link_->offset)));
        return;
    }
    if (index == shownIndex_) {
        ++serial_;
        updateLabels();
        return;
    }
    worker_->request(++serial_, index);
    updateLabels();
}

void VideoDock::onDecoded(quint64 serial, long long index, const QImage& image, const QString& error) {
    if (serial != serial_) return;  // a newer request is under way
    if (!error.isEmpty()) {
        showPlaceholder(error);
        return;
    }
    shownIndex_ = index;
    shownImage_ = image;
    placeholder_.clear();
    view_->setImage(image);
    updateLabels();
}

void VideoDock::showPlaceholder(const QString& text) {
    shownIndex_ = -1;
    shownImage_ = {};
    placeholder_ = text;
    view_->setText(text);
    updateLabels();
}

QString VideoDock::placeholderText() const { return placeholder_; }

long long VideoDock::decoderSeeks() const { return worker_ ? worker_->seekCount() : 0; }

void VideoDock::updateLabels() {
    if (!info_ || wanted_ < 0) {
        positionLabel_->setText(info_ ? tr("outside the video") : QString());
        return;
    }
    positionLabel_->setText(tr("frame %1 / %2 · video %3 s")
                                .arg(wanted_)
                                .arg(info_->frames - 1)
                                .arg(formatSeconds(double(wanted_) / info_->fps)));
}

bool VideoDock::waitForFrame(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (!info_ || wanted_ < 0 || shownIndex_ == wanted_) return true;
        if (!placeholder_.isEmpty() && shownIndex_ < 0 && wanted_ >= 0 && !worker_) return true;
        QThread::msleep(2);
    }
    return false;
}

namespace {

const char* kContext = "athlos::ui::VideoDock";

VideoDock* findDock(QWidget* window) {
    return window ? window->findChild<VideoDock*>(QStringLiteral("videoDock")) : nullptr;
}

QString askForVideo(QWidget* parent) {
    return QFileDialog::getOpenFileName(
        parent, QCoreApplication::translate(kContext, "Attach a video"), QString(),
        QCoreApplication::translate(kContext,
                                    "Videos (*.mp4 *.m4v *.mov *.avi *.mkv *.webm *.mts *.mpg);;All files (*)"));
}

void launchVideo(Workspace& workspace) {
    Project* project = workspace.project();
    QWidget* parent = workspace.window();
    if (!project || project->recordingNames().isEmpty()) {
        QMessageBox::information(
            parent, QCoreApplication::translate(kContext, "Video"),
            QCoreApplication::translate(kContext, "Import a recording first; a video is attached to a recording."));
        return;
    }
    QString recording = ItemPath::parse(workspace.currentItem()).recording;
    if (recording.isEmpty() || !project->recording(recording)) recording = project->recordingNames().front();

    const auto link = VideoLink::of(*project, recording);
    auto resolved = link ? VideoLink::resolve(*project, recording) : Expected<QString>(makeError({}));
    if (!resolved) {
        if (link)
            QMessageBox::warning(parent, QCoreApplication::translate(kContext, "Video"),
                                 resolved.message() + QLatin1Char('\n') +
                                     QCoreApplication::translate(kContext, "Please locate the video."));
        const QString file = askForVideo(parent);
        if (file.isEmpty()) return;
        auto attached =
            VideoLink::attach(*project, recording, file, link ? link->offset : 0.0, link ? link->fpsOverride : 0.0);
        if (!attached) {
            QMessageBox::warning(parent, QCoreApplication::translate(kContext, "Video"), attached.message());
            return;
        }
        workspace.projectModified();
    }
    VideoDock* dock = findDock(parent);
    if (!dock) {
        dock = new VideoDock(workspace);
        workspace.addDock(dock, Qt::RightDockWidgetArea);
    } else {
        dock->show();
        dock->raise();
    }
    (void)dock->setRecording(recording);
}

Status prepareVideoView(Workspace& workspace) {
    Project* project = workspace.project();
    const QString recording = project ? VideoLink::firstLinkedRecording(*project) : QString();
    if (recording.isEmpty())
        return makeError(QCoreApplication::translate(kContext,
                                                     "no recording in this project has a video; attach one with "
                                                     "'athlos video <project> <recording> <file>'"));
    if (auto resolved = VideoLink::resolve(*project, recording); !resolved) return resolved.error();
    // Plot the recording's first stream so the cursor range is the recording's.
    if (const Recording* rec = project->recording(recording); rec && !rec->streams.empty())
        workspace.selectItem(recording + QLatin1Char('/') + rec->streams.begin()->first);
    workspace.waitForPlots();
    auto* dock = new VideoDock(workspace, workspace.window());
    workspace.addDock(dock, Qt::RightDockWidgetArea);
    workspace.resizeDock(dock, workspace.window()->width() * 2 / 5, Qt::Horizontal);
    if (Status status = dock->setRecording(recording); !status) return status;
    // The cursor in the middle of the part of the recording the video covers.
    TimeController* time = workspace.timeController();
    const auto link = VideoLink::of(*project, recording);
    auto reader = VideoReader::open(*VideoLink::resolve(*project, recording));
    if (time && link && reader) {
        const double a = std::max(time->begin(), link->recordingTime(0));
        const double b = std::min(time->end(), link->recordingTime((*reader)->info().duration()));
        time->setCursor(a <= b ? 0.5 * (a + b) : link->recordingTime(0.5 * (*reader)->info().duration()));
    }
    dock->waitForFrame(10000);
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("video"), QT_TRANSLATE_NOOP("Tools", "Video…"), QT_TRANSLATE_NOOP("Tools", "View"),
                      launchVideo});
ATHLOS_REGISTER_VIEW({QStringLiteral("video"), prepareVideoView});

}  // namespace athlos::ui
