// Beacon geometry checks (BeaconGeometry.h, issue #16 item 3) and their use in lps-calibration: a
// venue is observable; clustered, collinear and coplanar layouts are named; the calibration refuses
// 4 anchors inside a 2 m box (geometry_check=refuse) and reports a coplanar layout.
#include "plugins/lps/BeaconGeometry.h"
#include "plugins/lps/LpsCalibration.h"
#include "plugins/lps/TdoaSimulator.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::lps;

namespace {

std::vector<Vector3> trackArea() {
    std::vector<Vector3> area;
    for (const auto& s : TdoaSimulator::laps(TrackGeometry(), 0.3, 5.0, 1.0, 1.0, 1.0)) area.push_back(s.position);
    return area;
}

BeaconLayout boxOfFour() {
    BeaconLayout layout;
    const Vector3 corner(20.0, 45.0, 3.0);
    for (int i = 0; i < 4; ++i) {
        layout.ids << QString::number(i + 1);
        layout.positions.push_back(corner + Vector3(2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 0.5 * i));
    }
    return layout;
}

}  // namespace

TEST(BeaconGeometry, SimulatedVenueIsObservable) {
    TdoaSimulator sim(TdoaSimulator::Params(), 5);
    const BeaconLayout venue = sim.venue(VenueParams(), TrackGeometry());
    const auto r = assessBeaconGeometry(venue.positions, trackArea());
    EXPECT_TRUE(r.observable2d());
    EXPECT_TRUE(r.observable3d()) << r.reason().toStdString();
    EXPECT_TRUE(r.problems.isEmpty());
    EXPECT_GT(r.spreadMinor, 20.0);
    EXPECT_LT(r.dilution, 10.0);
}

TEST(BeaconGeometry, NamesClusteredCollinearAndCoplanarLayouts) {
    const auto box = assessBeaconGeometry(boxOfFour().positions, trackArea());
    EXPECT_TRUE(box.clustered);
    EXPECT_FALSE(box.observable2d());
    EXPECT_TRUE(box.reason().contains("clustered")) << box.reason().toStdString();
    // Without an area only the absolute limit applies (horizontal σ < 1 m):
    const auto tinyBox = assessBeaconGeometry({{0, 0, 3}, {0.5, 0, 4}, {0, 0.5, 5}, {0.5, 0.5, 3.5}});
    EXPECT_TRUE(tinyBox.clustered);

    std::vector<Vector3> line;
    for (int i = 0; i < 6; ++i) line.emplace_back(-60.0 + 24.0 * i, 0.05 * i, 3.0 + i);
    const auto collinear = assessBeaconGeometry(line, trackArea());
    EXPECT_TRUE(collinear.collinear);
    EXPECT_FALSE(collinear.clustered);
    EXPECT_TRUE(collinear.reason().contains("collinear"));

    TdoaSimulator sim(TdoaSimulator::Params(), 6);
    BeaconLayout flat = sim.venue(VenueParams(), TrackGeometry());
    for (auto& b : flat.positions) b.z() = 5.0;
    const auto coplanar = assessBeaconGeometry(flat.positions, trackArea());
    EXPECT_TRUE(coplanar.coplanar);
    EXPECT_TRUE(coplanar.observable2d());
    EXPECT_FALSE(coplanar.observable3d());
    EXPECT_TRUE(coplanar.reason().contains("coplanar"));

    const auto three = assessBeaconGeometry({{0, 0, 3}, {50, 0, 4}, {0, 50, 5}});
    EXPECT_TRUE(three.tooFew);
    EXPECT_FALSE(three.observable2d());
}

TEST(BeaconGeometry, DopGrowsWithDistanceFromTheBeacons) {
    const std::vector<Vector3> square = {{-30, -30, 5}, {30, -30, 6}, {30, 30, 4}, {-30, 30, 7}, {0, 40, 3}};
    const double inside = tdoaDop(square, Vector3(0, 0, 1), true);
    const double far = tdoaDop(square, Vector3(3000, 0, 1), true);
    EXPECT_GT(inside, 0.5);
    EXPECT_LT(inside, 3.0);
    EXPECT_GT(far, 50.0 * inside);
    // Worked example: 4 beacons on the axes at equal distance, tag at the centre, planar. Rows
    // (±1, 0, −1), (0, ±1, −1): HᵀH = diag(2, 2, 4), position block of the inverse diag(½, ½) → DOP 1.
    const std::vector<Vector3> cross = {{10, 0, 0}, {-10, 0, 0}, {0, 10, 0}, {0, -10, 0}};
    EXPECT_NEAR(tdoaDop(cross, Vector3::Zero(), true), 1.0, 1e-12);
    // 3D with all beacons in the tag's plane: the height is not observable.
    EXPECT_FALSE(std::isfinite(tdoaDop(cross, Vector3::Zero(), false)));
}

TEST(LpsCalibrationGeometry, RefusesFourAnchorsInATwoMetreBox) {
    const TrackGeometry track;
    const BeaconLayout box = boxOfFour();
    TdoaSimulator sim(TdoaSimulator::Params(), 9);
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, 1.0), box);
    auto refused = LpsCalibration().run(walk.epochs, box);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains("clustered")) << refused.message().toStdString();
    EXPECT_TRUE(refused.message().contains("geometry_check=warn"));

    LpsCalibration::Params warn;
    warn.geometryCheck = LpsCalibration::GeometryCheck::Warn;
    auto kept = LpsCalibration(warn).run(walk.epochs, box);
    // Either it fails for another reason, or it says why the result cannot be trusted.
    if (kept.ok()) {
        EXPECT_TRUE(kept->report.geometryWarning.contains("clustered"));
    }
}

TEST(LpsCalibrationGeometry, CoplanarBeaconsAreCalibratedWithAWarning) {
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 11);
    BeaconLayout flat = sim.venue(VenueParams(), track);
    for (auto& b : flat.positions) b.z() = 5.0;
    const BeaconLayout guess = sim.perturb(flat, {1.0, 0.5});
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, 1.0), flat);
    auto result = LpsCalibration().run(walk.epochs, guess);
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    EXPECT_TRUE(result->report.geometry.observable2d());
    EXPECT_TRUE(result->report.geometryWarning.contains("coplanar")) << result->report.geometryWarning.toStdString();
}

TEST(BeaconGeometry, ToaDopOfASquareAndOfAFarCluster) {
    using athlos::lps::toaDop;
    using athlos::lps::Vector3;
    // Tag in the middle of a square at its height: HᵀH = 2 I, DOP = √(½ + ½) = 1.
    const std::vector<Vector3> square = {{-5, -5, 1}, {5, -5, 1}, {5, 5, 1}, {-5, 5, 1}};
    EXPECT_NEAR(toaDop(square, {0, 0, 1}, true), 1.0, 1e-12);
    // Four anchors in a 2 m box seen from 50 m: the bearing is barely observable.
    const std::vector<Vector3> cluster = {{0.7, 0.9, 0.5}, {2.6, 0.9, 2.0}, {2.6, -0.9, 2.0}, {2.6, -0.9, 0.5}};
    EXPECT_GT(toaDop(cluster, {50, 0, 1}, true), 15.0);
    EXPECT_LT(toaDop(cluster, {5, 0, 1}, true), 5.0);
}
