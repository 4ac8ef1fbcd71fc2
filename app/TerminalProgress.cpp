#include "TerminalProgress.h"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace athlos::cli {
namespace {

CancelToken& interruptToken() {
    static CancelToken token;
    return token;
}
std::atomic_int interrupts{0};

extern "C" void onInterrupt(int) {
    if (++interrupts > 1) _exit(130);
    interruptToken().cancel();  // an atomic store: async-signal-safe
}

}  // namespace

TerminalProgress::TerminalProgress(QString label) : label_(std::move(label)), enabled_(::isatty(STDERR_FILENO) == 1) {
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    sinceDraw_.start();
}

TerminalProgress::~TerminalProgress() { finish(); }

Progress TerminalProgress::progress() {
    return Progress([this](double f, const QString& m) { draw(f, m); }, interruptToken());
}

void TerminalProgress::draw(double fraction, const QString& message) {
    if (!enabled_) return;
    // 10 redraws per second are enough for a person and cost nothing on fast jobs.
    if (drawn_ && fraction < 1.0 && sinceDraw_.elapsed() < 100) return;
    sinceDraw_.restart();
    drawn_ = true;
    constexpr int width = 30;
    const double f = std::clamp(fraction, 0.0, 1.0);
    const int filled = int(f * width + 0.5);
    const QByteArray bar = QByteArray(filled, '#') + QByteArray(width - filled, ' ');
    std::fprintf(stderr, "\r%s [%s] %3d%% %-40.40s", qUtf8Printable(label_), bar.constData(), int(f * 100 + 0.5),
                 qUtf8Printable(message));
    std::fflush(stderr);
}

void TerminalProgress::finish() {
    if (enabled_ && drawn_) {
        std::fprintf(stderr, "\n");
        drawn_ = false;
    }
}

}  // namespace athlos::cli
