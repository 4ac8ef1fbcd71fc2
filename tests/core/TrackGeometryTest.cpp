// Track geometry: World Athletics 400 m oval, 200 m indoor, polylines, pose, JSON, gradients.
#include "core/geometry/TrackGeometry.h"
#include "core/math/Angles.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using athlos::TrackGeometry;
using athlos::TrackPose;
using Eigen::Vector2d;

namespace {
double angleDiff(double a, double b) { return std::abs(athlos::math::wrapAngle(a - b)); }
}  // namespace

TEST(TrackGeometry, Iaaf400mLapLengthsAndLanes) {
    const TrackGeometry t = TrackGeometry::iaaf400m();
    EXPECT_DOUBLE_EQ(t.laneOffset(1), 0.30);
    EXPECT_NEAR(t.laneOffset(2), 1.22 + 0.20, 1e-12);
    EXPECT_NEAR(t.laneLength(1), 400.0, 0.005);  // 2·84.39 + 2π·36.80
    EXPECT_NEAR(t.laneLength(2) - t.laneLength(1), 2 * std::numbers::pi * (1.42 - 0.30), 1e-9);
    EXPECT_NEAR(t.referenceLength(), 2 * 84.39 + 2 * std::numbers::pi * 36.5, 1e-9);
    EXPECT_NEAR(TrackGeometry::indoor200m().laneLength(1), 200.0, 1e-9);
}

TEST(TrackGeometry, HeadingOnStraightsAndBends) {
    const TrackGeometry t = TrackGeometry::iaaf400m();
    EXPECT_NEAR(t.headingAt({0, -36.8}), 0.0, 1e-12);                               // home straight towards +x
    EXPECT_NEAR(angleDiff(t.headingAt({10, 36.8}), std::numbers::pi), 0.0, 1e-12);  // back straight
    EXPECT_DOUBLE_EQ(t.curvatureAt({0, -36.8}), 0.0);
    // Bend 1 (centre (42.195, 0)): tangent of a counter-clockwise circle, curvature 1/ρ.
    for (double a : {-1.2, -0.3, 0.0, 0.7, 1.5}) {
        const Vector2d p = Vector2d(42.195, 0) + 37.0 * Vector2d(std::cos(a), std::sin(a));
        EXPECT_NEAR(angleDiff(t.headingAt(p), a + std::numbers::pi / 2), 0.0, 1e-12);
        EXPECT_NEAR(t.curvatureAt(p), 1.0 / 37.0, 1e-12);
        EXPECT_NEAR(t.query(p).d, 0.5, 1e-12);
    }
    const Vector2d p2 = Vector2d(-42.195, 0) + 38.0 * Vector2d(std::cos(2.5), std::sin(2.5));
    EXPECT_NEAR(angleDiff(t.headingAt(p2), 2.5 + std::numbers::pi / 2), 0.0, 1e-12);
}

TEST(TrackGeometry, ArcLengthRoundTripAndPose) {
    TrackGeometry t = TrackGeometry::iaaf400m();
    t.setPose({12.0, -5.0, 0.4});
    for (double s = 0.5; s < t.referenceLength(); s += 17.3) {
        const auto pt = t.pointAt(s, 1.1);
        const auto q = t.query(pt.position);
        EXPECT_NEAR(q.s, s, 1e-9);
        EXPECT_NEAR(q.d, 1.1, 1e-9);
        EXPECT_NEAR(angleDiff(q.heading, pt.heading), 0.0, 1e-9);
        EXPECT_NEAR(q.curvature, pt.curvature, 1e-12);
    }
    // Finish line (s = 0) is at the end of the home straight, rotated and shifted by the pose.
    const Vector2d finish = t.pointAt(0.0, 0.0).position;
    const Vector2d expected = Eigen::Rotation2Dd(0.4) * Vector2d(42.195, -36.5) + Vector2d(12, -5);
    EXPECT_LT((finish - expected).norm(), 1e-9);
    EXPECT_LT((t.toTrack(t.toLps({3, 4})) - Vector2d(3, 4)).norm(), 1e-12);
    EXPECT_NEAR(t.headingAt(t.toLps({0, -36.8})), 0.4, 1e-12);
}

