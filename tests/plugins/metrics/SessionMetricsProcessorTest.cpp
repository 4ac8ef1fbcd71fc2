// session-metrics through the runner (as the CLI runs it): the table's rows and columns, periods from
// annotations and windows, action counts, PlayerLoad from an IMU, GNSS input, and parameter errors.
#include "core/processing/ProcessorRunner.h"
#include "plugins/metrics/SessionMetricsProcessor.h"

#include <QDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;
using namespace athlos::metrics;

namespace {

// 0–60 s standing at the origin, 60–660 s running around at 4.5 m/s on a 40 m circle, then standing:
// exactly 2700 m; fixes at 10 Hz without noise.
Stream circleRun(const QString& kind) {
    const double rate = 10.0, radius = 40.0, speed = 4.5;
    const std::size_t n = static_cast<std::size_t>(720 * rate) + 1;
    StreamData d(n, 2);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) / rate;
        const double s = speed * std::clamp(t - 60.0, 0.0, 600.0);
        d.t[k] = t;
        d.at(k, 0) = radius * std::sin(s / radius);
        d.at(k, 1) = radius * (1 - std::cos(s / radius));
    }
    StreamInfo info;
    info.kind = kind;
    info.frame = QStringLiteral("pitch");
    info.columns = {{QStringLiteral("x"), QStringLiteral("m")}, {QStringLiteral("y"), QStringLiteral("m")}};
    return Stream(info, std::move(d));
}

Annotation annotation(const QString& label, double start, double end) {
    Annotation a;
    a.label = label;
    a.tStart = start;
    a.tEnd = end;
    return a;
}

std::unique_ptr<Project> project() {
    auto p = Project::create(QDir::temp().filePath(QStringLiteral("athlos-session-metrics-test.athlos")));
    p->putStream(QStringLiteral("s/pos"), circleRun(QStringLiteral("lps-position")));
    Recording& rec = p->ensureRecording(QStringLiteral("s"));
    rec.annotations.push_back(annotation(QStringLiteral("first half"), 0.0, 360.0));
    rec.annotations.push_back(annotation(QStringLiteral("second half"), 360.0, 720.0));
    rec.annotations.push_back(annotation(QStringLiteral("tackle"), 100.0, 100.0));
    rec.annotations.push_back(annotation(QStringLiteral("tackle"), 400.0, 401.0));
    rec.annotations.push_back(annotation(QStringLiteral("Jump shot"), 500.0, 500.0));
    return p;
}

const TableColumn& column(const Table& t, const char* name) {
    const TableColumn* c = t.column(QLatin1String(name));
    EXPECT_NE(c, nullptr) << name;
    static const TableColumn empty;
    return c ? *c : empty;
}

Expected<RunOutcome> run(Project& p, const QString& input, const QString& output, QVariantMap params = {}) {
    QStringList inputs = input.split(QLatin1Char(','));
    return runProcessor(p, SessionMetricsProcessor(),
                        RunRequest{QStringLiteral("session-metrics"), inputs, output, params});
}

}  // namespace

TEST(SessionMetricsProcessor, RowsPerPeriodWithActionCounts) {
    auto p = project();
    const auto out = run(*p, QStringLiteral("s/pos"), QStringLiteral("s/metrics"), {{QStringLiteral("window"), 300}});
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
    const Table* t = p->table(QStringLiteral("s/metrics"));
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->kind, QStringLiteral("session-metrics"));
    // whole, the two halves, windows 0–300, 300–600, 600–720.
    EXPECT_EQ(column(*t, "period").texts,
              (QStringList{QStringLiteral("whole"), QStringLiteral("first half"), QStringLiteral("second half"),
                           QStringLiteral("window 1"), QStringLiteral("window 2"), QStringLiteral("window 3")}));
    const auto& distance = column(*t, "distance").numbers;
    EXPECT_NEAR(distance[0], 2700.0, 27.0);  // within 1 %
    EXPECT_NEAR(distance[1], 1350.0, 13.5);  // 60–360 s at 4.5 m/s
    EXPECT_NEAR(distance[2], 1350.0, 13.5);
    EXPECT_NEAR(distance[3], 1080.0, 10.8);  // 60–300 s
    EXPECT_NEAR(column(*t, "max_speed").numbers[0], 4.5, 0.1);
    // 4.5 m/s = 16.2 km/h: zone 3 (14.4–19.8 km/h) but for the start and stop.
    EXPECT_NEAR(column(*t, "distance_zone3").numbers[0], distance[0], 0.02 * distance[0]);
    EXPECT_EQ(column(*t, "sprint_count").numbers[0], 0.0);
    EXPECT_EQ(column(*t, "actions_tackle").numbers, (std::vector<double>{2, 1, 1, 1, 1, 0}));
    EXPECT_EQ(column(*t, "actions_jump_shot").numbers, (std::vector<double>{1, 0, 1, 0, 1, 0}));
    EXPECT_EQ(column(*t, "distance").unit, QStringLiteral("m"));
    EXPECT_EQ(column(*t, "metabolic_power").unit, QStringLiteral("W/kg"));
    // The motion the metrics were computed on; standing phases held still.
    const Stream* motion = p->stream(QStringLiteral("s/metrics-motion"));
    ASSERT_NE(motion, nullptr);
    EXPECT_EQ(motion->info().columnNames().join(QLatin1Char(',')), QStringLiteral("x,y,speed,accel,valid"));
}

