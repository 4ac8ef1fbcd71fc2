#pragma once
// The attached video of a recording (core/video/VideoLink), in a dock that follows the window's
// time cursor: the frame shown is the one at video time cursor − offset (t_recording = t_video +
// offset). Frames decode on a worker thread; only the newest request is served, so scrubbing
// stays fluid, and playback (ascending frames) decodes on without seeking.
//
// Synchronisation: put the cursor on an event visible in the video (a clap, a jump's take-off) and
// press "Mark event in video"; put it on the same event in a signal (the acceleration spike) and
// press "Mark event in signal". The offset follows from the pair and is stored in the project;
// the dock's Undo restores the previous one. The offset can also be typed (ms resolution).
#include "core/video/VideoLink.h"

#include <QDockWidget>
#include <QImage>
#include <QString>

#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QUndoStack;

namespace athlos::ui {

class Workspace;
class VideoFrameView;
class VideoDecodeWorker;

class VideoDock : public QDockWidget {
    Q_OBJECT

public:
    explicit VideoDock(Workspace& workspace, QWidget* parent = nullptr);
    ~VideoDock() override;

    // Shows recording's video (re-reading its link); error if it has none or the file cannot be
    // opened (the dock then shows the message).
    Status setRecording(const QString& recording);
    QString recording() const { return recording_; }
    bool hasVideo() const { return bool(info_); }

    double offset() const;
    // Stores a new offset in the project (undoable in the dock).
    void setOffset(double offset);
    // The two halves of the synchronisation; the second one sets the offset.
    void markVideoEvent();
    void markSignalEvent();
    // One video frame forward / back: moves the window's cursor.
    void stepFrame(int frames);

    // The frame index requested for the current cursor (−1: the cursor is outside the video).
    long long wantedFrame() const { return wanted_; }
    // The frame on screen (−1: placeholder) and its picture.
    long long shownFrame() const { return shownIndex_; }
    const QImage& shownImage() const { return shownImage_; }
    QString placeholderText() const;
    // Blocks (processing events) until the wanted frame is on screen or the timeout expires.
    bool waitForFrame(int timeoutMs = 5000);

    // Seeks the decoder made (playback and small forward steps decode on instead).
    long long decoderSeeks() const;

    QUndoStack* undoStack() const { return undoStack_; }
    QDoubleSpinBox* offsetBox() const { return offsetBox_; }
    QLabel* positionLabel() const { return positionLabel_; }

private:
    // Both events marked (either order): sets the offset from the pair and says so.
    bool completeSync();
    void applyOffset(double offset);
    void reloadProject();
    void onCursor(double t);
    void onDecoded(quint64 serial, long long index, const QImage& image, const QString& error);
    void showPlaceholder(const QString& text);
    void updateLabels();

    Workspace& workspace_;
    const void* projectSeen_ = nullptr;
    QString recording_;
    std::optional<VideoLink> link_;
    struct Info {
        double fps = 0;
        long long frames = 0;
        QString file, codec;
    };
    std::optional<Info> info_;
    std::unique_ptr<VideoDecodeWorker> worker_;
    quint64 serial_ = 0;
    long long wanted_ = -1;
    long long shownIndex_ = -1;
    QImage shownImage_;
    QString placeholder_;
    std::optional<double> markedVideo_, markedSignal_;

    QComboBox* recordingCombo_ = nullptr;
    VideoFrameView* view_ = nullptr;
    QLabel* fileLabel_ = nullptr;
    QLabel* positionLabel_ = nullptr;
    QLabel* syncLabel_ = nullptr;
    QDoubleSpinBox* offsetBox_ = nullptr;
    QPushButton* markVideoButton_ = nullptr;
    QPushButton* markSignalButton_ = nullptr;
    QUndoStack* undoStack_ = nullptr;
};

}  // namespace athlos::ui
