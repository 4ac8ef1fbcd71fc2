// Venues from coordinates: the least-squares rectangle through 4 surveyed corners (lat/lon or x, y),
// its length, width, rotation and pitch frame, residuals, refusals that name the parameter, JSON.
#include "core/geometry/LocalTangentPlane.h"
#include "core/geometry/PitchGeometry.h"
#include "core/model/Project.h"

#include <Eigen/Geometry>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>
#include <random>

using athlos::GeodeticOrigin;
using athlos::LocalTangentPlane;
using athlos::PitchGeometry;
using Eigen::Vector2d;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 100.0, kWidth = 64.0;

// Corners of a true pitch (ENU), counter-clockwise from (−L/2, −W/2) in the pitch frame.
std::vector<Vector2d> trueCorners(const Vector2d& centre, double rotation, double length = kLength,
                                  double width = kWidth) {
    const Eigen::Rotation2Dd r(rotation);
    std::vector<Vector2d> c;
    for (const auto& q : {Vector2d(-1, -1), Vector2d(1, -1), Vector2d(1, 1), Vector2d(-1, 1)})
        c.push_back(centre + r * Vector2d(q.x() * length / 2, q.y() * width / 2));
    return c;
}

double angleDiff(double a, double b) { return std::abs(std::remainder(a - b, 2 * kPi)); }

}  // namespace

TEST(PitchGeometry, RecoversARotatedPitchSurveyedInLatLonWithNoise) {
    // A 100 × 64 m pitch near Munich, its x axis 35° from East, centre 180 m east and 90 m north of
    // the project's origin; corners surveyed with 5 cm (1 σ) noise per axis.
    const GeodeticOrigin origin{48.1, 11.5, 520.0};
    const LocalTangentPlane plane(origin.lat, origin.lon, origin.height);
    const double rotation = 35.0 * kPi / 180.0;
    const Vector2d centre(180.0, 90.0);
    std::mt19937 rng(13);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Vector2d> latLon, enu;
        for (const Vector2d& c : trueCorners(centre, rotation)) {
            const Vector2d n(noise(rng), noise(rng));
            const Eigen::Vector3d g = plane.toGeodetic(Eigen::Vector3d(c.x() + n.x(), c.y() + n.y(), 0.0));
            latLon.emplace_back(g.x(), g.y());
            enu.push_back(c + n);
        }
        auto pitch = PitchGeometry::fitGeodetic(latLon, origin, PitchGeometry::Kind::Football);
        ASSERT_TRUE(pitch.ok()) << qPrintable(pitch.message());
        EXPECT_NEAR(pitch->length(), kLength, 0.15);
        EXPECT_NEAR(pitch->width(), kWidth, 0.15);
        EXPECT_LT(angleDiff(pitch->rotation(), rotation), 0.003);
        EXPECT_LT((pitch->centre() - centre).norm(), 0.15);
        ASSERT_EQ(pitch->residuals().size(), 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_LT(pitch->residuals()[i], 0.25);
            // The geodetic conversion reproduces the surveyed ENU corner to well under a millimetre.
            EXPECT_LT((pitch->corners()[i] - enu[i]).norm(), 1e-3);
        }
        EXPECT_TRUE(pitch->notes().isEmpty());
    }
}

