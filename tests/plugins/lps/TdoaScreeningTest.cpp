// Whole-recording TDoA screening (Fig. 3.16 methods 2 and 3): a tag moving smoothly past ten beacons,
// 0.1 m noise, and isolated late (NLOS) readings of +3 m planted on one beacon; both screens must
// drop the planted readings and keep almost all clean ones, and positioning after the screen must beat
// positioning with every reading.
#include "plugins/lps/TdoaPositioning.h"
#include "plugins/lps/TdoaScreening.h"

#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace athlos::lps;

namespace {

BeaconLayout square() {
    BeaconLayout layout;
    const double xy[10][2] = {{-50, -30}, {0, -35},  {50, -30}, {55, 0},   {50, 30},
                              {0, 35},    {-50, 30}, {-55, 0},  {25, -33}, {-25, 33}};
    for (int i = 0; i < 10; ++i) {
        layout.ids << QString::number(i + 1);
        layout.positions.emplace_back(xy[i][0], xy[i][1], 4.0 + (i % 4));
    }
    return layout;
}

struct Recording {
    std::vector<TdoaEpoch> epochs;
    std::vector<Vector3> truth;
    std::set<std::pair<std::size_t, int>> planted;  // (epoch, beacon)
};

// 60 s at 10 Hz on a circle of radius 20 m at 5 m/s; every `period`-th epoch beacon 4's reading is 3 m
// late.
Recording recording(int period) {
    Recording r;
    std::mt19937 rng(42);
    std::normal_distribution<double> noise(0.0, 0.1);
    const BeaconLayout layout = square();
    for (int k = 0; k < 600; ++k) {
        const double t = 0.1 * k, a = 5.0 * t / 20.0;
        const Vector3 m(20.0 * std::cos(a), 20.0 * std::sin(a), 1.2);
        TdoaEpoch e{t, {}};
        for (int i = 0; i < layout.size(); ++i) {
            const Vector3& b = layout.positions[size_t(i)];
            double extra = noise(rng);
            if (i == 3 && k % period == 7) {
                extra += 3.0;
                r.planted.insert({std::size_t(k), i});
            }
            e.readings.push_back({i, ((m - b).norm() - b.norm() + extra) / kSpeedOfLight + 7e-6});
        }
        r.epochs.push_back(e);
        r.truth.push_back(m);
    }
    return r;
}

double rmse(const std::vector<TagFix>& fixes, const std::vector<Vector3>& truth) {
    double s = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < fixes.size(); ++k)
        if (fixes[k].valid) {
            s += (fixes[k].position - truth[k]).head<2>().squaredNorm();
            ++n;
        }
    return std::sqrt(s / std::max(n, 1));
}

}  // namespace

class TdoaScreeningMethods : public ::testing::TestWithParam<TdoaScreening::Method> {};

TEST_P(TdoaScreeningMethods, DropsPlantedNlosReadingsAndKeepsCleanOnes) {
    // Grubbs' test masks itself when outliers are frequent (each late reading gives two outlying
    // rates, and they inflate the SD): one in 60 readings here; the Kalman gate takes one in 15.
    const Recording r = recording(GetParam() == TdoaScreening::Method::GrubbsRate ? 60 : 15);
    TdoaScreening::Params p;
    p.method = GetParam();
    int dropped = 0;
    const auto screened = TdoaScreening(p).screen(r.epochs, 10, &dropped);
    ASSERT_EQ(screened.size(), r.epochs.size());
    int plantedKept = 0, cleanDropped = 0;
    for (std::size_t k = 0; k < screened.size(); ++k) {
        std::set<int> kept;
        for (const auto& reading : screened[k].readings) kept.insert(reading.beacon);
        for (int i = 0; i < 10; ++i) {
            const bool planted = r.planted.count({k, i}) > 0;
            if (planted && kept.count(i)) ++plantedKept;
            if (!planted && !kept.count(i)) ++cleanDropped;
        }
    }
    EXPECT_EQ(plantedKept, 0) << "of " << r.planted.size() << " planted";
    EXPECT_LT(cleanDropped, 60) << "of " << 6000 - r.planted.size() << " clean readings";  // < 1 %
    EXPECT_GT(r.planted.size(), 9u);
    EXPECT_EQ(dropped, int(r.planted.size()) + cleanDropped);

    TdoaPositioning::Params all;
    all.selection.method = BeaconSelection::Method::All;
    TdoaPositioning::Params screenedParams = all;
    screenedParams.screening = p;
    const double before = rmse(*TdoaPositioning(all, square()).run(r.epochs), r.truth);
    const double after = rmse(*TdoaPositioning(screenedParams, square()).run(r.epochs), r.truth);
    EXPECT_LT(after, 0.8 * before) << "RMSE " << before << " m with every reading, " << after << " m screened";
}

INSTANTIATE_TEST_SUITE_P(Methods, TdoaScreeningMethods,
                         ::testing::Values(TdoaScreening::Method::GrubbsRate, TdoaScreening::Method::KalmanGate));

TEST(TdoaScreening, GrubbsIsMaskedByFrequentOutliers) {
    // The limitation the thesis' Fig. 3.16 shows (Grubbs 4.61 m vs all 4.72 m): with one late reading in
    // 15 the SD of the rates is so inflated that the test finds none of them.
    const Recording r = recording(15);
    TdoaScreening::Params p;
    p.method = TdoaScreening::Method::GrubbsRate;
    int dropped = -1;
    TdoaScreening(p).screen(r.epochs, 10, &dropped);
    EXPECT_LT(dropped, int(r.planted.size()) / 2);
}

TEST(TdoaScreening, NoneKeepsEverything) {
    const Recording r = recording(15);
    int dropped = -1;
    const auto out = TdoaScreening(TdoaScreening::Params()).screen(r.epochs, 10, &dropped);
    EXPECT_EQ(dropped, 0);
    ASSERT_EQ(out.size(), r.epochs.size());
    EXPECT_EQ(out[7].readings.size(), 10u);
}
