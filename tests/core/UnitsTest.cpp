// Unit parsing/conversion (core/util/Units) and the kind table (core/model/StreamKinds).
#include "core/model/StreamKinds.h"
#include "core/util/Units.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace athlos;

namespace {

std::pair<QString, QString> split(const QString& header) {
    QString name, unit;
    splitNameAndUnit(header, name, unit);
    return {name, unit};
}

}  // namespace

TEST(Units, SplitsNameAndUnitInBracketsOrParentheses) {
    EXPECT_EQ(split("gyr_x [deg/s]"), std::make_pair(QString("gyr_x"), QString("deg/s")));
    EXPECT_EQ(split("acc_x(g)"), std::make_pair(QString("acc_x"), QString("g")));
    EXPECT_EQ(split("  mag_x ( µT ) "), std::make_pair(QString("mag_x"), QString("uT")));
    EXPECT_EQ(split("t"), std::make_pair(QString("t"), QString()));
    EXPECT_EQ(split("(g)"), std::make_pair(QString("(g)"), QString()));  // no name: not a unit
    EXPECT_EQ(split("angle(left) []"), std::make_pair(QString("angle(left)"), QString()));
}

TEST(Units, CanonicalSpellings) {
    EXPECT_EQ(canonicalUnit("m/s²"), "m/s^2");
    EXPECT_EQ(canonicalUnit("m/s2"), "m/s^2");
    EXPECT_EQ(canonicalUnit("°/s"), "deg/s");
    EXPECT_EQ(canonicalUnit("dps"), "deg/s");
    EXPECT_EQ(canonicalUnit("μT"), "uT");
    EXPECT_EQ(canonicalUnit("sec"), "s");
    EXPECT_EQ(canonicalUnit("°C"), "degC");
    EXPECT_EQ(canonicalUnit("G"), "G");  // gauss, not g: case matters
}

TEST(Units, ConvertsToSi) {
    auto check = [](const char* from, const char* to, double scale, double offset = 0.0) {
        const auto c = conversionTo(from, to);
        ASSERT_TRUE(c.ok()) << from << " → " << to << ": " << c.message().toStdString();
        EXPECT_DOUBLE_EQ(c->scale, scale) << from;
        EXPECT_DOUBLE_EQ(c->offset, offset) << from;
        EXPECT_EQ(c->si, QString(to));
    };
    check("deg/s", "rad/s", std::numbers::pi / 180.0);
    check("rpm", "rad/s", 2.0 * std::numbers::pi / 60.0);
    check("g", "m/s^2", 9.80665);
    check("mg", "m/s^2", 9.80665e-3);
    check("ms", "s", 1e-3);
    check("cm", "m", 1e-2);
    check("G", "uT", 100.0);
    check("nT", "uT", 1e-3);
    check("rad", "deg", 180.0 / std::numbers::pi);
    check("K", "degC", 1.0, -273.15);
    check("km/h", "m/s", 1.0 / 3.6);
    check("", "rad/s", 1.0);  // no unit given: already in the target
    check("rad/s", "rad/s", 1.0);
}

TEST(Units, RefusesIncompatibleAndUnknownUnits) {
    const auto wrong = conversionTo("m", "rad/s");
    ASSERT_FALSE(wrong.ok());
    EXPECT_TRUE(wrong.message().contains("'m'")) << wrong.message().toStdString();
    EXPECT_TRUE(wrong.message().contains("rad/s"));
    const auto unknown = conversionTo("furlong", "m");
    ASSERT_FALSE(unknown.ok());
    EXPECT_TRUE(unknown.message().contains("furlong"));
    EXPECT_FALSE(conversionTo("deg/s", "m/s^2").ok());
}

TEST(StreamKinds, DefaultNamesFramesAndUnits) {
    struct Expect {
        const char* kind;
        const char* name;
        const char* frame;
        bool table;
    };
    for (const auto& e :
         {Expect{"imu", "imu", "sensor", false}, Expect{"lps-position", "lps", "lps", false},
          Expect{"lps-tdoa", "tdoa", "lps", false}, Expect{"gnss", "gnss", "WGS84", false},
          Expect{"beacons", "beacons", "lps", true}, Expect{"orientation", "orientation", "ENU", false}}) {
        const StreamKind* k = findStreamKind(e.kind);
        ASSERT_NE(k, nullptr) << e.kind;
        EXPECT_EQ(k->defaultName, e.name);
        EXPECT_EQ(k->defaultFrame, e.frame);
        EXPECT_EQ(k->table, e.table);
    }
    const StreamKind* imu = findStreamKind("imu");
    EXPECT_EQ(imu->unitFor("acc_x"), "m/s^2");
    EXPECT_EQ(imu->unitFor("gyr_z"), "rad/s");
    EXPECT_EQ(imu->unitFor("mag_y"), "uT");
    EXPECT_EQ(imu->unitFor("acc_"), "");
    EXPECT_EQ(imu->unitFor("pressure"), "");
    const StreamKind* lps = findStreamKind("lps-position");
    EXPECT_EQ(lps->unitFor("x"), "m");
    EXPECT_EQ(lps->unitFor("xyz"), "");  // exact names do not act as prefixes
    EXPECT_EQ(findStreamKind("gnss")->unitFor("lat"), "deg");
    EXPECT_EQ(findStreamKind("orientation")->unitFor("qw"), "1");
    EXPECT_EQ(findStreamKind("nope"), nullptr);
    EXPECT_TRUE(streamKindNames().contains("lps-tdoa"));
}