TEST(PitchGeometry, ExactCornersGiveExactRectangleAndFrame) {
    const double rotation = -1.1;
    const Vector2d centre(-12.0, 40.0);
    auto pitch = PitchGeometry::fit(trueCorners(centre, rotation), PitchGeometry::Kind::Rectangle);
    ASSERT_TRUE(pitch.ok()) << qPrintable(pitch.message());
    EXPECT_NEAR(pitch->length(), kLength, 1e-9);
    EXPECT_NEAR(pitch->width(), kWidth, 1e-9);
    EXPECT_NEAR(pitch->rotation(), rotation, 1e-12);
    EXPECT_LT(pitch->maxResidual(), 1e-9);
    // Pitch frame: origin at the centre spot, x along the length, y across, right-handed.
    EXPECT_LT(pitch->toPitch(centre).norm(), 1e-9);
    const auto corners = trueCorners(centre, rotation);
    EXPECT_LT((pitch->toPitch(corners[1]) - Vector2d(kLength / 2, -kWidth / 2)).norm(), 1e-9);
    EXPECT_LT((pitch->toPitch(corners[3]) - Vector2d(-kLength / 2, kWidth / 2)).norm(), 1e-9);
    EXPECT_LT((pitch->toEnu(pitch->toPitch({3.0, -7.0})) - Vector2d(3.0, -7.0)).norm(), 1e-12);
    // y is x turned 90° counter-clockwise.
    const Vector2d ex = pitch->toEnu({1, 0}) - pitch->toEnu({0, 0}), ey = pitch->toEnu({0, 1}) - pitch->toEnu({0, 0});
    EXPECT_NEAR(ex.x() * ey.y() - ex.y() * ey.x(), 1.0, 1e-12);
}

TEST(PitchGeometry, AnyCyclicOrderAndDirectionGiveTheSamePitch) {
    const auto c = trueCorners({5.0, 5.0}, 0.3);
    // Start at any corner, counter-clockwise or clockwise; the length is the longer side even when
    // the first side given is the short one.
    const std::vector<std::array<int, 4>> orders = {{0, 1, 2, 3}, {1, 2, 3, 0}, {2, 3, 0, 1}, {3, 0, 1, 2},
                                                    {0, 3, 2, 1}, {3, 2, 1, 0}, {1, 0, 3, 2}, {2, 1, 0, 3}};
    for (const auto& o : orders) {
        auto pitch = PitchGeometry::fit({c[o[0]], c[o[1]], c[o[2]], c[o[3]]}, PitchGeometry::Kind::Rugby);
        ASSERT_TRUE(pitch.ok()) << qPrintable(pitch.message());
        EXPECT_NEAR(pitch->length(), kLength, 1e-9);
        EXPECT_NEAR(pitch->width(), kWidth, 1e-9);
        // rotation in (−π/2, π/2]: +x towards the end nearer East.
        EXPECT_NEAR(pitch->rotation(), 0.3, 1e-12);
    }
    // A pitch whose length runs north-west: rotation folded into (−π/2, π/2].
    auto nw = PitchGeometry::fit(trueCorners({0, 0}, 2.5), PitchGeometry::Kind::Rectangle);
    ASSERT_TRUE(nw.ok());
    EXPECT_NEAR(nw->rotation(), 2.5 - kPi, 1e-12);
}

TEST(PitchGeometry, ClosedFormIsTheLeastSquaresOptimum) {
    // Sum of squared distances of the corners to the nearest corner of a rectangle (centre, rotation, L, W).
    auto cost = [](const std::vector<Vector2d>& c, const Vector2d& centre, double rotation, double length,
                   double width) {
        const Eigen::Rotation2Dd r(rotation);
        double sum = 0.0;
        for (const Vector2d& p : c) {
            double best = 1e300;
            for (const auto& q : {Vector2d(-1, -1), Vector2d(1, -1), Vector2d(1, 1), Vector2d(-1, 1)})
                best = std::min(best, (p - centre - r * Vector2d(q.x() * length / 2, q.y() * width / 2)).squaredNorm());
            sum += best;
        }
        return sum;
    };
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.3);
    for (int trial = 0; trial < 10; ++trial) {
        auto c = trueCorners({3.0, -4.0}, 0.2 + 0.1 * trial);
        for (auto& p : c) p += Vector2d(noise(rng), noise(rng));
        PitchGeometry::Params params;
        params.maxResidual = 3.0;
        auto pitch = PitchGeometry::fit(c, PitchGeometry::Kind::Rectangle, params);
        ASSERT_TRUE(pitch.ok()) << qPrintable(pitch.message());
        const double best = cost(c, pitch->centre(), pitch->rotation(), pitch->length(), pitch->width());
        double reported = 0.0;
        for (double r : pitch->residuals()) reported += r * r;
        EXPECT_NEAR(best, reported, 1e-9);  // the residuals are those of the fit
        // Every step of any of the 5 parameters costs more.
        for (const double h : {-1e-3, 1e-3}) {
            EXPECT_GT(cost(c, pitch->centre() + Vector2d(h, 0), pitch->rotation(), pitch->length(), pitch->width()),
                      best);
            EXPECT_GT(cost(c, pitch->centre() + Vector2d(0, h), pitch->rotation(), pitch->length(), pitch->width()),
                      best);
            EXPECT_GT(cost(c, pitch->centre(), pitch->rotation() + h, pitch->length(), pitch->width()), best);
            EXPECT_GT(cost(c, pitch->centre(), pitch->rotation(), pitch->length() + h, pitch->width()), best);
            EXPECT_GT(cost(c, pitch->centre(), pitch->rotation(), pitch->length(), pitch->width() + h), best);
        }
    }
    // One corner surveyed 40 cm long: the error is spread over the fit (length +0.2 m), every residual
    // is below the displacement.
    auto c = trueCorners({0, 0}, 0.0);
    c[2] += Vector2d(0.4, 0.0);
    auto pitch = PitchGeometry::fit(c, PitchGeometry::Kind::Football);
    ASSERT_TRUE(pitch.ok());
    EXPECT_NEAR(pitch->length(), kLength + 0.2, 1e-3);
    EXPECT_NEAR(pitch->width(), kWidth, 1e-3);
    for (double r : pitch->residuals()) EXPECT_LT(r, 0.2);
}

