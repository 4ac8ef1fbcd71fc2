// Simulated foot gyroscope with known events: the detector must find every IC and TC at its true
// time, independent of the sampling rate and the sign convention of the ML axis.
#include "plugins/events/GaitEventDetector.h"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace athlos::events;

namespace {

struct Truth {
    std::vector<double> ic, tc;
};

double bump(double t, double centre, double sigma) { return std::exp(-0.5 * std::pow((t - centre) / sigma, 2)); }

// ω_ml of a walk: per stride a push-off dip (TC), a swing peak, a pre-impact dip (IC), still stance.
struct Walk {
    std::vector<double> t, gyr;  // gyr: N×3 (ML on y)
    Truth truth;
};

Walk simulate(double rate, double strideTime, int strides, double sign, unsigned seed) {
    Walk w;
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::uniform_real_distribution<double> jitter(-0.04, 0.04);
    // The walk starts standing (foot flat from t = 0): the first observable IC ends the first swing.
    double ic = 1.0;
    for (int s = 0; s < strides; ++s) {
        const double tc = ic + 0.6 * strideTime + jitter(rng);
        w.truth.tc.push_back(tc);
        ic += strideTime + jitter(rng);
        w.truth.ic.push_back(ic);
    }
    const double end = ic + 1.0;
    for (double t = 0.0; t < end; t += 1.0 / rate) {
        double ml = 0.0;
        for (std::size_t s = 0; s < w.truth.tc.size(); ++s) {
            const double tc = w.truth.tc[s], next = w.truth.ic[s];
            ml += -4.0 * bump(t, tc, 0.03) + 6.0 * bump(t, 0.5 * (tc + next), 0.07) - 3.0 * bump(t, next, 0.02);
        }
        w.t.push_back(t);
        w.gyr.insert(w.gyr.end(), {0.3 * ml + noise(rng), sign * ml + noise(rng), noise(rng)});
    }
    return w;
}

void expectMatches(const std::vector<double>& truth, const std::vector<double>& found, double tol) {
    ASSERT_EQ(found.size(), truth.size());
    for (std::size_t k = 0; k < truth.size(); ++k) EXPECT_NEAR(found[k], truth[k], tol) << k;
}

std::vector<double> eventsOf(const GaitEventDetector& d, GaitEventType type) {
    std::vector<double> out;
    for (const auto& e : d.events())
        if (e.type == type) out.push_back(e.t);
    return out;
}

}  // namespace

class GaitEventDetectorRates : public ::testing::TestWithParam<double> {};

