#pragma once
// Runs work that parses untrusted bytes through a library that cannot be made safe (libhdf5,
// FFmpeg) in a forked child process, so that a crash or a hang in the library becomes an error
// message instead of taking Athlos down (issue #11: "a damaged file is refused with a clear message,
// never a crash").
//
// The child runs `work` and reports its Status through a pipe; the parent waits at most `timeout`.
//   - work() succeeded                    → success
//   - work() returned an error            → that error
//   - the child died of a signal, exited
//     abnormally or ran past the timeout  → an error that says so (the bytes are damaged)
// The child's stderr goes to /dev/null and it writes no core file. `work` must not rely on other
// threads of the parent (they do not exist in the child) and must not take locks that another
// thread may hold; call it with the HDF5 lock held by the calling thread (see ProjectFile).
#include "core/util/Expected.h"

#include <QString>
#include <chrono>
#include <functional>

namespace athlos {

struct IsolatedRunParams {
    std::chrono::milliseconds timeout{std::chrono::seconds(30)};
    // Upper bound of the child's address space in bytes (0: unlimited). Ignored under
    // AddressSanitizer, which reserves terabytes of virtual memory.
    unsigned long long memoryLimit = 0;
};

// `what` names the input for messages, e.g. "project 'p.athlos'".
Status runIsolated(const QString& what, const std::function<Status()>& work, const IsolatedRunParams& params = {});

// A timeout that grows with the size of the file to be read: base + 1 s per 20 MB. The environment
// variable ATHLOS_ISOLATION_TIMEOUT_S (seconds) replaces the base.
std::chrono::milliseconds isolatedTimeoutFor(long long fileBytes,
                                             std::chrono::milliseconds base = std::chrono::seconds(20));

}  // namespace athlos