TEST(PitchGeometry, RefusesWhatIsNotNearARectangle) {
    // A kite: corner 3 is 6 m off.
    auto kite = trueCorners({0, 0}, 0.2);
    kite[2] += Vector2d(6.0, 3.0);
    auto r = PitchGeometry::fit(kite, PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("max_residual 1 m")) << qPrintable(r.message());
    EXPECT_TRUE(r.message().contains("not near a rectangle")) << qPrintable(r.message());
    // The same kite passes with a generous tolerance.
    PitchGeometry::Params loose;
    loose.maxResidual = 5.0;
    EXPECT_TRUE(PitchGeometry::fit(kite, PitchGeometry::Kind::Rectangle, loose).ok());

    // A bow-tie: two corners swapped, the outline crosses itself.
    const auto c = trueCorners({0, 0}, 0.2);
    r = PitchGeometry::fit({c[0], c[2], c[1], c[3]}, PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("crosses itself")) << qPrintable(r.message());

    // Not convex (a dart).
    r = PitchGeometry::fit({Vector2d(0, 0), Vector2d(100, 0), Vector2d(20, 10), Vector2d(0, 60)},
                           PitchGeometry::Kind::Rectangle);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("not convex at corner 3")) << qPrintable(r.message());

    // Degenerate: a sliver.
    r = PitchGeometry::fit(trueCorners({0, 0}, 0.0, 100.0, 2.0), PitchGeometry::Kind::Rectangle);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("min_side 5 m")) << qPrintable(r.message());
}

TEST(PitchGeometry, RefusesBadInputNamingTheParameter) {
    const auto c = trueCorners({0, 0}, 0.0);
    auto r = PitchGeometry::fit({c[0], c[1], c[2]}, PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("corners: a pitch needs 4 corners, got 3")) << qPrintable(r.message());
    r = PitchGeometry::fit({c[0], c[1], Vector2d(std::nan(""), 0), c[3]}, PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("corner 3 is not a finite point")) << qPrintable(r.message());
    PitchGeometry::Params bad;
    bad.maxResidual = -1;
    r = PitchGeometry::fit(c, PitchGeometry::Kind::Football, bad);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("max_residual")) << qPrintable(r.message());
    r = PitchGeometry::fitGeodetic({{48.1, 11.5}, {48.1, 11.501}, {95.0, 11.501}, {48.101, 11.5}}, {48.1, 11.5, 0},
                                   PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("corner 3 (95, 11.501): latitude must be in [-90, 90]"))
        << qPrintable(r.message());
    r = PitchGeometry::fitGeodetic({{8.1, 11.5}, {8.1, 11.501}, {8.101, 11.501}, {8.101, 11.5}}, {48.1, 11.5, 0},
                                   PitchGeometry::Kind::Football);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("km from the project's geodetic origin")) << qPrintable(r.message());

    auto parsed = PitchGeometry::parseCorners(" 1,2 ; 3,4;5,6;7,8 ", "--corners-xy");
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ((*parsed)[3], Vector2d(7, 8));
    parsed = PitchGeometry::parseCorners("1,2;3,4;5,6", "--corners");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.message(), QStringLiteral("--corners: expected 4 corners separated by ';', got 3"));
    parsed = PitchGeometry::parseCorners("1,2;3,x;5,6;7,8", "--corners");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.message(), QStringLiteral("--corners: corner 2 '3,x' is not a pair of numbers A,B"));
}

