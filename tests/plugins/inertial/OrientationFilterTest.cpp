// Orientation filters on simulated data with known truth: exact strapdown, convergence from a wrong
// initial orientation, gyroscope bias estimation, magnetic disturbance detection and ride-out.
#include "core/math/Angles.h"
#include "core/math/OrientationError.h"
#include "plugins/inertial/ImuGnssSimulator.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::inertial;

namespace {
using math::kDeg;

struct Rows {
    std::vector<double> v;  // acc, gyr, mag per row
    ImuBatch batch(bool mag = true) const {
        return {v.data() + 3, v.data(), mag ? v.data() + 6 : nullptr, v.size() / 9, 9};
    }
};
Rows rows(const SimulatedData& d) {
    Rows r;
    for (std::size_t k = 0; k < d.imuT.size(); ++k)
        for (const Vec3* x : {&d.acc[k], &d.gyr[k], &d.mag[k]}) r.v.insert(r.v.end(), x->data(), x->data() + 3);
    return r;
}
SimulatorParams ideal() {
    SimulatorParams p;
    p.gyrBias = p.gyrNoise = p.gyrScale = p.accBias = p.accNoise = p.accScale = p.magNoise = 0.0;
    p.translation = false;
    return p;
}
SimulatorParams rotationsOnly() {
    SimulatorParams p;
    p.translation = false;
    return p;
}
// RMS of an error component (deg) over samples from `from` seconds on.
double rmsFrom(const SimulatedData& d, const std::vector<Quat>& q, double from, bool inclination) {
    double s = 0;
    int n = 0;
    for (std::size_t k = 0; k < q.size(); ++k) {
        if (d.imuT[k] < from) continue;
        const auto e = math::orientationError(q[k], d.orientation[k]);
        s += std::pow(inclination ? e.inclination : e.total, 2);
        ++n;
    }
    return std::sqrt(s / n) / kDeg;
}
}  // namespace

TEST(Strapdown, ExactOnSimulatedMotionWithIdealGyro) {
    const SimulatedData d = simulateImuGnss(ideal());
    Strapdown s(0.01);
    s.setQuaternion(d.orientation[0]);
    double worst = 0;
    for (std::size_t k = 1; k < d.imuT.size(); ++k) {
        s.update(d.gyr[k], d.acc[k], nullptr);
        worst = std::max(worst, math::orientationError(s.quaternion(), d.orientation[k]).total);
    }
    EXPECT_LT(worst, 1e-6);  // rounding over 9000 steps
}

TEST(OrientationFilter, AllAlgorithmsTrackIdealData) {
    SimulatorParams p = ideal();
    p.duration = 40;
    const SimulatedData d = simulateImuGnss(p);
    const Rows r = rows(d);
    for (const QString& name : orientationAlgorithmNames()) {
        OrientationOptions o;
        o.algorithm = *parseOrientationAlgorithm(name);
        const auto run = estimateOrientation(o, r.batch(), 0.01);
        // Baselines feel the running accelerations directly; the VQF-class filter must do much better.
        const double bound = name == QLatin1String("vqf") ? 1.0 : 8.0;
        EXPECT_LT(rmsFrom(d, run.track.q, 5.0, false), bound) << qPrintable(name);
    }
}

TEST(OrientationFilter, ConvergesFromWrongInitialOrientation) {
    SimulatorParams p = rotationsOnly();
    p.duration = 60;
    const SimulatedData d = simulateImuGnss(p);
    const Rows r = rows(d);
    // The filter initialises from the first samples: make them lie (40° tilt, 90° heading off) for 2 s.
    Rows wrong = r;
    const Quat lie = math::quatFromAxisAngle(Vec3(1, 1, 0), 40 * kDeg) * math::headingRotation(90 * kDeg);
    for (std::size_t k = 0; k < 200; ++k) {
        const Vec3 a = lie.conjugate() * Vec3(0, 0, 9.81), m = lie.conjugate() * p.magField;
        for (int i = 0; i < 3; ++i) {
            wrong.v[k * 9 + i] = a[i];
            wrong.v[k * 9 + 6 + i] = m[i];
        }
    }
    OrientationFilter f(0.01);
    OrientationTrack track;
    f.updateBatch(wrong.batch(), track);
    EXPECT_GT(math::orientationError(track.q[150], d.orientation[150]).total, 20 * kDeg);  // really started wrong
    EXPECT_LT(rmsFrom(d, track.q, 40.0, false), 2.0);
    Madgwick m(0.01, Madgwick::Params{});
    m.setQuaternion(lie);
    OrientationTrack mt;
    m.updateBatch(r.batch(), mt);
    EXPECT_LT(rmsFrom(d, mt.q, 40.0, true), 5.0);
}

