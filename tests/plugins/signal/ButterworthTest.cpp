// Butterworth design and filtering against analytic answers and scipy.signal reference values.
#include "plugins/signal/Butterworth.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

using athlos::signal::Butterworth;
using Type = Butterworth::Type;

namespace {

constexpr double kPi = std::numbers::pi;

Butterworth make(Type type, int order, double cutoff, double fs, double cutoffHigh = 0.0) {
    return Butterworth({type, order, cutoff, cutoffHigh, fs});
}

Eigen::VectorXd sine(Eigen::Index n, double f, double fs, double phase = 0.0) {
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = std::sin(2 * kPi * f * double(i) / fs + phase);
    return x;
}

// Least-squares fit y ≈ a·sin(ωn) + b·cos(ωn) over [from, to): amplitude and phase (rad) relative
// to sin(ωn).
struct SineFit {
    double amplitude;
    double phase;
};
SineFit fitSine(const Eigen::VectorXd& y, double f, double fs, Eigen::Index from, Eigen::Index to) {
    Eigen::MatrixX2d design(to - from, 2);
    for (Eigen::Index i = from; i < to; ++i) {
        const double w = 2 * kPi * f * double(i) / fs;
        design(i - from, 0) = std::sin(w);
        design(i - from, 1) = std::cos(w);
    }
    const Eigen::Vector2d ab = design.colPivHouseholderQr().solve(y.segment(from, to - from));
    return {ab.norm(), std::atan2(ab[1], ab[0])};
}

// Analytic magnitude of the digital Butterworth at f with pre-warped Ω = tan(πf/fs).
double analyticMagnitude(Type type, int n, double f, double fs, double fc, double fh = 0.0) {
    const double w = std::tan(kPi * f / fs), wl = std::tan(kPi * fc / fs), wh = std::tan(kPi * fh / fs);
    double ratio = 0.0;  // the argument x of 1/sqrt(1 + x^(2n))
    switch (type) {
        case Type::LowPass:
            ratio = w / wl;
            break;
        case Type::HighPass:
            ratio = wl / w;
            break;
        case Type::BandPass:
            ratio = (w * w - wl * wh) / (w * (wh - wl));
            break;
        case Type::BandStop:
            ratio = w * (wh - wl) / (wl * wh - w * w);
            break;
    }
    return 1.0 / std::sqrt(1.0 + std::pow(ratio, 2 * n));
}

// Deterministic test input used for the scipy reference outputs below.
Eigen::VectorXd referenceInput() {
    Eigen::VectorXd x(60);
    for (int n = 0; n < 60; ++n) x[n] = std::sin(0.3 * n) + 0.5 * std::cos(1.7 * n) + 0.01 * n;
    return x;
}

}  // namespace

// scipy.signal.butter(4, 10, fs=100, output='sos'), scipy 1.10.1.
TEST(SignalButterworth, SosMatchesScipyLowpassOrder4) {
    const Eigen::Matrix<double, 2, 6> scipy{
        {0.00482434335771623, 0.00964868671543246, 0.00482434335771623, 1.0, -1.0485995763626117, 0.2961403575616696},
        {1.0, 2.0, 1.0, 1.0, -1.320913430819426, 0.6327387928852762}};
    const auto sos = make(Type::LowPass, 4, 10, 100).sos();
    ASSERT_EQ(sos.rows(), 2);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 6; ++c) EXPECT_NEAR(sos(r, c), scipy(r, c), 1e-14) << "row " << r << " col " << c;
}

// scipy.signal.butter(3, 10, btype='highpass', fs=100, output='sos'): odd order → first-order section.
TEST(SignalButterworth, SosMatchesScipyHighpassOrder3) {
    const Eigen::Matrix<double, 2, 6> scipy{
        {0.5276243825019432, -0.5276243825019432, 0.0, 1.0, -0.5095254494944288, 0.0},
        {1.0, -2.0, 1.0, 1.0, -1.2505164308487402, 0.5457233155094579}};
    const auto sos = make(Type::HighPass, 3, 10, 100).sos();
    ASSERT_EQ(sos.rows(), 2);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 6; ++c) EXPECT_NEAR(sos(r, c), scipy(r, c), 1e-14) << "row " << r << " col " << c;
}

