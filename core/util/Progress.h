#pragma once
// Progress reporting and cooperative cancellation shared by importers, processors and the runner.
// The GUI feeds it into a progress dialog, the CLI into a terminal bar; algorithms only call report()
// and poll isCancelled().
#include <QString>
#include <atomic>
#include <functional>
#include <memory>

namespace athlos {

class CancelToken {
public:
    CancelToken() : flag_(std::make_shared<std::atomic_bool>(false)) {}
    void cancel() { flag_->store(true); }
    bool isCancelled() const { return flag_->load(std::memory_order_relaxed); }

private:
    std::shared_ptr<std::atomic_bool> flag_;
};

class Progress {
public:
    using Callback = std::function<void(double fraction, const QString& message)>;

    Progress() = default;
    explicit Progress(Callback callback, CancelToken token = {})
        : callback_(std::move(callback)), token_(std::move(token)) {}

    // fraction in [0, 1]; the callback is throttled by the receiver, so calling it per block is fine.
    void report(double fraction, const QString& message = {}) const {
        if (callback_) callback_(fraction, message);
    }
    bool isCancelled() const { return token_.isCancelled(); }
    const CancelToken& token() const { return token_; }

    // A view on the sub-range [begin, end] of this progress, for steps of a longer job.
    Progress sub(double begin, double end) const {
        auto parent = callback_;
        return Progress(
            [parent, begin, end](double f, const QString& m) {
                if (parent) parent(begin + (end - begin) * f, m);
            },
            token_);
    }

private:
    Callback callback_;
    CancelToken token_;
};

}  // namespace athlos
