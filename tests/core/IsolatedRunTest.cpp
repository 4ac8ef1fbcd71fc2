// runIsolated turns a crash or a hang of the work into an error, and passes results through.
#include "core/util/IsolatedRun.h"

#include <gtest/gtest.h>

#include <csignal>
#include <thread>

namespace athlos {
namespace {

TEST(IsolatedRun, SuccessPassesThrough) {
    EXPECT_TRUE(runIsolated(QStringLiteral("the file"), [] { return Status{}; }).ok());
}

TEST(IsolatedRun, ErrorMessageComesBackFromTheChild) {
    const Status status =
        runIsolated(QStringLiteral("the file"), [] { return Status(makeError(QStringLiteral("row 7: bad ünïcode"))); });
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.message(), QStringLiteral("row 7: bad ünïcode"));
}

TEST(IsolatedRun, CrashBecomesAnErrorNamingTheInput) {
    const Status status = runIsolated(QStringLiteral("project 'x.athlos'"), []() -> Status {
        std::raise(SIGSEGV);
        return {};
    });
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(status.message().contains(QStringLiteral("project 'x.athlos' is damaged")))
        << status.message().toStdString();
}

TEST(IsolatedRun, AbortBecomesAnError) {
    const Status status = runIsolated(QStringLiteral("the file"), []() -> Status { std::abort(); });
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(status.message().contains(QStringLiteral("damaged"))) << status.message().toStdString();
}

TEST(IsolatedRun, HangIsStoppedAtTheTimeout) {
    IsolatedRunParams params;
    params.timeout = std::chrono::milliseconds(300);
    const auto start = std::chrono::steady_clock::now();
    const Status status = runIsolated(
        QStringLiteral("the file"),
        []() -> Status {
            for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        },
        params);
    const auto took = std::chrono::steady_clock::now() - start;
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(status.message().contains(QStringLiteral("did not finish"))) << status.message().toStdString();
    EXPECT_LT(took, std::chrono::seconds(5));
}

TEST(IsolatedRun, TimeoutGrowsWithTheFileSize) {
    EXPECT_EQ(isolatedTimeoutFor(0, std::chrono::seconds(20)), std::chrono::seconds(20));
    EXPECT_EQ(isolatedTimeoutFor(200'000'000, std::chrono::seconds(20)), std::chrono::seconds(30));
}

}  // namespace
}  // namespace athlos
