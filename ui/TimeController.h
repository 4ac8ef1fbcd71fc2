#pragma once
// The one time cursor of the window: cursor time, visible range, playback (speed 0.25×–4×,
// forward or backward) and frame step. Every time panel follows it, so zooming one panel zooms
// all and the cursor is the same instant everywhere (video, trajectory, plots).
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <algorithm>

class QKeyEvent;

namespace athlos::ui {

class TimeController : public QObject {
    Q_OBJECT

public:
    static constexpr double kMinSpeed = 0.25;
    static constexpr double kMaxSpeed = 4.0;

    explicit TimeController(QObject* parent = nullptr);

    // The recording's span; cursor and playback stay inside it. Resets the visible range.
    void setBounds(double begin, double end);
    double begin() const { return begin_; }
    double end() const { return end_; }

    double cursor() const { return cursor_; }
    double visibleBegin() const { return visibleBegin_; }
    double visibleEnd() const { return visibleEnd_; }

    bool isPlaying() const { return playing_; }
    // +1 forward, -1 backward.
    int direction() const { return direction_; }
    double speed() const { return speed_; }
    // Seconds per frame step (the sample interval of the main stream, or 1/30 s).
    double step() const { return step_; }
    void setStep(double seconds);

    // Space, Left/Right, J/K/L, Home/End. Returns whether the key was a transport key.
    bool handleKey(QKeyEvent* event);
    // Moves playback by wall-clock seconds (the timer does this; tests call it directly).
    void advance(double wallSeconds);
    // Manual clock: playing no longer starts the display timer, only advance() moves the cursor
    // (tests and benchmarks that must know which instant each frame shows).
    void setManualClock(bool manual) {
        manualClock_ = manual;
        if (manual) timer_.stop();
    }

public slots:
    void setCursor(double t);
    void setVisibleRange(double begin, double end);
    void zoomToSelection(double a, double b) { setVisibleRange(std::min(a, b), std::max(a, b)); }
    void showAll() { setVisibleRange(begin_, end_); }
    void setPlaying(bool playing);
    void togglePlaying() { setPlaying(!playing_); }
    void setSpeed(double speed);
    void stepForward() { stepBy(+1); }
    void stepBackward() { stepBy(-1); }
    // J / K / L: back (repeated: faster) / pause / forward (repeated: faster).
    void jogBackward() { jog(-1); }
    void jogForward() { jog(+1); }

signals:
    void cursorChanged(double t);
    void visibleRangeChanged(double begin, double end);
    void playingChanged(bool playing);
    void speedChanged(double speed, int direction);

private:
    void stepBy(int frames);
    void jog(int direction);
    void onTick();

    double begin_ = 0, end_ = 1;
    double cursor_ = 0;
    double visibleBegin_ = 0, visibleEnd_ = 1;
    bool playing_ = false;
    bool manualClock_ = false;
    int direction_ = 1;
    double speed_ = 1.0;
    double step_ = 1.0 / 30.0;
    QTimer timer_;
    QElapsedTimer clock_;
};

}  // namespace athlos::ui
