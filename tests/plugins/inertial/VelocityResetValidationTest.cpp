// velocity-reset on gaitmap's real foot IMUs, through the processors (import --format gaitmap,
// orientation mode=6d, velocity-reset mode=foot, gait-parameters): every motion-capture stride (IC to
// IC) holds exactly one stance phase; the data has no distance reference, so stride lengths and
// heights are checked against gait-parameters (an independent per-stride integration) for agreement
// in the mean. Figures: docs/validation/drift-reduction.md ("Velocity resets").
#include "tools/eval/VelocityEvaluation.h"

#include <QDir>
#include <QFileInfo>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::inertial;

namespace {
const QDir kDir(QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap"));
}

TEST(VelocityResetValidation, GaitmapWalkOneStancePerMotionCaptureStride) {
    if (!QFileInfo::exists(kDir.filePath(QStringLiteral("imu_sample_ic_stride.csv"))))
        GTEST_SKIP() << "no gaitmap data";
    auto score = evaluateGaitmapVelocity(kDir.filePath(QStringLiteral("imu_sample_ic_stride.csv")),
                                         kDir.filePath(QStringLiteral("stride_borders_sample_ic_stride.csv")));
    ASSERT_TRUE(score.ok()) << qPrintable(score.message());
    EXPECT_EQ(score->referenceStrides, 14);
    EXPECT_EQ(score->oneStance, 14);
    EXPECT_GE(score->strides, 50);
    EXPECT_LT(std::abs(score->lengthDiffPct.mean()), 8.0);
    std::printf("[ figures  ] gaitmap walk: %d/%d strides with one stance, length vs gait-parameters %+.1f ± %.1f %%\n",
                score->oneStance, score->referenceStrides, score->lengthDiffPct.mean(), score->lengthDiffPct.sd());
}

TEST(VelocityResetValidation, GaitmapStairsClimbAsGaitParametersDoes) {
    for (const char* file : {"imu_sample_healthy_stair_up.csv", "imu_sample_healthy_stair_down.csv"}) {
        if (!QFileInfo::exists(kDir.filePath(QLatin1String(file)))) GTEST_SKIP() << "no gaitmap data";
        auto score = evaluateGaitmapVelocity(kDir.filePath(QLatin1String(file)), QString());
        ASSERT_TRUE(score.ok()) << qPrintable(score.message());
        EXPECT_GE(score->strides, 30) << file;
        EXPECT_LT(std::abs(score->heightDiff.mean()), 0.03) << file;
        EXPECT_LT(std::abs(score->lengthDiffPct.mean()), 8.0) << file;
    }
}