TEST(OrientationFilter, EstimatesGyroscopeBias) {
    SimulatorParams p = rotationsOnly();
    p.duration = 120;
    p.gyrBias = 1.0 * kDeg;
    p.gyrScale = 0.0;  // scale errors would look like a motion-dependent bias
    const SimulatedData d = simulateImuGnss(p);
    OrientationFilter f(0.01);
    OrientationTrack track;
    f.updateBatch(rows(d).batch(), track);
    // The initial rest (5 s) is enough for the rest update; motion keeps it in place.
    EXPECT_LT((track.bias[450] - d.gyrBias).norm(), 0.15 * kDeg) << track.bias[450].transpose() / kDeg;
    EXPECT_TRUE(track.rest[400]);
    EXPECT_LT((track.bias.back() - d.gyrBias).norm(), 0.3 * kDeg)
        << track.bias.back().transpose() / kDeg << " true " << d.gyrBias.transpose() / kDeg;
    // Without bias estimation the heading/inclination would drift: compare 6D inclination error.
    OrientationOptions off;
    off.filter.restBiasEstimation = off.filter.motionBiasEstimation = false;
    off.useMagnetometer = false;
    OrientationOptions on = off;
    on.filter = OrientationFilter::Params();
    const Rows r = rows(d);
    const double eOn = rmsFrom(d, estimateOrientation(on, r.batch(), 0.01).track.q, 10, false);
    const double eOff = rmsFrom(d, estimateOrientation(off, r.batch(), 0.01).track.q, 10, false);
    EXPECT_LT(eOn, 0.5 * eOff) << eOn << " vs " << eOff;
}

TEST(OrientationFilter, FlagsAndRidesOutMagneticDisturbance) {
    SimulatorParams p = rotationsOnly();
    p.duration = 90;
    const SimulatedData d = simulateImuGnss(p);
    Rows r = rows(d);
    // A magnet near the sensor from 60 s to 70 s: +25 µT along an earth-fixed direction. (The first
    // reference field is accepted after 5 s of turning, so the disturbance comes later.)
    for (std::size_t k = 6000; k < 7000; ++k) {
        const Vec3 add = d.orientation[k].conjugate() * Vec3(25.0, 0.0, 10.0);
        for (int i = 0; i < 3; ++i) r.v[k * 9 + 6 + i] += add[i];
    }
    OrientationFilter f(0.01);
    OrientationTrack track;
    f.updateBatch(r.batch(), track);
    int flagged = 0;
    for (std::size_t k = 6000; k < 7000; ++k) flagged += track.magDisturbed[k];
    EXPECT_GT(flagged, 900);
    int before = 0;
    for (std::size_t k = 5000; k < 6000; ++k) before += track.magDisturbed[k];
    EXPECT_LT(before, 50);
    double worst = 0;
    for (std::size_t k = 6000; k < 7500; ++k)
        worst = std::max(worst, math::orientationError(track.q[k], d.orientation[k]).heading);
    EXPECT_LT(worst, 3.0 * kDeg);
    // Without rejection the heading is pulled away.
    OrientationFilter::Params noReject;
    noReject.magDisturbanceRejection = false;
    OrientationFilter g(0.01, noReject);
    OrientationTrack bad;
    g.updateBatch(r.batch(), bad);
    EXPECT_GT(math::orientationError(bad.q[6999], d.orientation[6999]).heading, 2.0 * worst);
}

TEST(OrientationFilter, SprintsLimitAnyImuOnlyFilterButStayBounded) {
    // A 0→8 m/s sprint is a sustained horizontal acceleration: the inclination error it causes is
    // physical (only velocity aiding, e.g. gnss-imu, removes it). The filter must stay bounded.
    SimulatorParams p;
    p.duration = 60;
    const SimulatedData d = simulateImuGnss(p);
    OrientationFilter f(0.01);
    OrientationTrack track;
    f.updateBatch(rows(d).batch(), track);
    EXPECT_LT(rmsFrom(d, track.q, 5.0, true), 12.0);
}

TEST(OrientationFilter, AnySamplingRate) {
    for (double rate : {50.0, 400.0}) {
        SimulatorParams p = rotationsOnly();
        p.duration = 40;
        p.imuRate = rate;
        const SimulatedData d = simulateImuGnss(p);
        OrientationFilter f(1.0 / rate);
        OrientationTrack track;
        f.updateBatch(rows(d).batch(), track);
        EXPECT_LT(rmsFrom(d, track.q, 10.0, false), 2.0) << rate;
    }
}

TEST(OrientationFilter, MissingSamplesDoNotPoisonTheState) {
    SimulatorParams p = rotationsOnly();
    p.duration = 30;
    const SimulatedData d = simulateImuGnss(p);
    Rows r = rows(d);
    for (std::size_t k = 1000; k < 1010; ++k)
        for (int i = 0; i < 9; ++i) r.v[k * 9 + i] = std::numeric_limits<double>::quiet_NaN();
    OrientationFilter f(0.01);
    OrientationTrack track;
    f.updateBatch(r.batch(), track);
    EXPECT_TRUE(track.q.back().coeffs().allFinite());
    EXPECT_LT(rmsFrom(d, track.q, 15.0, false), 2.0);
}

TEST(OrientationFilter, SaturatedAccelerometerSamplesAreGated) {
    SimulatorParams p = rotationsOnly();
    p.duration = 40;
    const SimulatedData d = simulateImuGnss(p);
    Rows r = rows(d);
    // One-sided clipped "impacts": +60 m/s² on x for 20 ms every second (no opposite half survives).
    for (std::size_t k = 600; k < r.v.size() / 9; k += 100)
        for (std::size_t j = k; j < k + 2; ++j) r.v[j * 9] = 60.0;
    OrientationFilter::Params gated;
    gated.accRange = 60.0;
    OrientationFilter f(0.01, gated), g(0.01);
    OrientationTrack withGate, without;
    f.updateBatch(r.batch(), withGate);
    g.updateBatch(r.batch(), without);
    const double eGate = rmsFrom(d, withGate.q, 10.0, true), eNone = rmsFrom(d, without.q, 10.0, true);
    EXPECT_LT(eGate, 1.0);
    EXPECT_GT(eNone, 2.0 * eGate) << eNone << " vs " << eGate;
}
