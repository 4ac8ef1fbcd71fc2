#include "ui/TimeController.h"

#include <QKeyEvent>

#include <algorithm>
#include <cmath>

namespace athlos::ui {

TimeController::TimeController(QObject* parent) : QObject(parent) {
    // ~60 Hz; the elapsed clock (not the tick count) drives time, so a late tick does not slow playback.
    timer_.setInterval(16);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &TimeController::onTick);
}

void TimeController::setBounds(double begin, double end) {
    if (!std::isfinite(begin) || !std::isfinite(end)) return;
    if (end < begin) std::swap(begin, end);
    begin_ = begin;
    end_ = end;
    setVisibleRange(begin, end);
    setCursor(std::clamp(cursor_, begin_, end_));
}

void TimeController::setStep(double seconds) {
    if (std::isfinite(seconds) && seconds > 0) step_ = seconds;
}

void TimeController::setCursor(double t) {
    if (!std::isfinite(t)) return;
    t = std::clamp(t, begin_, end_);
    if (t == cursor_) return;
    cursor_ = t;
    emit cursorChanged(cursor_);
    // Playback pages the view so the cursor stays visible.
    const double width = visibleEnd_ - visibleBegin_;
    if (playing_ && width > 0 && (t > visibleEnd_ || t < visibleBegin_)) {
        const double start = direction_ > 0 ? t : t - width;
        setVisibleRange(start, start + width);
    }
}

void TimeController::setVisibleRange(double begin, double end) {
    if (!std::isfinite(begin) || !std::isfinite(end) || end <= begin) return;
    if (begin == visibleBegin_ && end == visibleEnd_) return;
    visibleBegin_ = begin;
    visibleEnd_ = end;
    emit visibleRangeChanged(begin, end);
}

void TimeController::setPlaying(bool playing) {
    if (playing == playing_) return;
    playing_ = playing;
    if (playing_) {
        // Playing from the end (forward) starts over, as players do.
        if (direction_ > 0 && cursor_ >= end_) setCursor(begin_);
        if (direction_ < 0 && cursor_ <= begin_) setCursor(end_);
        clock_.start();
        if (!manualClock_) timer_.start();
    } else {
        timer_.stop();
    }
    emit playingChanged(playing_);
}

void TimeController::setSpeed(double speed) {
    speed = std::clamp(speed, kMinSpeed, kMaxSpeed);
    if (speed == speed_) return;
    speed_ = speed;
    emit speedChanged(speed_, direction_);
}

void TimeController::stepBy(int frames) {
    setPlaying(false);
    setCursor(cursor_ + frames * step_);
}

void TimeController::jog(int direction) {
    if (playing_ && direction_ == direction) {
        setSpeed(speed_ * 2);
        return;
    }
    direction_ = direction;
    speed_ = 1.0;
    emit speedChanged(speed_, direction_);
    setPlaying(true);
}

void TimeController::advance(double wallSeconds) {
    if (!playing_) return;
    const double t = cursor_ + direction_ * speed_ * wallSeconds;
    setCursor(t);
    if ((direction_ > 0 && t >= end_) || (direction_ < 0 && t <= begin_)) setPlaying(false);
}

void TimeController::onTick() {
    const double elapsed = clock_.nsecsElapsed() * 1e-9;
    clock_.restart();
    advance(elapsed);
}

bool TimeController::handleKey(QKeyEvent* event) {
    if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) return false;
    switch (event->key()) {
        case Qt::Key_Space:
            togglePlaying();
            return true;
        case Qt::Key_Right:
            stepForward();
            return true;
        case Qt::Key_Left:
            stepBackward();
            return true;
        case Qt::Key_J:
            jogBackward();
            return true;
        case Qt::Key_K:
            setPlaying(false);
            return true;
        case Qt::Key_L:
            jogForward();
            return true;
        case Qt::Key_Home:
            setCursor(begin_);
            return true;
        case Qt::Key_End:
            setCursor(end_);
            return true;
        default:
            return false;
    }
}

}  // namespace athlos::ui
