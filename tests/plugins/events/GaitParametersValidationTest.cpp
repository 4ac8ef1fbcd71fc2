// gait-parameters through the real runner on gaitmap's walk (left and right foot, 102.4 Hz) against
// the strides segmented from motion capture: every reference stride (IC to IC) contains the
// midpoint of exactly one estimated stride (the judged rule of issue #17). The shared data has no
// stride-length reference, so lengths are checked for plausibility only (healthy walking
// 1.0–1.8 m, small spread). Stairs: stride height ≈ a step pair. The walk rotated into the raw
// sensor frames gives the same results (ml_axis = auto). Figures:
// docs/validation/gait-parameters.md.
#include "plugins/events/GaitParametersProcessor.h"

#include "core/io/Importer.h"
#include "core/processing/ProcessorRunner.h"
#include "tools/eval/GaitEvaluation.h"

#include <Eigen/Geometry>
#include <QDir>
#include <QJsonArray>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <map>

using namespace athlos;
using namespace athlos::events;

namespace {

const QDir kDir(QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap"));

class GaitParametersValidation : public ::testing::Test {
protected:
    void SetUp() override {
        if (!QFileInfo::exists(kDir.filePath(QStringLiteral("imu_sample_ic_stride.csv"))))
            GTEST_SKIP() << "no gaitmap data";
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
    }
    void import(const QString& file, const QString& as) {
        ImportOptions options;
        options.format = QStringLiteral("gaitmap");
        options.target = as;
        auto imported = importFile(kDir.filePath(file), options);
        ASSERT_TRUE(imported.ok()) << qPrintable(imported.message());
        ASSERT_TRUE(applyImport(*project_, std::move(imported).value(), false).ok());
    }
    const Table* run(const QString& input, const QString& output, const QVariantMap& params = {}) {
        auto r = runProcessor(*project_, processor_, RunRequest{processor_.id(), {input}, output, params});
        EXPECT_TRUE(r.ok()) << qPrintable(r.message());
        return r.ok() ? project_->table(output) : nullptr;
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
    GaitParametersProcessor processor_;
};

std::vector<double> column(const Table& t, const char* name) {
    const TableColumn* c = t.column(QString::fromLatin1(name));
    EXPECT_NE(c, nullptr) << name;
    return c ? c->numbers : std::vector<double>{};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Straight walking bouts of one foot: runs of at least 3 strides turning less than 0.3 rad each.
struct Bout {
    double from = 0.0, to = 0.0, meanLength = 0.0;
    std::size_t strides = 0;
};
std::vector<Bout> straightBouts(const Table& t) {
    const auto start = column(t, "start"), end = column(t, "end"), length = column(t, "stride_length"),
               turn = column(t, "turning_angle");
    std::vector<Bout> bouts;
    Bout b;
    const auto close = [&] {
        if (b.strides >= 3) bouts.push_back(Bout{b.from, b.to, b.meanLength / double(b.strides), b.strides});
        b = Bout{};
    };
    for (std::size_t i = 0; i < start.size(); ++i) {
        if (std::abs(turn[i]) >= 0.3) {
            close();
            continue;
        }
        if (!b.strides) b.from = start[i];
        b.to = end[i];
        b.meanLength += length[i];
        ++b.strides;
    }
    close();
    return bouts;
}

// Both feet walk the same path: per straight bout (paired by time overlap) the mean stride lengths
// of the two feet should agree. Returns the mean relative difference and the number of bouts, and
// prints each bout under `label`.
std::pair<double, int> leftRightDifference(const Table& left, const Table& right, const char* label) {
    const auto l = straightBouts(left), r = straightBouts(right);
    double sum = 0.0;
    int n = 0;
    for (const Bout& a : l) {
        const Bout* best = nullptr;
        double overlap = 0.0;
        for (const Bout& b : r)
            if (const double o = std::min(a.to, b.to) - std::max(a.from, b.from); o > overlap) {
                overlap = o;
                best = &b;
            }
        if (!best) continue;
        sum += std::abs(best->meanLength / a.meanLength - 1.0);
        ++n;
        std::printf("[ figures  ] %s bout %.1f-%.1f s: strides L/R %zu / %zu, mean L / R %.3f / %.3f m (%+.1f %%)\n",
                    label, a.from, a.to, a.strides, best->strides, a.meanLength, best->meanLength,
                    100.0 * (best->meanLength / a.meanLength - 1.0));
    }
    return {n ? sum / n : 1.0, n};
}

}  // namespace

TEST_F(GaitParametersValidation, EveryMotionCaptureStrideMatchedOnce) {
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    auto reference = readStrideBorders(kDir.filePath(QStringLiteral("stride_borders_sample_ic_stride.csv")), 102.4);
    ASSERT_TRUE(reference.ok()) << qPrintable(reference.message());
    ASSERT_EQ(reference->size(), 14u);
    int matched = 0;
    std::vector<double> lengths;
    for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
        const Table* table = run(QStringLiteral("walk/%1-foot").arg(foot), QStringLiteral("walk/%1-strides").arg(foot));
        ASSERT_NE(table, nullptr);
        EXPECT_EQ(table->column(QStringLiteral("cadence"))->unit, QStringLiteral("steps/min"));
        const auto start = column(*table, "start"), end = column(*table, "end"),
                   length = column(*table, "stride_length");
        for (const ReferenceStride& ref : *reference) {
            if (ref.foot != foot) continue;
            int hits = 0;
            std::size_t hit = 0;
            for (std::size_t i = 0; i < start.size(); ++i) {
                const double mid = 0.5 * (start[i] + end[i]);
                if (mid >= ref.tStart && mid <= ref.tEnd) {
                    ++hits;
                    hit = i;
                }
            }
            EXPECT_EQ(hits, 1) << qPrintable(foot) << " stride " << ref.tStart << "–" << ref.tEnd << " s";
            if (hits != 1) continue;
            ++matched;
            lengths.push_back(length[hit]);
            EXPECT_GT(length[hit], 1.0) << ref.tStart;
            EXPECT_LT(length[hit], 1.8) << ref.tStart;
        }
        const Stream* trajectory = project_->stream(QStringLiteral("walk/%1-strides-trajectory").arg(foot));
        ASSERT_NE(trajectory, nullptr);
        EXPECT_EQ(trajectory->info().columnNames(), (QStringList{"x", "y", "z"}));
    }
    EXPECT_EQ(matched, 14);
    // Straight walking at a steady pace: the matched strides agree with each other.
    const double m = median(lengths);
    double spread = 0.0;
    for (double l : lengths) spread = std::max(spread, std::abs(l / m - 1.0));
    EXPECT_LT(spread, 0.10) << "median " << m;
    std::printf(
        "[ figures  ] gaitmap walk: %d/14 reference strides matched once; matched lengths median %.3f m, "
        "largest deviation %.1f %%\n",
        matched, m, 100.0 * spread);
}

TEST_F(GaitParametersValidation, MethodRtsMatchesEveryStrideAndTheFeetAgree) {
    // method = rts swaps the per-stride integration for the Kalman smoother over the whole
    // recording: the same strides (segmentation), other lengths. Both methods must keep every
    // reference stride matched once; the figures of docs/validation/gait-parameters.md.
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    auto reference = readStrideBorders(kDir.filePath(QStringLiteral("stride_borders_sample_ic_stride.csv")), 102.4);
    ASSERT_TRUE(reference.ok()) << qPrintable(reference.message());
    std::map<QString, const Table*> tables;
    for (const QString& method : {QStringLiteral("instant"), QStringLiteral("rts")})
        for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
            const Table* t = run(QStringLiteral("walk/%1-foot").arg(foot),
                                 QStringLiteral("walk/%1-%2").arg(foot, method), {{QStringLiteral("method"), method}});
            ASSERT_NE(t, nullptr);
            EXPECT_EQ(t->attributes.value(QStringLiteral("method")).toString(), method);
            tables[method + foot] = t;
        }
    int matched = 0;
    double maxDifference = 0.0, sumDifference = 0.0;
    for (const ReferenceStride& ref : *reference) {
        const Table& a = *tables[QStringLiteral("instant") + ref.foot];
        const Table& b = *tables[QStringLiteral("rts") + ref.foot];
        const auto start = column(b, "start"), end = column(b, "end");
        ASSERT_EQ(start, column(a, "start"));  // the same strides
        int hits = 0;
        std::size_t hit = 0;
        for (std::size_t i = 0; i < start.size(); ++i)
            if (const double mid = 0.5 * (start[i] + end[i]); mid >= ref.tStart && mid <= ref.tEnd) {
                ++hits;
                hit = i;
            }
        EXPECT_EQ(hits, 1) << qPrintable(ref.foot) << " " << ref.tStart;
        if (hits != 1) continue;
        ++matched;
        const double instant = column(a, "stride_length")[hit], rts = column(b, "stride_length")[hit];
        EXPECT_GT(rts, 1.0) << ref.tStart;
        EXPECT_LT(rts, 1.8) << ref.tStart;
        maxDifference = std::max(maxDifference, std::abs(rts / instant - 1.0));
        sumDifference += rts / instant - 1.0;
        std::printf("[ figures  ] %s %.2f-%.2f s: instant %.3f m, rts %.3f m (%+.1f %%)\n", qPrintable(ref.foot),
                    ref.tStart, ref.tEnd, instant, rts, 100.0 * (rts / instant - 1.0));
    }
    EXPECT_EQ(matched, 14);
    EXPECT_GT(maxDifference, 0.005);  // the parameter does switch the method
    const auto [instantLr, bouts] =
        leftRightDifference(*tables[QStringLiteral("instantleft")], *tables[QStringLiteral("instantright")], "instant");
    const auto [rtsLr, rtsBouts] =
        leftRightDifference(*tables[QStringLiteral("rtsleft")], *tables[QStringLiteral("rtsright")], "rts");
    EXPECT_EQ(bouts, 4);
    EXPECT_EQ(rtsBouts, 4);
    // Left and right mean stride per straight bout: a weak check, as the two feet's strides of a
    // bout start and end at different footfalls, so their means may differ by up to a step over
    // the bout's strides (0.6 m / 5 strides). Version 4 (white noise) had 0.62 % here and 12 cm
    // of climb per stride on this level floor; the truth test is LevelFloorStridesStayLevel.
    EXPECT_LT(instantLr, 0.03);
    EXPECT_LT(rtsLr, 0.05);
    std::printf(
        "[ figures  ] gaitmap walk: rts − instant on the 14 matched strides mean %+.1f %%, largest %.1f %%; "
        "left/right mean stride per straight bout differs by %.2f %% (instant) and %.2f %% (rts) over %d bouts\n",
        100.0 * sumDifference / matched, 100.0 * maxDifference, 100.0 * instantLr, 100.0 * rtsLr, bouts);
}

TEST_F(GaitParametersValidation, LevelFloorStridesStayLevel) {
    // The walk is on a level floor, so every stride's height change is 0: a reference that needs no
    // motion capture. The smoother's velocity noise follows the dynamics (acc_noise_dynamic), so a
    // stance's correction goes to push-off and landing, where the errors arise; with white noise
    // (version 4, acc_noise 0.5, acc_noise_dynamic 0) the left foot climbed 0.12 m per stride.
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
        const Table* dynamic = run(QStringLiteral("walk/%1-foot").arg(foot), QStringLiteral("walk/%1-d").arg(foot));
        const Table* white = run(QStringLiteral("walk/%1-foot").arg(foot), QStringLiteral("walk/%1-w").arg(foot),
                                 {{QStringLiteral("acc_noise"), 0.5}, {QStringLiteral("acc_noise_dynamic"), 0.0}});
        ASSERT_TRUE(dynamic && white);
        const auto meanAbs = [](const std::vector<double>& v) {
            double sum = 0.0;
            for (double x : v) sum += std::abs(x);
            return sum / double(v.size());
        };
        const double d = meanAbs(column(*dynamic, "stride_height")), w = meanAbs(column(*white, "stride_height"));
        std::printf("[ figures  ] %s foot, level floor: mean |stride height| %.3f m (white noise %.3f m)\n",
                    qPrintable(foot), d, w);
        EXPECT_LT(d, 0.035) << qPrintable(foot);
        EXPECT_LT(d, 0.5 * w) << qPrintable(foot);
    }
}