TEST(SessionMetricsProcessor, PlayerLoadFromAnImu) {
    auto p = project();
    // 100 Hz IMU: gravity on z plus a 1 g square wave on x toggling every 10 samples for 10 s:
    // 100 toggles of 1 g → PlayerLoad 1.0 AU.
    const std::size_t n = 1000;
    StreamData d(n, 6);
    for (std::size_t k = 0; k < n; ++k) {
        d.t[k] = 100.0 + 0.01 * double(k);
        d.at(k, 0) = (k / 10) % 2 ? 9.80665 : 0.0;
        d.at(k, 2) = 9.80665;
    }
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {
        {QStringLiteral("acc_x"), QStringLiteral("m/s^2")}, {QStringLiteral("acc_y"), QStringLiteral("m/s^2")},
        {QStringLiteral("acc_z"), QStringLiteral("m/s^2")}, {QStringLiteral("gyr_x"), QStringLiteral("rad/s")},
        {QStringLiteral("gyr_y"), QStringLiteral("rad/s")}, {QStringLiteral("gyr_z"), QStringLiteral("rad/s")}};
    p->putStream(QStringLiteral("s/imu"), Stream(info, std::move(d)));
    const auto out = run(*p, QStringLiteral("s/pos,s/imu"), QStringLiteral("s/m"), {{QStringLiteral("window"), 0}});
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
    const Table* t = p->table(QStringLiteral("s/m"));
    ASSERT_NE(t, nullptr);
    EXPECT_NEAR(column(*t, "player_load").numbers[0], 0.99, 1e-9);  // 99 toggles between 1000 samples
}

TEST(SessionMetricsProcessor, RawAndSmoothedOnNoisyFixes) {
    auto p = project();
    Stream noisy = circleRun(QStringLiteral("gnss"));
    auto data = noisy.data();
    ASSERT_TRUE(data.ok());
    StreamData d = **data;
    std::uint64_t state = 12345;
    auto gauss = [&]() {  // Box–Muller on a 64-bit LCG, deterministic
        auto u = [&]() {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            return (double(state >> 11) + 0.5) / 9007199254740992.0;
        };
        return std::sqrt(-2 * std::log(u())) * std::cos(6.283185307179586 * u());
    };
    for (std::size_t k = 0; k < d.rows(); ++k) d.at(k, 0) += 0.1 * gauss(), d.at(k, 1) += 0.1 * gauss();
    p->putStream(QStringLiteral("s/gnss"), Stream(noisy.info(), std::move(d)));
    ASSERT_TRUE(run(*p, QStringLiteral("s/gnss"), QStringLiteral("s/smooth")).ok());
    ASSERT_TRUE(
        run(*p, QStringLiteral("s/gnss"), QStringLiteral("s/raw"), {{QStringLiteral("filter"), QStringLiteral("none")}})
            .ok());
    const double smooth = column(*p->table(QStringLiteral("s/smooth")), "distance").numbers[0];
    const double raw = column(*p->table(QStringLiteral("s/raw")), "distance").numbers[0];
    EXPECT_NEAR(smooth, 2700.0, 27.0);
    EXPECT_GT(raw, 2700.0 * 1.1);  // raw noisy fixes overstate the distance
    EXPECT_NEAR(column(*p->table(QStringLiteral("s/smooth")), "max_speed").numbers[0], 4.5, 0.2);
    EXPECT_TRUE(p->table(QStringLiteral("s/smooth"))->attributes.contains(QStringLiteral("estimated_noise")));
}

TEST(SessionMetricsProcessor, ParameterAndInputErrors) {
    auto p = project();
    const auto zones =
        run(*p, QStringLiteral("s/pos"), QStringLiteral("s/m"), {{QStringLiteral("zones"), QStringLiteral("0,14,7")}});
    ASSERT_FALSE(zones.ok());
    EXPECT_TRUE(zones.message().contains(QStringLiteral("zones"))) << zones.message().toStdString();
    const auto peaks = run(*p, QStringLiteral("s/pos"), QStringLiteral("s/m"),
                           {{QStringLiteral("peak_windows"), QStringLiteral("60,abc")}});
    ASSERT_FALSE(peaks.ok());
    EXPECT_TRUE(peaks.message().contains(QStringLiteral("peak_windows")));
    const auto pattern = run(*p, QStringLiteral("s/pos"), QStringLiteral("s/m"),
                             {{QStringLiteral("period_pattern"), QStringLiteral("(")}});
    ASSERT_FALSE(pattern.ok());
    EXPECT_TRUE(pattern.message().contains(QStringLiteral("period_pattern")));
    // A position stream without x, y.
    StreamInfo info;
    info.kind = QStringLiteral("gnss");
    info.columns = {{QStringLiteral("lat"), QStringLiteral("deg")}, {QStringLiteral("lon"), QStringLiteral("deg")}};
    StreamData d(20, 2);
    for (std::size_t k = 0; k < 20; ++k) d.t[k] = double(k);
    p->putStream(QStringLiteral("s/latlon"), Stream(info, std::move(d)));
    const auto latlon = run(*p, QStringLiteral("s/latlon"), QStringLiteral("s/m"));
    ASSERT_FALSE(latlon.ok());
    EXPECT_TRUE(latlon.message().contains(QStringLiteral("s/latlon"))) << latlon.message().toStdString();
    EXPECT_EQ(p->table(QStringLiteral("s/m")), nullptr);
}
