// IMU calibration: magnetometer ellipsoid fit, six-position accelerometer calibration, static
// segments, saturation, and the plausibility of the result.
#include "core/processing/ProcessorRunner.h"
#include "plugins/inertial/CalibrationPlausibility.h"
#include "plugins/inertial/ImuCalibration.h"
#include "plugins/inertial/ImuCalibrationProcessor.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <random>

using namespace athlos::inertial;

TEST(ImuCalibration, EllipsoidFitRecoversHardAndSoftIron) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n;
    Mat3 soft;  // symmetric distortion
    soft << 1.10, 0.05, -0.03, 0.05, 0.92, 0.02, -0.03, 0.02, 1.04;
    const Vec3 hard(12.0, -30.0, 5.0);
    std::vector<Vec3> samples;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 dir = Vec3(n(rng), n(rng), n(rng)).normalized();
        samples.push_back(soft * (48.0 * dir) + hard + 0.2 * Vec3(n(rng), n(rng), n(rng)));
    }
    const auto c = calibrateMagnetometer(samples);
    ASSERT_TRUE(c.has_value());
    EXPECT_LT((c->hardIron - hard).norm(), 0.2);
    const Mat3 product = c->softIron * soft / (c->radius / 48.0);  // A·S ∝ I
    EXPECT_LT((product - Mat3::Identity()).norm(), 0.01) << product;
    EXPECT_NEAR(c->radius, 48.0 * std::cbrt(soft.determinant()), 0.5);
    EXPECT_LT(c->rms, 0.3);
}

TEST(ImuCalibration, SixPositionRecoversOffsetAndScale) {
    const Vec3 offset(0.15, -0.2, 0.08), scale(1.02, 0.97, 1.01);
    std::vector<Vec3> means;
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {1.0, -1.0}) {
            Vec3 a = Vec3::Zero();
            a[axis] = s * 9.81;
            means.push_back(scale.cwiseProduct(a) + offset);
        }
    const auto c = calibrateAccelerometer(means, 9.81);
    ASSERT_TRUE(c.has_value());
    EXPECT_LT((c->offset - offset).norm(), 1e-6);
    EXPECT_LT((c->scale - scale).norm(), 1e-7);
    means.pop_back();  // z never points down any more: refuse
    means.push_back(means.front());
    EXPECT_FALSE(calibrateAccelerometer(means, 9.81).has_value());
}

TEST(ImuCalibration, StaticSegmentsAndGyroOffset) {
    // 3 s rest, 2 s rotation, 6 s rest at 100 Hz with a gyro offset.
    const Vec3 gyrOffset(0.01, -0.02, 0.005);
    std::vector<double> v;
    for (int k = 0; k < 1100; ++k) {
        const bool moving = k >= 300 && k < 500;
        const Vec3 g = gyrOffset + (moving ? Vec3(0, 0, 2.0) : Vec3::Zero());
        const Vec3 a(0, 0, 9.81);
        v.insert(v.end(), a.data(), a.data() + 3);
        v.insert(v.end(), g.data(), g.data() + 3);
    }
    const ImuBatch b{v.data() + 3, v.data(), nullptr, 1100, 6};
    const auto segments = findStaticSegments(b, 0.01, 1.5);
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_LT((segments[0].gyr - gyrOffset).norm(), 1e-12);
    EXPECT_LE(segments[0].end, 300u);
    EXPECT_GE(segments[1].begin, 500u);
}

TEST(ImuCalibration, SaturationCount) {
    std::vector<double> v{1, 2, 3, 16, 0, 0, 16, 0, 0, 16, 0, 0, 5, 0, 0};
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 0.0)[0], 3);  // clipped run at the extreme
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 16.0)[0], 3);
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 0.0)[1], 0);
}

TEST(ImuCalibration, EllipsoidFitRefusesPlanarCoverage) {
    std::vector<Vec3> ring;  // turning about the vertical only
    for (int i = 0; i < 500; ++i) {
        const double a = 0.05 * i;
        ring.emplace_back(20.0 * std::cos(a) + 5.0, 20.0 * std::sin(a), -44.0);
    }
    EXPECT_FALSE(calibrateMagnetometer(ring).has_value());
}