TEST_F(GaitParametersValidation, SensorMountingDoesNotMatter) {
    // gaitmap's files are turned into "x forward, z up"; its raw lateral NilsPods are not (the
    // rotations of gaitmap's example_data/extract_example_data.py: raw = Rz(±90°) Rx(±90°) aligned, so
    // the medio-lateral axis is z and x points up). The same walk expressed in those raw frames must
    // give the same strides, lengths and turns with the default ml_axis = auto: the principal axis of
    // ω turns with the sensor, the heading change is taken from the rotation between mid-stances.
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    for (const auto& [foot, sign] :
         {std::pair{QStringLiteral("left"), 1.0}, std::pair{QStringLiteral("right"), -1.0}}) {
        const Stream* aligned = project_->stream(QStringLiteral("walk/%1-foot").arg(foot));
        ASSERT_NE(aligned, nullptr);
        auto data = aligned->data();
        ASSERT_TRUE(data.ok()) << qPrintable(data.message());
        const Eigen::Matrix3d mount = (Eigen::AngleAxisd(sign * M_PI / 2, Eigen::Vector3d::UnitZ()) *
                                       Eigen::AngleAxisd(sign * M_PI / 2, Eigen::Vector3d::UnitX()))
                                          .toRotationMatrix();
        StreamData raw = **data;
        const int acc = aligned->info().columnIndex(QStringLiteral("acc_x")),
                  gyr = aligned->info().columnIndex(QStringLiteral("gyr_x"));
        for (std::size_t k = 0; k < raw.rows(); ++k)
            for (const int c : {acc, gyr}) {
                const Eigen::Vector3d v = mount * Eigen::Vector3d(raw.at(k, c), raw.at(k, c + 1), raw.at(k, c + 2));
                for (int i = 0; i < 3; ++i) raw.at(k, c + i) = v[i];
            }
        StreamInfo info = aligned->info();
        info.name = QStringLiteral("walk/%1-raw").arg(foot);
        project_->putStream(info.name, Stream(info, std::move(raw)));

        const Table* a = run(QStringLiteral("walk/%1-foot").arg(foot), QStringLiteral("walk/%1-a").arg(foot));
        const Table* b = run(info.name, QStringLiteral("walk/%1-b").arg(foot));
        ASSERT_NE(a, nullptr);
        ASSERT_NE(b, nullptr);
        // In the raw frame the medio-lateral axis is z.
        const QJsonArray axis = b->attributes.value(QStringLiteral("ml_axis")).toArray();
        ASSERT_EQ(axis.size(), 3);
        EXPECT_GT(std::abs(axis[2].toDouble()), 0.95) << qPrintable(foot);
        const double dominance = b->attributes.value(QStringLiteral("ml_axis_dominance")).toDouble();
        EXPECT_GT(dominance, 0.5);
        const QJsonArray u = b->attributes.value(QStringLiteral("ml_axis_principal")).toArray();
        ASSERT_EQ(u.size(), 3);
        std::printf(
            "[ figures  ] %s foot, raw lateral frame: principal axis [%.3f, %.3f, %.3f], used [%.0f, %.0f, "
            "%.0f], dominance %.2f\n",
            qPrintable(foot), u[0].toDouble(), u[1].toDouble(), u[2].toDouble(), axis[0].toDouble(), axis[1].toDouble(),
            axis[2].toDouble(), dominance);
        EXPECT_EQ(column(*a, "start"), column(*b, "start")) << qPrintable(foot);
        EXPECT_EQ(column(*a, "end"), column(*b, "end")) << qPrintable(foot);
        for (const char* name :
             {"stride_length", "stride_height", "max_toe_clearance", "turning_angle", "swing_time"}) {
            const auto x = column(*a, name), y = column(*b, name);
            ASSERT_EQ(x.size(), y.size()) << name;
            for (std::size_t i = 0; i < x.size(); ++i)
                EXPECT_NEAR(x[i], y[i], 1e-6) << qPrintable(foot) << " " << name << " stride " << i;
        }
    }
}

