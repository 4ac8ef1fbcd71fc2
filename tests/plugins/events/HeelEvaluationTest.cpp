// The heel-marker scoring of athlos-eval-gait-heel (tools/eval/HeelEvaluation.h) on a hand-made
// gaitmap mocap file and hand-made strides, so that the figures of docs/validation/gait-parameters.md
// rest on a checked scorer.
#include "tools/eval/HeelEvaluation.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos::events;

namespace {
// 100 Hz: the left heel stands at x = 0 until 1 s, at 1.40 m from 2 s; the right heel stays at
// (5, 5). Columns as gaitmap's mocap_sample.csv, marker names in the first row, axes in the second.
QString writeMocap(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("mocap.csv"));
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Text));
    QTextStream out(&f);
    out << ",L_TOE,L_TOE,L_TOE,L_FCC,L_FCC,L_FCC,R_FCC,R_FCC,R_FCC\n,x,y,z,x,y,z,x,y,z\n";
    for (int k = 0; k <= 300; ++k) {
        const double x = k <= 100 ? 0.0 : k >= 200 ? 1400.0 : 14.0 * (k - 100);
        out << k << ",0,0,0," << x << ",0,40," << 5000 << ",5000,40\n";
    }
    return path;
}
}  // namespace

TEST(HeelEvaluation, ReadsTheHeelMarkersInMetres) {
    QTemporaryDir dir;
    auto heel = readGaitmapHeel(writeMocap(dir));
    ASSERT_TRUE(heel.ok()) << qPrintable(heel.message());
    ASSERT_EQ(heel->left.size(), 301u);
    EXPECT_DOUBLE_EQ(heel->left[250].x(), 1.4);
    EXPECT_DOUBLE_EQ(heel->right[0].y(), 5.0);
}

TEST(HeelEvaluation, ScoresMatchedStridesAgainstTheHeelDisplacement) {
    QTemporaryDir dir;
    auto heel = readGaitmapHeel(writeMocap(dir));
    ASSERT_TRUE(heel.ok());
    const std::vector<ReferenceStride> reference = {{QStringLiteral("left"), 0.5, 2.5}};
    // Midpoint 1.5 s lies in the reference stride: 1.47 m against the heel's 1.40 m (+5 %); a
    // second estimated stride outside it does not count there, but between its own borders the
    // heel moved less than 0.2 m, so it is left out of the own-border figures too.
    const std::vector<EstimatedStride> strides = {{0.6, 2.4, 1.47, 0.0}, {2.5, 2.9, 0.1, 0.5}};
    HeelScore score;
    scoreAgainstHeel(reference, heel->left, heel->rate, strides, score);
    EXPECT_EQ(score.reference, 1);
    EXPECT_EQ(score.matchedOnce, 1);
    ASSERT_EQ(score.error.size(), 1u);
    EXPECT_NEAR(score.error[0], 0.05, 1e-12);
    ASSERT_EQ(score.straightError.size(), 1u);
    ASSERT_EQ(score.ownError.size(), 1u);
    EXPECT_NEAR(score.ownError[0], 0.05, 1e-12);

    // Two estimated midpoints in one reference stride: not matched once, no error recorded.
    HeelScore twice;
    scoreAgainstHeel(reference, heel->left, heel->rate, {{0.6, 1.4, 0.7, 0.0}, {1.4, 2.4, 0.7, 0.0}}, twice);
    EXPECT_EQ(twice.matchedOnce, 0);
    EXPECT_TRUE(twice.error.empty());
}

TEST(HeelEvaluation, RefusesAFileWithoutHeelMarkers) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("no_heel.csv"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Text));
    f.write(",L_TOE,L_TOE\n,x,y\n0,1,2\n");
    f.close();
    auto heel = readGaitmapHeel(path);
    ASSERT_FALSE(heel.ok());
    EXPECT_TRUE(heel.message().contains(QStringLiteral("L_FCC"))) << qPrintable(heel.message());
}

