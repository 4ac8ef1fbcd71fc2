// Tracks placed like pitches: an oval by the two ends of its home straight (start, finish) in the
// project's ENU frame, a polyline by its points; refusals name the parameter.
#include "core/geometry/TrackPlacement.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <cmath>

using athlos::TrackGeometry;
using Eigen::Vector2d;

TEST(TrackPlacement, OvalPoseFromTheHomeStraight) {
    TrackGeometry truth = TrackGeometry::iaaf400m();
    truth.setPose({12.0, -5.0, 0.4});
    const auto& o = truth.ovalParams();
    // The kerb ends of the home straight (track frame y = −r), surveyed 3 cm long at the finish.
    const Vector2d a = truth.toLps({-o.straightLength / 2, -o.kerbRadius});
    const Vector2d b = truth.toLps({o.straightLength / 2 + 0.03, -o.kerbRadius});
    auto placed = athlos::placeOval(TrackGeometry::iaaf400m(), a, b, 0.5);
    ASSERT_TRUE(placed.ok()) << qPrintable(placed.message());
    EXPECT_NEAR(placed->track.pose().rotation, 0.4, 1e-12);
    EXPECT_NEAR(placed->track.pose().x, 12.0 + 0.015 * std::cos(0.4), 1e-9);
    EXPECT_NEAR(placed->track.pose().y, -5.0 + 0.015 * std::sin(0.4), 1e-9);
    EXPECT_NEAR(placed->residuals[0], 0.015, 1e-9);
    // The finish line (s = 0) is where it was surveyed, to the residual.
    EXPECT_LT((placed->track.pointAt(0.0, 0.0).position - b).norm(), 0.02);

    // Stored as a track document (athlos venue adds frame, units and the surveyed points), a
    // processor's `track` parameter resolves it with its pose.
    QJsonObject doc = placed->track.toJson();
    doc.insert("name", "track");
    doc.insert("frame", "enu");
    auto resolved = TrackGeometry::resolve({{"track", doc}}, "track");
    ASSERT_TRUE(resolved.ok()) << qPrintable(resolved.message());
    EXPECT_NEAR(resolved->pose().rotation, 0.4, 1e-12);
    EXPECT_LT((resolved->pointAt(0.0, 0.0).position - b).norm(), 0.02);

    auto refused = athlos::placeOval(TrackGeometry::iaaf400m(), a, a + Vector2d(70.0, 0.0), 1.0);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains("the home straight of 'iaaf-400m' is 84.39 m"))
        << qPrintable(refused.message());
    EXPECT_TRUE(refused.message().contains("max_residual 1 m")) << qPrintable(refused.message());
    EXPECT_FALSE(athlos::placeOval(TrackGeometry::iaaf400m(), a, a, 1.0).ok());
}

TEST(TrackPlacement, PolylineFromPoints) {
    auto placed = athlos::placePolyline({{0, 0}, {100, 0}, {100, 50}}, true, "loop");
    ASSERT_TRUE(placed.ok());
    EXPECT_EQ(placed->track.kind(), TrackGeometry::Kind::Polyline);
    EXPECT_NEAR(placed->track.referenceLength(), 100.0 + 50.0 + std::hypot(100.0, 50.0), 1e-9);
    EXPECT_TRUE(
        athlos::placePolyline({{0, 0}}, false, "x").message().contains("points: a polyline needs at least 2 points"));
    EXPECT_TRUE(
        athlos::placePolyline({{0, 0}, {0, 0}}, false, "x").message().contains("points: points 1 and 2 coincide"));
}