TEST_F(GaitParametersValidation, StairsClimbAStepPairPerStride) {
    for (const auto& [file, sign] :
         {std::pair{"imu_sample_healthy_stair_up.csv", 1.0}, std::pair{"imu_sample_healthy_stair_down.csv", -1.0}}) {
        const QString name = sign > 0 ? QStringLiteral("up") : QStringLiteral("down");
        import(QString::fromLatin1(file), name);
        for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
            const Table* table =
                run(QStringLiteral("%1/%2-foot").arg(name, foot), QStringLiteral("%1/%2-strides").arg(name, foot));
            ASSERT_NE(table, nullptr);
            const auto height = column(*table, "stride_height"), length = column(*table, "stride_length");
            // Stair strides: a vertical change of two steps, a short horizontal one (two treads). The
            // riser height is not in the data: the bounds are those of stairs (risers 10–21 cm).
            std::vector<double> climbing, treads;
            for (std::size_t i = 0; i < height.size(); ++i)
                if (sign * height[i] > 0.15) {
                    climbing.push_back(sign * height[i]);
                    treads.push_back(length[i]);
                }
            ASSERT_GE(climbing.size(), 6u) << file << " " << qPrintable(foot);
            const double h = median(climbing), l = median(treads);
            EXPECT_GT(h, 0.20) << file;
            EXPECT_LT(h, 0.42) << file;
            EXPECT_GT(l, 0.4) << file;
            EXPECT_LT(l, 0.8) << file;
            std::printf(
                "[ figures  ] stairs %s, %s foot: %zu strides, %zu on the stairs, median height %.3f m, "
                "median length %.3f m\n",
                qPrintable(name), qPrintable(foot), height.size(), climbing.size(), h, l);
        }
    }
}

