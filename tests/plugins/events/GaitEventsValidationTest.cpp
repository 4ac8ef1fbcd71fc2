// Validation of the gait event detector on real data: gaitmap's foot IMU example (left and right
// foot, 102.4 Hz) against the strides segmented from motion capture (start = initial contact).
// Figures and the reproducing command: docs/validation/gait-events.md.
#include "tools/eval/GaitEvaluation.h"

#include <QDir>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::events;

namespace {
const QDir kDir(QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap"));
}

TEST(GaitEventsValidation, GaitmapInitialContactsMatchMotionCapture) {
    const QString imu = kDir.filePath(QStringLiteral("imu_sample_ic_stride.csv"));
    const QString borders = kDir.filePath(QStringLiteral("stride_borders_sample_ic_stride.csv"));
    if (!QFileInfo::exists(imu) || !QFileInfo::exists(borders))
        GTEST_SKIP() << "no gaitmap data in " << qPrintable(kDir.path());
    // ±50 ms: 5 samples at 102.4 Hz, a tenth of a step; far below half a step, so a match is unambiguous.
    auto v = validateGaitmap(imu, borders, 0.050);
    ASSERT_TRUE(v.ok()) << qPrintable(v.message());
    const IcScore& s = v->total;
    ASSERT_EQ(s.referenceIcs, 22);
    ASSERT_EQ(s.referenceStrides, 14);
    EXPECT_EQ(s.matchedIcs, s.referenceIcs) << "IC detection rate " << s.icRate();
    EXPECT_EQ(s.matchedStrides, s.referenceStrides) << "stride detection rate " << s.strideRate();
    EXPECT_EQ(s.falseIcs, 0);
    // The gyroscope's pre-impact peak leads the motion-capture contact by a few samples; bound the
    // bias and the spread (the spread is what matters for stride times).
    EXPECT_LT(std::abs(s.meanErrorMs), 35.0) << s.meanErrorMs;
    EXPECT_LT(s.sdErrorMs, 15.0) << s.sdErrorMs;
    // Stride times from the detection agree with the reference strides they matched.
    EXPECT_EQ(v->left.referenceIcs + v->right.referenceIcs, s.referenceIcs);
}

TEST(GaitEventsValidation, StairRecordingsGiveRegularStrides) {
    // No reference for the stairs (204.8 Hz, about 22 s, ~1 s strides): the detector must still find
    // a plausible stride sequence on both feet at twice the sampling rate (parameters are in seconds,
    // not samples). Stairs are not level walking (toe-first landing going down), so only the stride
    // count and regularity are checked; the event timing is validated on the level walk above.
    for (const char* name : {"imu_sample_healthy_stair_up.csv", "imu_sample_healthy_stair_down.csv"}) {
        const QString file = kDir.filePath(QString::fromLatin1(name));
        if (!QFileInfo::exists(file)) GTEST_SKIP() << "no " << name;
        auto feet = detectGaitmapFile(file);
        ASSERT_TRUE(feet.ok()) << qPrintable(feet.message());
        ASSERT_EQ(feet->size(), 2u);
        for (const auto& f : *feet) {
            EXPECT_NEAR(f.rate, 204.8, 0.5);
            EXPECT_GE(f.strides.size(), 12u) << name << " " << qPrintable(f.foot);
            EXPECT_LE(f.strides.size(), 25u) << name << " " << qPrintable(f.foot);
            std::vector<double> d;
            for (const auto& s : f.strides) {
                d.push_back(s.tEnd - s.tStart);
                EXPECT_LT(s.tStart, s.tMinVel);
                EXPECT_LT(s.tMinVel, s.tTc);
                EXPECT_LT(s.tTc, s.tEnd);
            }
            std::vector<double> sorted = d;
            std::sort(sorted.begin(), sorted.end());
            const double median = sorted[sorted.size() / 2];
            EXPECT_GT(median, 0.7) << name;
            EXPECT_LT(median, 1.3) << name;
            const auto regular =
                std::count_if(d.begin(), d.end(), [&](double x) { return std::abs(x / median - 1.0) < 0.25; });
            EXPECT_GE(double(regular), 0.5 * double(d.size())) << name << " " << qPrintable(f.foot);
        }
    }
}
