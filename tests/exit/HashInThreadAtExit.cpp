// Regression test for OpenSSL's exit order (core/model/StreamData.cpp): a worker thread that hashes
// a stream and is joined only at exit, after OpenSSL's own exit handler would have run had OpenSSL
// been initialised by that first hash. Under LeakSanitizer (scripts/sanitize.sh) the thread's error
// state then leaks and the process fails; in the plain build the hash is checked only.
#include "core/model/StreamData.h"

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

namespace {

// Like Qt's global thread pool: created before the first hash, joins its thread at exit.
class ExitJoinedWorker {
public:
    ExitJoinedWorker()
        : thread_([this] {
              athlos::StreamData data;
              data.t = {0.0, 0.01, 0.02};
              data.columns = 1;
              data.values = {1.0, 2.0, 3.0};
              const QByteArray hash = data.contentHash();
              {
                  std::lock_guard lock(mutex_);
                  hash_ = hash;
                  hashed_ = true;
              }
              changed_.notify_all();
              std::unique_lock lock(mutex_);
              changed_.wait(lock, [this] { return stop_; });
          }) {}
    ~ExitJoinedWorker() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
        thread_.join();
    }
    QByteArray waitForHash() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return hashed_; });
        return hash_;
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    bool hashed_ = false;
    bool stop_ = false;
    QByteArray hash_;
    std::thread thread_;
};

}  // namespace

int main() {
    static ExitJoinedWorker worker;  // destroyed at exit, after main returns
    const QByteArray hash = worker.waitForHash();
    // SHA-256 is 32 bytes, 64 hex digits; a second hash of the same content must agree.
    athlos::StreamData same;
    same.t = {0.0, 0.01, 0.02};
    same.columns = 1;
    same.values = {1.0, 2.0, 3.0};
    if (hash.size() != 64 || hash != same.contentHash()) {
        std::fprintf(stderr, "contentHash in a worker thread: '%s', on the main thread: '%s'\n", hash.constData(),
                     same.contentHash().constData());
        return 1;
    }
    return 0;
}