TEST(PitchGeometry, NotesDimensionsOutsideTheLaws) {
    auto small = PitchGeometry::fit(trueCorners({0, 0}, 0.0, 60.0, 40.0), PitchGeometry::Kind::Football);
    ASSERT_TRUE(small.ok());
    ASSERT_EQ(small->notes().size(), 2);
    EXPECT_TRUE(small->notes()[0].contains("length 60.0 m is outside IFAB Law 1 (90-120 m)"))
        << qPrintable(small->notes()[0]);
    auto rect = PitchGeometry::fit(trueCorners({0, 0}, 0.0, 60.0, 40.0), PitchGeometry::Kind::Rectangle);
    EXPECT_TRUE(rect->notes().isEmpty());
}

TEST(PitchGeometry, JsonRoundTripAndProjectStore) {
    const GeodeticOrigin origin{-27.2, 153.05, 4.0};
    const LocalTangentPlane plane(origin.lat, origin.lon, origin.height);
    std::vector<Vector2d> latLon;
    for (const Vector2d& c : trueCorners({30, -20}, 0.7)) {
        const Eigen::Vector3d g = plane.toGeodetic(Eigen::Vector3d(c.x(), c.y(), 0.0));
        latLon.emplace_back(g.x(), g.y());
    }
    auto pitch = PitchGeometry::fitGeodetic(latLon, origin, PitchGeometry::Kind::Rugby, {}, "main");
    ASSERT_TRUE(pitch.ok()) << qPrintable(pitch.message());
    const QJsonObject json = pitch->toJson();
    EXPECT_EQ(json.value("type").toString(), "pitch");
    EXPECT_EQ(json.value("units").toObject().value("rotation").toString(), "rad");
    EXPECT_EQ(json.value("frame").toString(), "enu");
    EXPECT_EQ(json.value("pitch_frame").toString(), "pitch");

    QTemporaryDir dir;
    {
        auto project = athlos::Project::create(dir.filePath("p.athlos"));
        project->geometry()["main"] = json;
        ASSERT_TRUE(project->save().ok());
    }
    auto reopened = athlos::Project::open(dir.filePath("p.athlos"));
    ASSERT_TRUE(reopened.ok());
    auto back = PitchGeometry::firstOf((*reopened)->geometry());
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->name(), "main");
    EXPECT_EQ(back->kind(), PitchGeometry::Kind::Rugby);
    EXPECT_DOUBLE_EQ(back->length(), pitch->length());
    EXPECT_DOUBLE_EQ(back->width(), pitch->width());
    EXPECT_DOUBLE_EQ(back->rotation(), pitch->rotation());
    EXPECT_EQ(back->centre(), pitch->centre());
    EXPECT_EQ(back->residuals(), pitch->residuals());
    EXPECT_EQ(back->cornersGeodetic(), latLon);
    EXPECT_EQ(back->toJson(), json);

    QJsonObject broken = json;
    broken.insert("kind", "cricket");
    EXPECT_TRUE(
        PitchGeometry::fromJson(broken).message().contains("kind 'cricket' is not one of football, rugby, rectangle"));
    broken = json;
    broken.insert("length", -3);
    EXPECT_TRUE(PitchGeometry::fromJson(broken).message().contains("length and width must be positive"));
}
