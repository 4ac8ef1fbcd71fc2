#include "core/util/IsolatedRun.h"

#include <QByteArray>
#include <QtGlobal>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ATHLOS_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ATHLOS_ASAN 1
#endif

namespace athlos {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 86;  // work() returned an error; its message is in the pipe

[[noreturn]] void runChild(int out, const std::function<Status()>& work, const IsolatedRunParams& params) {
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) ::dup2(devNull, STDERR_FILENO);
    rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
#ifndef ATHLOS_ASAN
    if (params.memoryLimit > 0) {
        rlimit memory{params.memoryLimit, params.memoryLimit};
        ::setrlimit(RLIMIT_AS, &memory);
    }
#else
    (void)params;
#endif
    int code = kExitOk;
    QByteArray message;
    try {
        const Status status = work();
        if (!status) {
            code = kExitError;
            message = status.message().toUtf8();
        }
    } catch (const std::bad_alloc&) {
        code = kExitError;
        message = "out of memory while reading (the sizes in it are implausible)";
    } catch (...) {
        code = 3;
    }
    const char* p = message.constData();
    qsizetype left = message.size();
    while (left > 0) {
        const ssize_t n = ::write(out, p, std::size_t(left));
        if (n <= 0) break;
        p += n;
        left -= n;
    }
    ::_exit(code);
}

QString describeSignal(int signal) {
    const char* name = ::strsignal(signal);
    return QStringLiteral("signal %1%2")
        .arg(signal)
        .arg(name ? QStringLiteral(", ") + QString::fromLocal8Bit(name) : QString());
}

}  // namespace

std::chrono::milliseconds isolatedTimeoutFor(long long fileBytes, std::chrono::milliseconds base) {
    // ATHLOS_ISOLATION_TIMEOUT_S replaces the base (the fuzzers use a short one).
    bool ok = false;
    const double seconds = qEnvironmentVariable("ATHLOS_ISOLATION_TIMEOUT_S").toDouble(&ok);
    if (ok && seconds > 0) base = std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
    return base + std::chrono::milliseconds(std::max(0LL, fileBytes) / 20'000);
}

Status runIsolated(const QString& what, const std::function<Status()>& work, const IsolatedRunParams& params) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        return makeError(QStringLiteral("cannot check %1: %2").arg(what, QString::fromLocal8Bit(std::strerror(errno))));
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return makeError(QStringLiteral("cannot check %1: %2").arg(what, QString::fromLocal8Bit(std::strerror(errno))));
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(fds[1], work, params);
    }
    ::close(fds[1]);

    // Read the child's message until it closes the pipe (exit) or the time is up.
    QByteArray message;
    const auto deadline = std::chrono::steady_clock::now() + params.timeout;
    bool timedOut = false;
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        char buffer[4096];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // EOF: the child has exited (or closed the pipe)
        if (message.size() < (1 << 16)) message.append(buffer, qsizetype(n));
    }
    ::close(fds[0]);
    if (timedOut) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}

    if (timedOut)
        return makeError(QStringLiteral("%1 is damaged: reading it did not finish within %2 s")
                             .arg(what)
                             .arg(double(params.timeout.count()) / 1000.0, 0, 'f', 0));
    if (WIFSIGNALED(status))
        return makeError(QStringLiteral("%1 is damaged: reading it crashed the file library (%2); nothing was changed")
                             .arg(what, describeSignal(WTERMSIG(status))));
    if (!WIFEXITED(status)) return makeError(QStringLiteral("%1 could not be checked").arg(what));
    const int code = WEXITSTATUS(status);
    if (code == kExitOk) return {};
    if (code == kExitError && !message.isEmpty()) return makeError(QString::fromUtf8(message));
    return makeError(
        QStringLiteral("%1 is damaged: reading it failed inside the file library (exit code %2); nothing was changed")
            .arg(what)
            .arg(code));
}

}  // namespace athlos
