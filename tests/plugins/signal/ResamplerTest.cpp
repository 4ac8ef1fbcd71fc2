// Resampler against exact answers: ramps, quadratics, sines, SLERP half-angles, gaps and flags.
#include "plugins/signal/Resampler.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

using athlos::StreamData;
using athlos::signal::ColumnGroups;
using athlos::signal::Resampler;
using Method = Resampler::Method;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// n jittered time stamps around a nominal period: t_i = t0 + i·period + U(−jitter, jitter)·period.
std::vector<double> jitteredTimes(int n, double period, double jitter, double t0 = 0.0, unsigned seed = 7) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter, jitter);
    std::vector<double> t(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) t[i] = t0 + (i + u(rng)) * period;
    return t;
}

StreamData columnData(const std::vector<double>& t, const std::function<double(double)>& f) {
    StreamData d(t.size(), 1);
    d.t = t;
    for (std::size_t i = 0; i < t.size(); ++i) d.at(i, 0) = f(t[i]);
    return d;
}

StreamData run(const StreamData& in, Resampler::Params p, const QStringList& names) {
    EXPECT_TRUE(Resampler::check(p, in.t).ok());
    return Resampler(p, in.t).resample(in, ColumnGroups::detect(names));
}

double maxError(const StreamData& out, const std::function<double(double)>& f) {
    double e = 0.0;
    for (std::size_t k = 0; k < out.rows(); ++k) e = std::max(e, std::abs(out.at(k, 0) - f(out.t[k])));
    return e;
}

}  // namespace

TEST(SignalResampler, GridCoversSpanUniformly) {
    const auto t = jitteredTimes(1000, 0.01, 0.3, 0.0137);
    const StreamData out = run(columnData(t, [](double) { return 0.0; }), {33.0}, {QStringLiteral("x")});
    ASSERT_GT(out.rows(), 2u);
    EXPECT_DOUBLE_EQ(out.t.front(), t.front());
    EXPECT_LE(out.t.back(), t.back());
    EXPECT_GT(out.t.back(), t.back() - 1.0 / 33.0);
    for (std::size_t k = 0; k < out.rows(); ++k) EXPECT_NEAR(out.t[k], t.front() + double(k) / 33.0, 1e-12);

    const StreamData aligned =
        run(columnData(t, [](double) { return 0.0; }), {100.0, Method::Linear, 0.0, true}, {QStringLiteral("x")});
    EXPECT_DOUBLE_EQ(aligned.t.front(), 0.02);  // first multiple of 0.01 at or after 0.0137 (+ jitter)
    for (double tk : aligned.t) EXPECT_NEAR(tk * 100.0, std::round(tk * 100.0), 1e-9);
}

TEST(SignalResampler, LinearIsExactOnRamp) {
    auto ramp = [](double t) { return 2.0 - 3.5 * t; };
    const StreamData out = run(columnData(jitteredTimes(500, 0.02, 0.45), ramp), {37.0}, {QStringLiteral("x")});
    EXPECT_LT(maxError(out, ramp), 1e-12);
}

TEST(SignalResampler, CubicIsExactOnQuadraticFromNonUniformTimes) {
    auto quadratic = [](double t) { return 1.0 + 2.0 * t - 3.0 * t * t; };
    const StreamData out =
        run(columnData(jitteredTimes(300, 0.01, 0.45), quadratic), {123.0, Method::Cubic}, {QStringLiteral("x")});
    EXPECT_LT(maxError(out, quadratic), 1e-11);
    // Linear interpolation cannot do that (so the test above can fail).
    const StreamData lin = run(columnData(jitteredTimes(300, 0.01, 0.45), quadratic), {123.0}, {QStringLiteral("x")});
    EXPECT_GT(maxError(lin, quadratic), 1e-6);
}

TEST(SignalResampler, SineFromNonUniformTimesHasSmallError) {
    const double f = 5.0;
    auto wave = [f](double t) { return std::sin(2 * kPi * f * t); };
    const double h = 0.001 * 1.4;  // largest input interval with ±20 % jitter around 1 ms
    const auto t = jitteredTimes(4000, 0.001, 0.2);
    // Linear interpolation error bound: h²/8 · max|y''| = h²/8 · (2πf)².
    const double linearBound = h * h / 8 * std::pow(2 * kPi * f, 2);
    EXPECT_LT(maxError(run(columnData(t, wave), {250.0}, {QStringLiteral("x")}), wave), linearBound);
    EXPECT_LT(maxError(run(columnData(t, wave), {250.0, Method::Cubic}, {QStringLiteral("x")}), wave),
              linearBound / 100);
}