// sosfilt(sos, x, zi=sosfilt_zi(sos)·x[0]) and sosfiltfilt(sos, x) from scipy 1.10.1 on referenceInput().
// Band filters pair zeros differently from scipy, but the cascade (and its output) is the same.
TEST(SignalButterworth, FilteringMatchesScipy) {
    const Eigen::VectorXd x = referenceInput();
    struct Case {
        Butterworth filter;
        bool zeroPhase;
        std::vector<std::pair<int, double>> expected;
    };
    const std::vector<Case> cases = {
        {make(Type::LowPass, 4, 10, 100),
         true,
         {{0, 0.5043004191259609},
          {1, 0.598570674020597},
          {30, 0.7112063907447066},
          {58, -0.06669954838717367},
          {59, 0.17110619300525917}}},
        {make(Type::LowPass, 4, 10, 100),
         false,
         {{0, 0.5000000000000001},
          {1, 0.4987509676606802},
          {30, 1.2517289118796597},
          {58, 0.12093907267985596},
          {59, -0.1165176617138722}}},
        {make(Type::BandPass, 3, 5, 100, 15),
         true,
         {{0, -0.05305305069921966},
          {1, -0.16279801111787567},
          {30, 0.16568690704155936},
          {58, -0.4458249312925342},
          {59, 0.006172155412418667}}},
        {make(Type::HighPass, 3, 10, 100),
         true,
         {{0, 0.00296435199990569}, {30, 0.37507932629111684}, {59, 0.008585335717070097}}},
        {make(Type::BandStop, 2, 8, 100, 12),
         true,
         {{0, 0.4840270026715767}, {30, 1.0847321908492047}, {59, 0.1775853762169}}},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        Eigen::VectorXd y = x;
        if (cases[k].zeroPhase)
            cases[k].filter.filtFilt(y);
        else
            cases[k].filter.filter(y);
        for (auto [i, v] : cases[k].expected) EXPECT_NEAR(y[i], v, 1e-12) << "case " << k << " sample " << i;
    }
}

// scipy.signal.sosfilt_zi(butter(4, 10, fs=100, output='sos')).
TEST(SignalButterworth, SteadyStateInitialMatchesScipy) {
    const Eigen::MatrixX2d zi = make(Type::LowPass, 4, 10, 100).steadyStateInitial();
    EXPECT_NEAR(zi(0, 0), 0.07313199715874638, 1e-14);
    EXPECT_NEAR(zi(0, 1), -0.01826167519702828, 1e-14);
    EXPECT_NEAR(zi(1, 0), 0.9220436594835376, 1e-14);
    EXPECT_NEAR(zi(1, 1), -0.5547824523688138, 1e-14);
}

TEST(SignalButterworth, PolesInsideUnitCircleAndPreWarpedEdge) {
    // Independent check of the design: every section is stable, and |H| at the cut-off is 1/√2
    // for every order and type (the pre-warping puts the −3 dB point exactly there).
    for (int n = 1; n <= Butterworth::kMaxOrder; ++n) {
        for (Type type : {Type::LowPass, Type::HighPass, Type::BandPass, Type::BandStop}) {
            const Butterworth b = make(type, n, 7, 100, 19);
            for (Eigen::Index s = 0; s < b.sos().rows(); ++s) {
                const double a1 = b.sos()(s, 4), a2 = b.sos()(s, 5);
                EXPECT_LT(std::abs(a2), 1.0);  // Jury: |a2| < 1 and |a1| < 1 + a2
                EXPECT_LT(std::abs(a1), 1.0 + a2 + 1e-15);
            }
            EXPECT_NEAR(std::abs(b.response(7)), 1 / std::sqrt(2.0), 1e-10) << "order " << n;
            if (Butterworth::isBand(type)) {
                EXPECT_NEAR(std::abs(b.response(19)), 1 / std::sqrt(2.0), 1e-10);
            }
        }
    }
}

TEST(SignalButterworth, ResponseEqualsAnalyticMagnitudeForAllTypesAndOrders) {
    const double fs = 200, fc = 12, fh = 30;
    for (int n = 1; n <= Butterworth::kMaxOrder; ++n) {
        for (Type type : {Type::LowPass, Type::HighPass, Type::BandPass, Type::BandStop}) {
            const Butterworth b = make(type, n, fc, fs, fh);
            for (double f : {0.5, 3.0, 12.0, 18.0, 24.0, 30.0, 45.0, 70.0, 99.0}) {
                EXPECT_NEAR(std::abs(b.response(f)), analyticMagnitude(type, n, f, fs, fc, fh), 1e-9)
                    << "order " << n << " type " << int(type) << " f " << f;
            }
        }
    }
}