TEST_P(GaitEventDetectorRates, FindsEveryEventAtItsTime) {
    const double rate = GetParam();
    for (double sign : {1.0, -1.0}) {
        const Walk w = simulate(rate, 1.1, 12, sign, 7);
        const int detected =
            GaitEventDetector::swingSign(w.t.data(), w.gyr.data(), w.t.size(), 3, Eigen::Vector3d::UnitY());
        EXPECT_EQ(detected, int(sign));
        GaitEventDetector d({}, detected);
        d.updateBatch(w.t.data(), w.gyr.data(), w.t.size(), 3, Eigen::Vector3d::UnitY());
        const double tol = 1.5 / rate + 0.005;
        expectMatches(w.truth.ic, eventsOf(d, GaitEventType::InitialContact), tol);
        expectMatches(w.truth.tc, eventsOf(d, GaitEventType::TerminalContact), tol);
        ASSERT_EQ(d.strides().size(), w.truth.ic.size() - 1);
        for (std::size_t k = 0; k < d.strides().size(); ++k) {
            const auto& s = d.strides()[k];
            EXPECT_NEAR(s.tStart, w.truth.ic[k], tol);
            EXPECT_NEAR(s.tEnd, w.truth.ic[k + 1], tol);
            EXPECT_NEAR(s.tTc, w.truth.tc[k + 1], tol);
            EXPECT_GT(s.tMinVel, s.tStart);
            EXPECT_LT(s.tMinVel, s.tTc);
            EXPECT_GT(s.confidence, 0.5);
            EXPECT_LE(s.confidence, 1.0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Rates, GaitEventDetectorRates, ::testing::Values(60.0, 102.4, 204.8, 500.0));

TEST(GaitEventDetector, WrongSignFindsNoProperStrides) {
    // With the swing sign flipped the push-off dips become "swing peaks": the events land elsewhere.
    const Walk w = simulate(100.0, 1.1, 10, 1.0, 3);
    GaitEventDetector d({}, -1);
    d.updateBatch(w.t.data(), w.gyr.data(), w.t.size(), 3, Eigen::Vector3d::UnitY());
    const auto ics = eventsOf(d, GaitEventType::InitialContact);
    int close = 0;
    for (double t : ics)
        for (double r : w.truth.ic) close += std::abs(t - r) < 0.03;
    EXPECT_LT(close, 3);
}

TEST(GaitEventDetector, PauseSplitsStridesAndLowersNothingElse) {
    // Two bouts with a 4 s stop: no stride across the stop, all strides inside the bouts.
    Walk a = simulate(100.0, 1.0, 5, 1.0, 1);
    const Walk b = simulate(100.0, 1.0, 5, 1.0, 2);
    const double shift = a.t.back() + 4.0;
    for (std::size_t k = 0; k < b.t.size(); ++k) {
        a.t.push_back(b.t[k] + shift);
        a.gyr.insert(a.gyr.end(), b.gyr.begin() + long(3 * k), b.gyr.begin() + long(3 * k + 3));
    }
    GaitEventDetector d;
    d.updateBatch(a.t.data(), a.gyr.data(), a.t.size(), 3, Eigen::Vector3d::UnitY());
    EXPECT_EQ(d.strides().size(), 8u);  // 5 swings → 5 ICs → 4 strides per bout
    for (const auto& s : d.strides()) EXPECT_LT(s.tEnd - s.tStart, 1.2);
}

TEST(GaitEventDetector, IrregularStrideHasLowerConfidence) {
    Walk w = simulate(100.0, 1.0, 8, 1.0, 5);
    GaitEventDetector regular;
    regular.updateBatch(w.t.data(), w.gyr.data(), w.t.size(), 3, Eigen::Vector3d::UnitY());
    // Stretch one stride by delaying everything after t = 5 s by 0.35 s (a hesitation step).
    Walk h;
    for (std::size_t k = 0; k < w.t.size(); ++k) {
        if (w.t[k] > 5.0 && (h.t.empty() || h.t.back() < 5.35)) {
            for (double t = h.t.back() + 0.01; t < 5.35; t += 0.01) {
                h.t.push_back(t);
                h.gyr.insert(h.gyr.end(), {0.0, 0.0, 0.0});
            }
        }
        h.t.push_back(w.t[k] > 5.0 ? w.t[k] + 0.35 : w.t[k]);
        h.gyr.insert(h.gyr.end(), w.gyr.begin() + long(3 * k), w.gyr.begin() + long(3 * k + 3));
    }
    GaitEventDetector hesitant;
    hesitant.updateBatch(h.t.data(), h.gyr.data(), h.t.size(), 3, Eigen::Vector3d::UnitY());
    ASSERT_EQ(hesitant.strides().size(), regular.strides().size());
    double minRegular = 1.0, minHesitant = 1.0;
    for (const auto& s : regular.strides()) minRegular = std::min(minRegular, s.confidence);
    for (const auto& s : hesitant.strides()) minHesitant = std::min(minHesitant, s.confidence);
    EXPECT_LT(minHesitant, minRegular - 0.2);
}

TEST(GaitEventDetector, PerSampleUpdateEqualsBatch) {
    const Walk w = simulate(102.4, 1.05, 6, 1.0, 9);
    GaitEventDetector batch, online;
    batch.updateBatch(w.t.data(), w.gyr.data(), w.t.size(), 3, Eigen::Vector3d::UnitY());
    std::size_t seenBeforeEnd = 0;
    for (std::size_t k = 0; k < w.t.size(); ++k) {
        const double* g = &w.gyr[3 * k];
        online.update(w.t[k], g[1], std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
    }
    seenBeforeEnd = online.events().size();
    online.finish();
    EXPECT_GT(seenBeforeEnd, 0u);  // events come out while streaming, not only at the end
    ASSERT_EQ(online.events().size(), batch.events().size());
    for (std::size_t k = 0; k < batch.events().size(); ++k) EXPECT_EQ(online.events()[k].t, batch.events()[k].t);
}