TEST(HeelEvaluation, ALostMarkerIsNotScoredAndABadCellIsNamed) {
    // An empty cell (the cameras lost the marker) reads as NaN, and a stride ending there is not scored;
    // text in a cell is refused with its line and column.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("gap.csv"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Text));
    f.write(",L_FCC,L_FCC,R_FCC,R_FCC\n,x,y,x,y\n0,0,0,5,5\n1,,0,5,5\n2,1400,0,5,5\n");
    f.close();
    auto heel = readGaitmapHeel(path, 1.0);
    ASSERT_TRUE(heel.ok()) << qPrintable(heel.message());
    EXPECT_TRUE(std::isnan(heel->left[1].x()));
    HeelScore lost, kept;
    scoreAgainstHeel({{QStringLiteral("left"), 0.0, 1.0}}, heel->left, 1.0, {{0.0, 0.9, 1.4, 0.0}}, lost);
    EXPECT_EQ(lost.matchedOnce, 1);
    EXPECT_TRUE(lost.error.empty());  // matched, but its heel length is unknown
    scoreAgainstHeel({{QStringLiteral("left"), 0.0, 2.0}}, heel->left, 1.0, {{0.0, 2.0, 1.4, 0.0}}, kept);
    ASSERT_EQ(kept.error.size(), 1u);
    EXPECT_NEAR(kept.error[0], 0.0, 1e-12);
    QFile bad(dir.filePath(QStringLiteral("bad.csv")));
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly | QIODevice::Text));
    bad.write(",L_FCC,L_FCC,R_FCC,R_FCC\n,x,y,x,y\n0,0,0,5,5\n1,0,x,5,5\n");
    bad.close();
    auto refused = readGaitmapHeel(bad.fileName());
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("bad.csv:4:3: 'x' is not a number")))
        << qPrintable(refused.message());
}

TEST(HeelEvaluation, StrideBordersAreReadInSecondsAndABadCellIsNamed) {
    // gaitmap's stride_borders_sample.csv: s_id,start,end,foot in samples; quoted or reordered cells,
    // a CRLF line end and a byte-order mark are read alike; bad cells name their line and column.
    QTemporaryDir dir;
    const auto write = [&](const char* name, const QByteArray& text) {
        QFile f(dir.filePath(QString::fromLatin1(name)));
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
        return f.fileName();
    };
    auto ok = readStrideBorders(write("ok.csv",
                                      "\xEF\xBB\xBFs_id,start,end,foot\r\n0,100,300,left\r\n1,150,\"350\","
                                      "\"right\"\n\n"),
                                100.0);
    ASSERT_TRUE(ok.ok()) << qPrintable(ok.message());
    ASSERT_EQ(ok->size(), 2u);
    EXPECT_EQ((*ok)[0].foot, QStringLiteral("left"));
    EXPECT_DOUBLE_EQ((*ok)[0].tStart, 1.0);
    EXPECT_DOUBLE_EQ((*ok)[0].tEnd, 3.0);
    EXPECT_EQ((*ok)[1].foot, QStringLiteral("right"));
    EXPECT_DOUBLE_EQ((*ok)[1].tEnd, 3.5);
    const auto refused = [&](const char* name, const QByteArray& text) {
        auto r = readStrideBorders(write(name, text), 100.0);
        EXPECT_FALSE(r.ok());
        return r.ok() ? QString() : r.message();
    };
    EXPECT_TRUE(refused("text.csv", "s_id,start,end,foot\n0,100,300,left\n1,1x0,300,left\n")
                    .contains(QStringLiteral("text.csv:3:2: start '1x0' is not a number")));
    EXPECT_TRUE(
        refused("short.csv", "s_id,start,end,foot\n0,100,300\n").contains(QStringLiteral("short.csv:2: 3 fields")));
    EXPECT_TRUE(refused("order.csv", "s_id,start,end,foot\n0,300,300,left\n")
                    .contains(QStringLiteral("order.csv:2:3: end 300 is not after start 300")));
    EXPECT_TRUE(
        refused("cols.csv", "a,b\n1,2\n").contains(QStringLiteral("cols.csv:1: expected columns foot, start, end")));
}