TEST(SignalResampler, SlerpMidpointIsHalfAngleRotation) {
    const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
    const double angle = 2.2;  // rad
    const Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();
    const Eigen::Quaterniond q1(Eigen::AngleAxisd(angle, axis));
    for (double sign : {1.0, -1.0}) {  // −q1 is the same rotation; SLERP must take the short arc
        StreamData in(2, 4);
        in.t = {0.0, 1.0};
        const Eigen::Vector4d a(q0.w(), q0.x(), q0.y(), q0.z()),
            b = sign * Eigen::Vector4d(q1.w(), q1.x(), q1.y(), q1.z());
        for (int c = 0; c < 4; ++c) {
            in.at(0, c) = a[c];
            in.at(1, c) = b[c];
        }
        const StreamData out = run(in, {4.0}, {"qw", "qx", "qy", "qz"});
        ASSERT_EQ(out.rows(), 5u);
        for (std::size_t k = 0; k < out.rows(); ++k) {
            const Eigen::Quaterniond expected(Eigen::AngleAxisd(angle * out.t[k], axis));
            const Eigen::Quaterniond got(out.at(k, 0), out.at(k, 1), out.at(k, 2), out.at(k, 3));
            EXPECT_NEAR(std::abs(got.dot(expected)), 1.0, 1e-12) << "t = " << out.t[k] << " sign " << sign;
            EXPECT_NEAR(got.angularDistance(expected), 0.0, 1e-7);
        }
    }
}

TEST(SignalResampler, QuaternionOutputIsUnitNormAndGroupsByPrefix) {
    const auto t = jitteredTimes(200, 0.01, 0.3);
    const QStringList names = {"ref_qx", "acc", "ref_qw", "ref_qz", "ref_qy"};
    StreamData in(t.size(), 5);
    in.t = t;
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double scale = 0.5 + double(i % 3);  // deliberately not unit
        for (int c = 0; c < 5; ++c) in.at(i, c) = c == 1 ? t[i] : scale * g(rng);
    }
    const ColumnGroups groups = ColumnGroups::detect(names);
    ASSERT_EQ(groups.quaternions.size(), 1u);
    EXPECT_EQ(groups.quaternions[0], (std::array<int, 4>{2, 0, 4, 3}));
    EXPECT_EQ(groups.ordinary, std::vector<int>{1});
    for (Method m : {Method::Linear, Method::Nearest, Method::Cubic}) {
        const StreamData out = run(in, {77.0, m}, names);
        for (std::size_t k = 0; k < out.rows(); ++k) {
            const double norm = std::sqrt(std::pow(out.at(k, 0), 2) + std::pow(out.at(k, 2), 2) +
                                          std::pow(out.at(k, 3), 2) + std::pow(out.at(k, 4), 2));
            EXPECT_NEAR(norm, 1.0, 1e-12);
        }
    }
}

TEST(SignalResampler, MaxGapGivesNaNOnlyInsideTheGap) {
    std::vector<double> t;
    for (int i = 0; i <= 100; ++i) t.push_back(i * 0.01);        // 0 … 1 s
    for (int i = 0; i <= 100; ++i) t.push_back(2.0 + i * 0.01);  // gap of 1 s, then 2 … 3 s
    const QStringList names = {"x", "movement", "qw", "qx", "qy", "qz"};
    StreamData in(t.size(), 6);
    in.t = t;
    for (std::size_t i = 0; i < t.size(); ++i) {
        in.at(i, 0) = t[i];
        in.at(i, 1) = t[i] > 1.5 ? 1.0 : 0.0;
        in.at(i, 2) = 1.0;
        in.at(i, 3) = in.at(i, 4) = in.at(i, 5) = 0.0;
    }
    const StreamData out = run(in, {50.0, Method::Linear, 0.5}, names);
    int inside = 0;
    for (std::size_t k = 0; k < out.rows(); ++k) {
        const bool inGap = out.t[k] > 1.0 + 1e-9 && out.t[k] < 2.0 - 1e-9;
        inside += inGap;
        for (int c = 0; c < 6; ++c) EXPECT_EQ(std::isnan(out.at(k, c)), inGap) << "t = " << out.t[k] << " col " << c;
        if (!inGap) {
            EXPECT_NEAR(out.at(k, 0), out.t[k], 1e-12);
        }
    }
    EXPECT_EQ(inside, 49);  // 1.02 … 1.98
    // A gap shorter than max_gap is interpolated.
    const StreamData bridged = run(in, {50.0, Method::Linear, 1.5}, names);
    for (std::size_t k = 0; k < bridged.rows(); ++k) EXPECT_NEAR(bridged.at(k, 0), bridged.t[k], 1e-12);
}

