#include "ui/PanelLoader.h"

#include <QtConcurrent/QtConcurrentRun>

namespace athlos::ui {

PanelLoader::PanelLoader(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<void>::finished, this, &PanelLoader::deliver);
}

// A worker still running keeps its own result slot alive; nothing waits for it.
PanelLoader::~PanelLoader() = default;

void PanelLoader::startErased(std::function<void()> work, std::function<void()> deliver) {
    deliver_ = std::move(deliver);
    // The watcher follows only the newest future, so a superseded one never signals here.
    watcher_.setFuture(QtConcurrent::run(std::move(work)));
}

void PanelLoader::cancel() { deliver_ = nullptr; }

void PanelLoader::waitForLoad() {
    if (!isLoading()) return;
    watcher_.waitForFinished();
    deliver();
}

void PanelLoader::deliver() {
    // A finished signal may still be queued for a request that waitForLoad() already delivered
    // or that was cancelled; the watched future is always the newest one.
    if (!deliver_ || !watcher_.isFinished()) return;
    const std::function<void()> pending = std::exchange(deliver_, nullptr);
    pending();
}

}  // namespace athlos::ui