// --- Plausibility of the result (issue #13 item 8, CalibrationPlausibility.h) ---------------------

namespace {

// A sensor turned through every direction (a Fibonacci spiral over the sphere, 100 Hz, never at
// rest) in a field of `field` µT with a hard-iron offset, written as `scale` × the true values into
// columns declared in µT (scale 10: a milligauss magnetometer imported as µT).
athlos::Stream turningImu(double field, double scale) {
    const std::size_t n = 2000;
    athlos::StreamInfo info;
    info.kind = QStringLiteral("imu");
    for (const char* c : {"acc_x", "acc_y", "acc_z"})
        info.columns.push_back({QString::fromLatin1(c), QStringLiteral("m/s^2")});
    for (const char* c : {"gyr_x", "gyr_y", "gyr_z"})
        info.columns.push_back({QString::fromLatin1(c), QStringLiteral("rad/s")});
    for (const char* c : {"mag_x", "mag_y", "mag_z"})
        info.columns.push_back({QString::fromLatin1(c), QStringLiteral("uT")});
    athlos::StreamData d(n, 9);
    const Vec3 hard(8.0, -5.0, 3.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double z = 1.0 - 2.0 * (double(k) + 0.5) / double(n),
                     phi = 2.399963229728653 * double(k);  // golden angle
        const Vec3 u(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
        d.t[k] = 0.01 * double(k);
        const Vec3 a = 9.81 * u.cross(Vec3::UnitX()).normalized(), g(1.0, -0.5, 0.8), m = scale * (field * u + hard);
        for (int i = 0; i < 3; ++i) {
            d.at(k, i) = a[i];
            d.at(k, 3 + i) = g[i];
            d.at(k, 6 + i) = m[i];
        }
    }
    return athlos::Stream(std::move(info), std::move(d));
}

athlos::Expected<athlos::RunOutcome> calibrate(athlos::Project& project, QVariantMap params = {}) {
    const ImuCalibrationProcessor p;
    return athlos::runProcessor(
        project, p, athlos::RunRequest{p.id(), {QStringLiteral("rec/imu")}, QStringLiteral("rec/cal"), params});
}

}  // namespace

TEST(ImuCalibrationPlausibility, EarthFieldIsAccepted) {
    QTemporaryDir dir;
    auto project = athlos::Project::create(dir.filePath(QStringLiteral("p.athlos")));
    project->putStream(QStringLiteral("rec/imu"), turningImu(48.0, 1.0));
    const auto outcome = calibrate(*project);
    ASSERT_TRUE(outcome.ok()) << outcome.message().toStdString();
    const athlos::Table* table = project->table(QStringLiteral("rec/cal-calibration"));
    ASSERT_NE(table, nullptr);
    EXPECT_NEAR(table->attributes.value(QStringLiteral("mag_field_median")).toDouble(), 48.0, 0.5);
    EXPECT_FALSE(table->attributes.contains(QStringLiteral("implausible")));
}

TEST(ImuCalibrationPlausibility, FieldOutsideTheGeomagneticRangeIsRefused) {
    QTemporaryDir dir;
    auto project = athlos::Project::create(dir.filePath(QStringLiteral("p.athlos")));
    project->putStream(QStringLiteral("rec/imu"), turningImu(48.0, 10.0));  // mG read as µT: 480 "µT"
    project->setModified(false);
    const auto outcome = calibrate(*project);
    ASSERT_FALSE(outcome.ok());
    EXPECT_TRUE(
        outcome.message().startsWith("imu-calibration: implausible calibration of 'rec/imu': the magnetic field after "
                                     "calibration is 480 µT (median |m|), "
                                     "outside mag_field_min … mag_field_max = 22 … 67 µT"))
        << outcome.message().toStdString();
    EXPECT_TRUE(outcome.message().endsWith("(to store it anyway, flagged, set accept_implausible=true)"));
    EXPECT_EQ(project->stream(QStringLiteral("rec/cal")), nullptr);
    EXPECT_EQ(project->table(QStringLiteral("rec/cal-calibration")), nullptr);
    EXPECT_FALSE(project->isModified());

    // Declared as mG, the same numbers are a plausible 48 µT.
    athlos::Stream milligauss = turningImu(48.0, 10.0);
    for (int i = 6; i < 9; ++i) milligauss.info().columns[std::size_t(i)].unit = QStringLiteral("mG");
    project->putStream(QStringLiteral("rec/imu"), std::move(milligauss));
    const auto declared = calibrate(*project);
    EXPECT_TRUE(declared.ok()) << declared.message().toStdString();
}

TEST(ImuCalibrationPlausibility, OverrideStoresTheResultFlagged) {
    QTemporaryDir dir;
    auto project = athlos::Project::create(dir.filePath(QStringLiteral("p.athlos")));
    project->putStream(QStringLiteral("rec/imu"), turningImu(48.0, 10.0));
    const auto outcome = calibrate(*project, {{QStringLiteral("accept_implausible"), QStringLiteral("true")}});
    ASSERT_TRUE(outcome.ok()) << outcome.message().toStdString();
    EXPECT_TRUE(outcome->parameters.value(QStringLiteral("accept_implausible")).toBool());  // in the provenance
    const athlos::Table* table = project->table(QStringLiteral("rec/cal-calibration"));
    const athlos::Stream* stream = project->stream(QStringLiteral("rec/cal"));
    ASSERT_TRUE(table && stream);
    EXPECT_TRUE(table->attributes.value(QStringLiteral("implausible")).toString().contains("480 µT"));
    EXPECT_TRUE(stream->info().attributes.value(QStringLiteral("implausible")).toString().contains("480 µT"));
    // A wider, explicit range accepts it unflagged.
    const auto wide = calibrate(*project, {{QStringLiteral("mag_field_max"), QStringLiteral("600")}});
    ASSERT_TRUE(wide.ok()) << wide.message().toStdString();
    EXPECT_FALSE(
        project->table(QStringLiteral("rec/cal-calibration"))->attributes.contains(QStringLiteral("implausible")));
}

TEST(ImuCalibrationPlausibility, AccelerometerScaleAndRestMagnitude) {
    const PlausibilityLimits limits;
    std::vector<Vec3> means;  // six positions of a sensor reading 80 % of the true acceleration
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {1.0, -1.0}) {
            Vec3 a = Vec3::Zero();
            a[axis] = s * 9.81 * 0.8;
            means.push_back(a);
        }
    const auto fitted = calibrateAccelerometer(means, 9.81);
    ASSERT_TRUE(fitted.has_value());
    const QStringList scale = checkAccelerometer(*fitted, means, 9.81, limits);
    ASSERT_EQ(scale.size(), 3) << scale.join("\n").toStdString();  // one per axis, none for |a| (the fit matched g)
    EXPECT_EQ(scale[0],
              "the fitted accelerometer scale factor x = 0.8 differs from 1 by more than acc_scale_tolerance = 0.1");
    // Identity calibration of that sensor: the rest magnitude is 20 % off.
    const QStringList rest = checkAccelerometer(AccCalibration{}, means, 9.81, limits);
    ASSERT_EQ(rest.size(), 1);
    EXPECT_EQ(rest[0],
              "|a| at rest after calibration is 7.848 m/s² in a static position, 20 % from gravity = 9.81 m/s², "
              "more than acc_norm_tolerance = 0.03 of gravity");
    // A 2 % sensor is plausible either way.
    for (Vec3& m : means) m *= 1.02 / 0.8;
    EXPECT_TRUE(checkAccelerometer(*calibrateAccelerometer(means, 9.81), means, 9.81, limits).isEmpty());
    EXPECT_TRUE(checkAccelerometer(AccCalibration{}, means, 9.81, limits).isEmpty());
}