TEST(SignalResampler, FlagColumnsUseNearestNeighbour) {
    const auto t = jitteredTimes(300, 0.01, 0.4);
    const QStringList names = {"speed", "outlier", "step_flag"};
    StreamData in(t.size(), 3);
    in.t = t;
    for (std::size_t i = 0; i < t.size(); ++i) {
        in.at(i, 0) = double(i);
        in.at(i, 1) = (i / 7) % 2;
        in.at(i, 2) = (i / 3) % 2;
    }
    EXPECT_EQ(ColumnGroups::detect(names).flags, (std::vector<int>{1, 2}));
    const StreamData out = run(in, {61.0}, names);
    bool interpolatedSpeed = false;
    for (std::size_t k = 0; k < out.rows(); ++k) {
        const auto nearest =
            std::min_element(t.begin(), t.end(),
                             [&](double a, double b) { return std::abs(a - out.t[k]) < std::abs(b - out.t[k]); }) -
            t.begin();
        EXPECT_EQ(out.at(k, 1), in.at(std::size_t(nearest), 1)) << "t = " << out.t[k];
        EXPECT_EQ(out.at(k, 2), in.at(std::size_t(nearest), 2)) << "t = " << out.t[k];
        interpolatedSpeed |= out.at(k, 0) != std::round(out.at(k, 0));
    }
    EXPECT_TRUE(interpolatedSpeed);  // the ordinary column really was interpolated
}

// GNSS quality columns are per fix: resampled by nearest neighbour, never blended (issue #13).
TEST(SignalResampler, GnssQualityColumnsAreNotInterpolated) {
    const QStringList names = {"x", "fix", "sats", "HDOP"};
    EXPECT_EQ(ColumnGroups::detect(names).flags, (std::vector<int>{1, 2, 3}));
    const auto t = jitteredTimes(200, 0.1, 0.3);
    StreamData in(t.size(), 4);
    in.t = t;
    for (std::size_t i = 0; i < t.size(); ++i) {
        in.at(i, 0) = 0.5 * double(i);
        in.at(i, 1) = i % 5 == 0 ? 1.0 : 4.0;     // GGA fix quality: GPS or RTK fixed
        in.at(i, 2) = double(7 + (i / 9) % 4);    // satellites
        in.at(i, 3) = 0.8 + 0.1 * double(i % 3);  // HDOP
    }
    const StreamData out = run(in, {23.0}, names);
    for (std::size_t k = 0; k < out.rows(); ++k) {
        EXPECT_TRUE(out.at(k, 1) == 1.0 || out.at(k, 1) == 4.0) << "t = " << out.t[k];
        EXPECT_EQ(out.at(k, 2), std::round(out.at(k, 2))) << "t = " << out.t[k];
        bool observed = false;
        for (std::size_t i = 0; i < t.size(); ++i) observed |= out.at(k, 3) == in.at(i, 3);
        EXPECT_TRUE(observed) << "HDOP " << out.at(k, 3) << " at t = " << out.t[k] << " was never observed";
    }
}

TEST(SignalResampler, NaNNeighboursGiveNaNAndNothingElse) {
    std::vector<double> t;  // binary-exact times so that grid points hit samples exactly
    for (int i = 0; i < 40; ++i) t.push_back(i * 0.125);
    StreamData in = columnData(t, [](double x) { return x; });
    in.at(16, 0) = kNaN;  // t = 2.0
    for (Method m : {Method::Linear, Method::Nearest, Method::Cubic}) {
        const StreamData out = run(in, {32.0, m}, {QStringLiteral("x")});
        for (std::size_t k = 0; k < out.rows(); ++k) {
            const double d = out.t[k] - 2.0;
            // Linear uses the bracketing samples, cubic one more on each side (but an exact hit on
            // another sample returns that sample), nearest the closer one (ties go to the later).
            const bool expectNaN = m == Method::Linear  ? std::abs(d) < 0.125
                                   : m == Method::Cubic ? std::abs(d) < 0.25 && std::abs(d) != 0.125
                                                        : d >= -0.0625 && d < 0.0625;
            EXPECT_EQ(std::isnan(out.at(k, 0)), expectNaN) << "method " << int(m) << " t = " << out.t[k];
            if (!expectNaN) {
                EXPECT_NEAR(out.at(k, 0), out.t[k], 1e-12 + (m == Method::Nearest ? 0.0625 : 0.0));
            }
        }
    }
}

TEST(SignalResampler, CheckNamesTheProblem) {
    const std::vector<double> ok = {0.0, 0.1, 0.2};
    EXPECT_TRUE(Resampler::check({0.0}, ok).message().startsWith(QLatin1String("rate")));
    EXPECT_TRUE(Resampler::check({10.0, Method::Linear, -1.0}, ok).message().startsWith(QLatin1String("max_gap")));
    EXPECT_TRUE(Resampler::check({10.0}, {0.0, 0.1, 0.1}).message().contains(QLatin1String("row 2")));
    EXPECT_TRUE(Resampler::check({10.0}, {0.0}).message().contains(QLatin1String("at least 2")));
    EXPECT_TRUE(Resampler::check({1e12}, ok).message().contains(QLatin1String("lower rate")));
    EXPECT_TRUE(Resampler::check({10.0}, ok).ok());
    EXPECT_FALSE(Resampler::parseMethod(QStringLiteral("spline")).ok());
}