TEST(TrackGeometry, GradientsMatchNumericDifferentiation) {
    TrackGeometry t = TrackGeometry::iaaf400m();
    t.setPose({1.0, 2.0, -0.7});
    const double h = 1e-6;
    for (const Vector2d& local : {Vector2d(60, -20), Vector2d(-70, 15), Vector2d(0, -37)}) {
        const Vector2d p = t.toLps(local);
        const auto q = t.field(p);
        for (int i = 0; i < 2; ++i) {
            const Vector2d e = Vector2d::Unit(i) * h;
            const double dh = athlos::math::wrapAngle(t.headingAt(p + e) - t.headingAt(p - e)) / (2 * h);
            const double dk = (t.curvatureAt(p + e) - t.curvatureAt(p - e)) / (2 * h);
            EXPECT_NEAR(q.headingGradient[i], dh, 1e-6);
            EXPECT_NEAR(q.curvatureGradient[i], dk, 1e-8);
        }
        EXPECT_NEAR(q.heading, t.query(p).heading, 1e-15);
    }
}

TEST(TrackGeometry, PolylineNearestSegmentHeading) {
    TrackGeometry::PolylineParams p;
    p.points = {{0, 0}, {100, 0}, {100, 50}, {0, 50}};
    p.closed = true;
    const TrackGeometry t = TrackGeometry::polyline(p, QStringLiteral("square"));
    EXPECT_NEAR(t.referenceLength(), 300.0, 1e-12);
    EXPECT_NEAR(t.headingAt({50, 1}), 0.0, 1e-12);
    EXPECT_NEAR(t.headingAt({99, 25}), std::numbers::pi / 2, 1e-12);
    EXPECT_NEAR(angleDiff(t.headingAt({50, 49}), std::numbers::pi), 0.0, 1e-12);
    EXPECT_NEAR(t.headingAt({1, 25}), -std::numbers::pi / 2, 1e-12);
    const auto q = t.query({50, -2});
    EXPECT_NEAR(q.s, 50.0, 1e-12);
    EXPECT_NEAR(q.d, 2.0, 1e-12);  // right of the running direction
    EXPECT_GT(q.curvature, -1e-12);
    EXPECT_NEAR(t.pointAt(150.0, 0).position.x(), 100.0, 1e-12);
}

TEST(TrackGeometry, JsonRoundTripAndResolve) {
    TrackGeometry t = TrackGeometry::indoor200m();
    t.setPose({3, 4, 0.5});
    const auto back = TrackGeometry::fromJson(t.toJson());
    ASSERT_TRUE(back.ok()) << back.message().toStdString();
    EXPECT_NEAR(back->laneLength(1), 200.0, 1e-9);
    EXPECT_NEAR(back->pose().rotation, 0.5, 0);
    EXPECT_NEAR(back->headingAt(t.toLps({0, -18})), 0.5, 1e-12);

    TrackGeometry::PolylineParams p;
    p.points = {{0, 0}, {10, 0}, {20, 10}};
    const auto poly = TrackGeometry::fromJson(TrackGeometry::polyline(p, QStringLiteral("road")).toJson());
    ASSERT_TRUE(poly.ok());
    EXPECT_EQ(poly->kind(), TrackGeometry::Kind::Polyline);
    EXPECT_NEAR(poly->headingAt({15, 6}), std::numbers::pi / 4, 1e-12);

    std::map<QString, QJsonObject> project{{QStringLiteral("velodrome"), poly->toJson()}};
    EXPECT_TRUE(TrackGeometry::resolve(project, QStringLiteral("velodrome")).ok());
    EXPECT_TRUE(TrackGeometry::resolve(project, QStringLiteral("iaaf-400m")).ok());
    const auto missing = TrackGeometry::resolve(project, QStringLiteral("nowhere"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains(QStringLiteral("nowhere")));
    EXPECT_TRUE(missing.message().contains(QStringLiteral("velodrome")));
    EXPECT_FALSE(TrackGeometry::fromJson(QJsonObject{{QStringLiteral("type"), QStringLiteral("blob")}}).ok());
}