TEST(SignalButterworth, MeasuredGainAtCutoffSinglePassAndZeroPhase) {
    const double fs = 100, fc = 10;
    const Butterworth b = make(Type::LowPass, 4, fc, fs);
    const Eigen::VectorXd x = sine(20000, fc, fs);
    Eigen::VectorXd causal = x, zeroPhase = x;
    b.filter(causal);
    b.filtFilt(zeroPhase);
    EXPECT_NEAR(fitSine(causal, fc, fs, 2000, 18000).amplitude, 1 / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(fitSine(zeroPhase, fc, fs, 2000, 18000).amplitude, 0.5, 1e-9);
}

TEST(SignalButterworth, MeasuredGainAtTwiceCutoffEqualsPreWarpedAnalytic) {
    const double fs = 100, fc = 10, f = 2 * fc;
    for (int n = 1; n <= Butterworth::kMaxOrder; ++n) {
        const Butterworth b = make(Type::LowPass, n, fc, fs);
        Eigen::VectorXd y = sine(20000, f, fs);
        b.filter(y);
        const double expected = 1 / std::sqrt(1 + std::pow(std::tan(kPi * f / fs) / std::tan(kPi * fc / fs), 2 * n));
        EXPECT_NEAR(fitSine(y, f, fs, 4000, 18000).amplitude, expected, 1e-3) << "order " << n;
        EXPECT_NEAR(fitSine(y, f, fs, 4000, 18000).amplitude, expected, 1e-8) << "order " << n;  // in fact far better
    }
}

TEST(SignalButterworth, ZeroPhaseHasNoPhaseShiftWhileCausalMatchesResponse) {
    const double fs = 100;
    const Butterworth b = make(Type::LowPass, 4, 10, fs);
    for (double f : {2.0, 7.0, 10.0, 14.0}) {
        const double phase0 = 0.4;
        const Eigen::VectorXd x = sine(20000, f, fs, phase0);
        Eigen::VectorXd zeroPhase = x, causal = x;
        b.filtFilt(zeroPhase);
        b.filter(causal);
        const SineFit in = fitSine(x, f, fs, 2000, 18000);
        EXPECT_NEAR(fitSine(zeroPhase, f, fs, 2000, 18000).phase, in.phase, 1e-7) << f << " Hz";
        // The causal pass shifts by arg H(f), which must be clearly non-zero (so the test can fail).
        const double shift = std::arg(b.response(f));
        EXPECT_GT(std::abs(shift), 0.1);
        EXPECT_NEAR(std::remainder(fitSine(causal, f, fs, 2000, 18000).phase - in.phase - shift, 2 * kPi), 0.0, 1e-7);
    }
}

TEST(SignalButterworth, DcAndCentreGains) {
    EXPECT_NEAR(std::abs(make(Type::LowPass, 5, 3, 50).response(0)), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(make(Type::HighPass, 5, 3, 50).response(0)), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(make(Type::HighPass, 5, 3, 50).response(25)), 1.0, 1e-12);  // Nyquist
    // Digital band centre: the geometric centre of the pre-warped edges.
    const double fs = 100, fl = 5, fh = 20;
    const double f0 = fs / kPi * std::atan(std::sqrt(std::tan(kPi * fl / fs) * std::tan(kPi * fh / fs)));
    for (int n : {1, 2, 4, 7}) {
        const Butterworth bp = make(Type::BandPass, n, fl, fs, fh);
        EXPECT_NEAR(std::abs(bp.response(f0)), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(bp.response(0)), 0.0, 1e-12);
        Eigen::VectorXd y = sine(20000, f0, fs);
        bp.filtFilt(y);
        EXPECT_NEAR(fitSine(y, f0, fs, 2000, 18000).amplitude, 1.0, 1e-9);
        const Butterworth bs = make(Type::BandStop, n, fl, fs, fh);
        EXPECT_NEAR(std::abs(bs.response(f0)), 0.0, 1e-10);
        EXPECT_NEAR(std::abs(bs.response(0)), 1.0, 1e-12);
    }
}

TEST(SignalButterworth, ConstantInputGivesConstantOutput) {
    const double c = 3.7;
    for (int n : {1, 2, 3, 6, 10}) {
        for (Type type : {Type::LowPass, Type::HighPass, Type::BandPass, Type::BandStop}) {
            const Butterworth b = make(type, n, 4, 100, 9);
            const double dc = std::abs(b.response(0)) * c;  // c for low-pass/band-stop, 0 otherwise
            for (bool zeroPhase : {false, true}) {
                Eigen::VectorXd y = Eigen::VectorXd::Constant(500, c);
                zeroPhase ? b.filtFilt(y) : b.filter(y);
                EXPECT_LT((y.array() - dc).abs().maxCoeff(), 1e-12)
                    << "order " << n << " type " << int(type) << " zero-phase " << zeroPhase;
            }
        }
    }
}

TEST(SignalButterworth, PadLengthFollowsScipy) {
    EXPECT_EQ(make(Type::LowPass, 4, 10, 100).defaultPadLength(), 15);  // 3·(2·2 + 1)
    EXPECT_EQ(make(Type::LowPass, 3, 10, 100).defaultPadLength(), 12);  // one first-order section
    EXPECT_EQ(make(Type::BandPass, 3, 5, 100, 15).defaultPadLength(), 21);
    // Shorter than the padding: clipped to the data, still finite and DC-preserving.
    Eigen::VectorXd y = Eigen::VectorXd::Constant(5, 2.0);
    make(Type::LowPass, 4, 10, 100).filtFilt(y);
    EXPECT_LT((y.array() - 2.0).abs().maxCoeff(), 1e-12);
}

TEST(SignalButterworth, NaNRunsAreFilteredSeparately) {
    const Butterworth b = make(Type::LowPass, 2, 5, 100);
    Eigen::VectorXd x = sine(400, 3, 100) + Eigen::VectorXd::LinSpaced(400, 0, 1);
    x[150] = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd y = x;
    b.filterSegments(y, true);
    EXPECT_TRUE(std::isnan(y[150]));
    EXPECT_EQ(y.array().isNaN().count(), 1);
    Eigen::VectorXd head = x.head(150), tail = x.tail(249);
    b.filtFilt(head);
    b.filtFilt(tail);
    EXPECT_TRUE(y.head(150) == head);
    EXPECT_TRUE(y.tail(249) == tail);
}

TEST(SignalButterworth, CheckNamesParameterAndNyquist) {
    auto message = [](Butterworth::Params p) {
        auto status = Butterworth::check(p);
        return status.ok() ? QString() : status.message();
    };
    const QString atNyquist = message({Type::LowPass, 4, 50, 0, 100});
    EXPECT_TRUE(atNyquist.contains(QLatin1String("cutoff"))) << atNyquist.toStdString();
    EXPECT_TRUE(atNyquist.contains(QLatin1String("Nyquist frequency 50 Hz"))) << atNyquist.toStdString();
    EXPECT_TRUE(message({Type::LowPass, 4, 0, 0, 100}).startsWith(QLatin1String("cutoff")));
    // A rate estimated from time stamps is slightly off; "at Nyquist" must still be refused.
    EXPECT_FALSE(message({Type::LowPass, 4, 100, 0, 1 / 0.005}).isEmpty());
    EXPECT_TRUE(message({Type::LowPass, 0, 10, 0, 100}).startsWith(QLatin1String("order")));
    EXPECT_TRUE(message({Type::LowPass, 11, 10, 0, 100}).startsWith(QLatin1String("order")));
    EXPECT_TRUE(message({Type::BandPass, 4, 20, 10, 100}).startsWith(QLatin1String("cutoff_high")));
    EXPECT_TRUE(message({Type::BandStop, 4, 20, 60, 100}).contains(QLatin1String("Nyquist")));
    EXPECT_TRUE(message({Type::BandPass, 4, 10, 20, 100}).isEmpty());
    EXPECT_TRUE(Butterworth::parseType(QStringLiteral("lowpass")).ok());
    EXPECT_FALSE(Butterworth::parseType(QStringLiteral("notch")).ok());
}
