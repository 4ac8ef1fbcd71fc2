// Anthropometric tables (issue #18 item 1): masses renormalised to the body, lengths scaled with height,
// de Leva's Table 4 reproduced for the thigh, the thorax CoM combined from the upper and middle trunk.
#include "plugins/body/Anthropometry.h"
#include "plugins/body/BodyModel.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::body;

TEST(Anthropometry, MassesSumToOneAndLengthsScaleWithHeight) {
    for (BspTable table : {BspTable::Dumas2007, BspTable::DeLeva1996})
        for (Sex sex : {Sex::Male, Sex::Female}) {
            auto a = anthropometry(table, sex, 1.70);
            auto b = anthropometry(table, sex, 1.87);
            ASSERT_TRUE(a && b);
            double sum = 0;
            for (const SegmentParameters& s : a->segments) sum += s.massFraction;
            EXPECT_NEAR(sum, 1.0, 1e-12);
            for (int s = 0; s < kSegments; ++s) {
                EXPECT_NEAR(b->segments[s].distal.norm(), a->segments[s].distal.norm() * 1.87 / 1.70, 1e-12);
                EXPECT_NEAR(b->segments[s].com.norm(), a->segments[s].com.norm() * 1.87 / 1.70, 1e-12);
                EXPECT_DOUBLE_EQ(a->segments[s].massFraction, b->segments[s].massFraction);
            }
            // Left and right mirror each other in Z only.
            const Vec3 r = a->segments[int(Segment::RightThigh)].com, l = a->segments[int(Segment::LeftThigh)].com;
            EXPECT_DOUBLE_EQ(r.x(), l.x());
            EXPECT_DOUBLE_EQ(r.y(), l.y());
            EXPECT_DOUBLE_EQ(r.z(), -l.z());
        }
}

TEST(Anthropometry, DeLevaThighAndThoraxAtTheReferenceStature) {
    // At de Leva's male reference stature (1.741 m) the thigh is 422.2 mm with its CoM 40.95 % from the hip.
    auto a = anthropometry(BspTable::DeLeva1996, Sex::Male, 1.741);
    ASSERT_TRUE(a);
    const SegmentParameters& thigh = (*a)[Segment::RightThigh];
    EXPECT_NEAR(thigh.distal.norm(), 0.4222, 1e-9);
    EXPECT_NEAR(-thigh.com.y() / thigh.distal.norm(), 0.4095, 1e-9);
    // Thorax = upper + middle trunk: its CoM lies between the two parts' CoMs.
    const SegmentParameters& thorax = (*a)[Segment::Thorax];
    const double top = thorax.distal.y();
    EXPECT_NEAR(top, 0.1707 + 0.2155, 1e-9);
    const double fromTop = top - thorax.com.y();
    EXPECT_GT(fromTop, 0.2999 * 0.1707);
    EXPECT_LT(fromTop, 0.1707 + 0.4502 * 0.2155);
}

TEST(Anthropometry, ErrorsNameTheParameter) {
    EXPECT_TRUE(anthropometry(BspTable::Dumas2007, Sex::Male, 3.0).message().contains("height"));
    EXPECT_TRUE(parseTable("winter").message().contains("table"));
    EXPECT_TRUE(parseSex("x").message().contains("sex"));
    EXPECT_TRUE(parseSegment("tail").message().contains("tail"));
    auto list = parseSegmentList("head:1,arm:2", "equipment");
    ASSERT_FALSE(list);
    EXPECT_TRUE(list.message().contains("equipment") && list.message().contains("arm")) << list.message().toStdString();
    BodyModel m;
    m.mass = 250;
    EXPECT_TRUE(m.check().message().contains("mass"));
    m.mass = 70;
    m.height = 0.8;
    EXPECT_TRUE(m.check().message().contains("height"));
}

TEST(BodyModel, TableRoundTrip) {
    BodyModel m;
    m.height = 1.82;
    m.mass = 81;
    m.sex = Sex::Female;
    m.table = BspTable::DeLeva1996;
    m.sensor[int(Segment::Pelvis)] = "run/sacrum";
    m.position[int(Segment::Head)] = "run/gnss";
    m.equipment[int(Segment::RightFoot)] = 3.5;
    m.antennaOffset = Vec3(0.01, 0.3, 0.0);
    const athlos::Table t = bodyModelTable(m);
    EXPECT_EQ(t.rows(), kSegments);
    auto back = readBodyModel(t, "run/model");
    ASSERT_TRUE(back) << back.message().toStdString();
    EXPECT_EQ(back->height, 1.82);
    EXPECT_EQ(back->sex, Sex::Female);
    EXPECT_EQ(back->table, BspTable::DeLeva1996);
    EXPECT_EQ(back->sensor[int(Segment::Pelvis)], "run/sacrum");
    EXPECT_EQ(back->antennaSegment(), int(Segment::Head));
    EXPECT_EQ(back->equipment[int(Segment::RightFoot)], 3.5);
    EXPECT_NEAR((back->antennaOffset - m.antennaOffset).norm(), 0.0, 1e-12);
    // A missing segment row is named.
    athlos::Table cut = t;
    for (TableColumn& c : cut.columns) {
        if (c.isText)
            c.texts.removeLast();
        else
            c.numbers.pop_back();
    }
    auto missing = readBodyModel(cut, "run/model");
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.message().contains("left-foot") && missing.message().contains("run/model"))
        << missing.message().toStdString();
}
