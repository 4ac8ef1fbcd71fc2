#pragma once
// The background load of a plot panel: the load function runs on a worker thread, its result is
// handed to the panel on the GUI thread, and only if no newer request (or clear) came meanwhile,
// so a slow load of a stream the user already left never overwrites the current one.
#include <QFutureWatcher>
#include <QObject>

#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace athlos::ui {

class PanelLoader : public QObject {
    Q_OBJECT

public:
    explicit PanelLoader(QObject* parent = nullptr);
    ~PanelLoader() override;

    // Runs load() on a worker; deliver(result) follows on the GUI thread. A request still
    // running is superseded: its result is dropped when it arrives.
    template <typename Result>
    void start(std::function<Result()> load, std::function<void(Result)> deliver) {
        // Written by the worker, read on the GUI thread after the future finished.
        auto slot = std::make_shared<std::optional<Result>>();
        startErased([load = std::move(load), slot] { slot->emplace(load()); },
                    [deliver = std::move(deliver), slot] { deliver(std::move(**slot)); });
    }
    // Drops the pending request, if any (the panel was cleared).
    void cancel();
    // A request was started and its result not yet delivered.
    bool isLoading() const { return static_cast<bool>(deliver_); }
    // Blocks until the pending request finished and delivers it now (tests, screenshots, and
    // before anything that must not run concurrently with a load, such as saving).
    void waitForLoad();

private:
    void startErased(std::function<void()> work, std::function<void()> deliver);
    void deliver();

    QFutureWatcher<void> watcher_;
    // The delivery of the newest request; empty once delivered or cancelled.
    std::function<void()> deliver_;
};

}  // namespace athlos::ui