TEST_F(GaitParametersValidation, RefusesARecordingWithoutStrides) {
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    // No swing reaches 100 rad/s: nothing to integrate, refused with the reason, nothing stored.
    auto r = runProcessor(*project_, processor_,
                          RunRequest{processor_.id(),
                                     {QStringLiteral("walk/left-foot")},
                                     QStringLiteral("walk/x"),
                                     {{QStringLiteral("swing_threshold"), 100.0}}});
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains(QStringLiteral("no stride found"))) << qPrintable(r.message());
    EXPECT_TRUE(r.message().contains(QStringLiteral("no swing above swing_threshold = 100")))
        << qPrintable(r.message());
    EXPECT_EQ(project_->table(QStringLiteral("walk/x")), nullptr);
    // One swing (min_stride longer than the walk), and the mid-stances on its sides are held to
    // rest_threshold = 0: the swing has no stride.
    r = runProcessor(*project_, processor_,
                     RunRequest{processor_.id(),
                                {QStringLiteral("walk/left-foot")},
                                QStringLiteral("walk/x"),
                                {{QStringLiteral("rest_threshold"), 0.0},
                                 {QStringLiteral("min_stride"), 100.0},
                                 {QStringLiteral("max_stride"), 200.0}}});
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(
        r.message().contains(QStringLiteral("1 swing(s), but the mid-stance before the first or after the "
                                            "last is above rest_threshold = 0")))
        << qPrintable(r.message());
    EXPECT_EQ(project_->table(QStringLiteral("walk/x")), nullptr);
}

TEST_F(GaitParametersValidation, RestThresholdOnlyHoldsTheFirstAndLastMidStance) {
    // Between two swings the quietest instant is the mid-stance whatever its rate (a running foot
    // rolls through stance); rest_threshold guards only the ends of the data. With it at 0 the walk
    // keeps every stride but the first and the last.
    import(QStringLiteral("imu_sample_ic_stride.csv"), QStringLiteral("walk"));
    const Table* all = run(QStringLiteral("walk/left-foot"), QStringLiteral("walk/all"));
    const Table* inner =
        run(QStringLiteral("walk/left-foot"), QStringLiteral("walk/inner"), {{QStringLiteral("rest_threshold"), 0.0}});
    ASSERT_TRUE(all && inner);
    const auto start = column(*all, "start"), length = column(*all, "stride_length");
    const auto innerStart = column(*inner, "start"), innerLength = column(*inner, "stride_length");
    ASSERT_GE(start.size(), 3u);
    ASSERT_EQ(innerStart.size() + 2, start.size());
    for (std::size_t i = 0; i < innerStart.size(); ++i) {
        EXPECT_DOUBLE_EQ(innerStart[i], start[i + 1]) << i;
        // The smoother runs over a shorter span: the same strides, lengths within 2 cm, except the
        // last five before the span's new end. There the end condition (the last sample's filtered
        // state is its smoothed one) moves the tilt shared by the strides: up to 7 cm on this foot
        // with the dynamic velocity noise (docs/validation/gait-parameters.md, gyr_noise_dynamic).
        EXPECT_NEAR(innerLength[i], length[i + 1], i + 5 < innerStart.size() ? 0.02 : 0.08) << i;
    }
}
