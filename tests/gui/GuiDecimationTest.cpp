// MinMaxPyramid against brute force: every pixel column's min and max must equal the extremes of
// the samples in it (no peak lost), in time order, on random data with single-sample spikes.
#include "ui/MinMaxPyramid.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace athlos;
using namespace athlos::ui;

namespace {

struct BruteExtremes {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    long long argMin = -1, argMax = -1;
    bool empty() const { return argMin < 0; }
};

BruteExtremes brute(const StreamData& d, int column, std::size_t begin, std::size_t end) {
    BruteExtremes e;
    for (std::size_t i = begin; i < end; ++i) {
        const double v = d.at(i, column);
        if (std::isnan(v)) continue;
        if (v < e.min) {
            e.min = v;
            e.argMin = (long long)i;
        }
        if (v > e.max) {
            e.max = v;
            e.argMax = (long long)i;
        }
    }
    return e;
}

// Random walk with non-uniform time steps, NaN gaps and isolated spikes of both signs.
std::shared_ptr<StreamData> randomData(std::size_t rows, int columns, unsigned seed,
                                       std::vector<std::size_t>* spikes = nullptr) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> step(0.001, 0.02);
    std::normal_distribution<double> noise(0.0, 1.0);
    auto d = std::make_shared<StreamData>(rows, columns);
    double t = 3.0;
    std::vector<double> level(std::size_t(columns), 0.0);
    for (std::size_t i = 0; i < rows; ++i) {
        t += step(rng);
        d->t[i] = t;
        for (int c = 0; c < columns; ++c) {
            level[std::size_t(c)] += noise(rng);
            d->at(i, c) = level[std::size_t(c)];
        }
    }
    std::uniform_int_distribution<std::size_t> index(0, rows - 1);
    for (int k = 0; k < 40; ++k) {
        const std::size_t i = index(rng);
        d->at(i, 0) += (k % 2 ? -1.0 : 1.0) * (5000.0 + k);
        if (spikes) spikes->push_back(i);
    }
    for (int k = 0; k < 20; ++k) d->at(index(rng), 0) = std::numeric_limits<double>::quiet_NaN();
    return d;
}

}  // namespace

class GuiDecimationTest : public QObject {
    Q_OBJECT

private slots:
    void combineKeepsTimeOrder();
    void rangeExtremesMatchBruteForce_data();
    void rangeExtremesMatchBruteForce();
    void envelopeMatchesBruteForcePerPixel_data();
    void envelopeMatchesBruteForcePerPixel();
    void spikesSurviveFullRange();
    void rawSamplesWhenZoomedIn();
    void edgeCases();
};

void GuiDecimationTest::combineKeepsTimeOrder() {
    const Extremes low{-1, -1, true}, high{5, 5, true};
    QVERIFY(Extremes::combine(low, high).minFirst);
    QVERIFY(!Extremes::combine(high, low).minFirst);
    const Extremes both = Extremes::combine(Extremes::combine(high, low), Extremes{0, 0, true});
    QCOMPARE(both.min, -1.0);
    QCOMPARE(both.max, 5.0);
    QVERIFY(!both.minFirst);
    QVERIFY(Extremes().isEmpty());
    QCOMPARE(Extremes::combine(Extremes(), low).min, -1.0);
}

void GuiDecimationTest::rangeExtremesMatchBruteForce_data() {
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("column");
    QTest::newRow("tiny") << 7 << 0;
    QTest::newRow("one bucket") << 16 << 1;
    QTest::newRow("odd size") << 12345 << 0;
    QTest::newRow("power of four") << 65536 << 2;
    QTest::newRow("large") << 300001 << 0;
}

void GuiDecimationTest::rangeExtremesMatchBruteForce() {
    QFETCH(int, rows);
    QFETCH(int, column);
    auto data = randomData(std::size_t(rows), 3, 42u + unsigned(rows));
    const MinMaxPyramid pyramid(data, column);
    QCOMPARE(pyramid.size(), std::size_t(rows));

    std::mt19937_64 rng(7);
    std::uniform_int_distribution<std::size_t> index(0, std::size_t(rows));
    for (int k = 0; k < 3000; ++k) {
        std::size_t a = index(rng), b = index(rng);
        if (a > b) std::swap(a, b);
        // Mix in long, bucket-aligned and short ranges.
        if (k % 3 == 0) b = std::min<std::size_t>(std::size_t(rows), a + std::size_t(k % 70));
        const Extremes e = pyramid.rangeExtremes(a, b);
        const BruteExtremes r = brute(*data, column, a, b);
        if (r.empty()) {
            QVERIFY2(e.isEmpty(), qPrintable(QStringLiteral("[%1,%2)").arg(a).arg(b)));
            continue;
        }
        QCOMPARE(e.min, r.min);
        QCOMPARE(e.max, r.max);
        QCOMPARE(e.minFirst, r.argMin <= r.argMax);
    }
}

void GuiDecimationTest::envelopeMatchesBruteForcePerPixel_data() {
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("pixels");
    QTest::addColumn<double>("from");  // fraction of the time span
    QTest::addColumn<double>("to");
    QTest::newRow("full, 1000 px") << 200000 << 1000 << 0.0 << 1.0;
    QTest::newRow("full, 37 px") << 200000 << 37 << 0.0 << 1.0;
    QTest::newRow("middle") << 200000 << 640 << 0.31 << 0.62;
    QTest::newRow("beyond both ends") << 50000 << 800 << -0.2 << 1.3;
    QTest::newRow("narrow, many samples per px") << 500000 << 1280 << 0.5 << 0.56;
}

void GuiDecimationTest::envelopeMatchesBruteForcePerPixel() {
    QFETCH(int, rows);
    QFETCH(int, pixels);
    QFETCH(double, from);
    QFETCH(double, to);
    auto data = randomData(std::size_t(rows), 1, 1234u);
    const MinMaxPyramid pyramid(data, 0);
    const double span = data->t.back() - data->t.front();
    const double t0 = data->t.front() + from * span, t1 = data->t.front() + to * span;
    const DecimatedSeries s = pyramid.decimate(t0, t1, pixels);
    QVERIFY(!s.raw);
    QVERIFY(s.keys.size() <= 2 * pixels + 2);
    QCOMPARE(s.keys.size(), s.values.size());
    QVERIFY(std::is_sorted(s.keys.begin(), s.keys.end()));

    // Brute force: walk the samples, assigning each to its pixel column [t0 + p·dt, t0 + (p+1)·dt).
    const double dt = (t1 - t0) / pixels;
    std::vector<BruteExtremes> columns(static_cast<std::size_t>(pixels));
    int p = 0;
    long long visible = 0;
    BruteExtremes all;
    for (std::size_t i = 0; i < data->rows(); ++i) {
        const double t = data->t[i];
        if (t < t0 || t > t1) continue;
        ++visible;
        while (p < pixels - 1 && t >= t0 + (p + 1) * dt) ++p;
        BruteExtremes& c = columns[std::size_t(p)];
        const double v = data->at(i, 0);
        if (std::isnan(v)) continue;
        if (v < c.min) {
            c.min = v;
            c.argMin = (long long)i;
        }
        if (v > c.max) {
            c.max = v;
            c.argMax = (long long)i;
        }
        if (v < all.min) {
            all.min = v;
            all.argMin = 0;
        }
        if (v > all.max) all.max = v;
    }
    QCOMPARE(s.visibleSamples, visible);
    QCOMPARE(s.visible.min, all.min);
    QCOMPARE(s.visible.max, all.max);

    // The decimated points inside each column must be exactly its (min, max) in time order.
    qsizetype k = 0;
    while (k < s.keys.size() && s.keys[k] < t0) ++k;  // the neighbour before the range
    for (int q = 0; q < pixels; ++q) {
        const BruteExtremes& c = columns[std::size_t(q)];
        const double x1 = t0 + (q + 1) * dt;
        QList<double> inColumn;
        while (k < s.keys.size() && s.keys[k] < x1 && s.keys[k] <= t1) inColumn << s.values[k++];
        if (c.empty()) {
            QVERIFY2(inColumn.isEmpty(), qPrintable(QStringLiteral("column %1 should be empty").arg(q)));
            continue;
        }
        if (c.min == c.max) {
            QCOMPARE(inColumn.size(), 1);
            QCOMPARE(inColumn[0], c.min);
            continue;
        }
        QCOMPARE(inColumn.size(), 2);
        const bool minFirst = c.argMin < c.argMax;
        QCOMPARE(inColumn[0], minFirst ? c.min : c.max);
        QCOMPARE(inColumn[1], minFirst ? c.max : c.min);
    }
}

void GuiDecimationTest::spikesSurviveFullRange() {
    std::vector<std::size_t> spikes;
    auto data = randomData(1'000'000, 1, 99u, &spikes);
    const MinMaxPyramid pyramid(data, 0);
    const DecimatedSeries s = pyramid.decimate(data->t.front(), data->t.back(), 800);
    QVERIFY(s.keys.size() <= 2 * 800 + 2);
    const double t0 = data->t.front(), dt = (data->t.back() - t0) / 800;
    for (std::size_t i : spikes) {
        const double v = data->at(i, 0);
        if (std::isnan(v)) continue;
        // The spike's pixel column must plot a point at least as extreme as the spike (equal,
        // unless a bigger spike of the same sign shares the column).
        int p = 0;
        while (p < 799 && data->t[i] >= t0 + (p + 1) * dt) ++p;
        bool found = false;
        for (qsizetype k = 0; k < s.keys.size(); ++k) {
            if (s.keys[k] < t0 + p * dt || s.keys[k] >= t0 + (p + 1) * dt) continue;
            found = found || (v > 0 ? s.values[k] >= v : s.values[k] <= v);
        }
        QVERIFY2(found, qPrintable(QStringLiteral("spike at sample %1 (%2) lost").arg(i).arg(v)));
    }
}

void GuiDecimationTest::rawSamplesWhenZoomedIn() {
    auto data = randomData(100000, 1, 5u);
    const MinMaxPyramid pyramid(data, 0);
    const double t0 = data->t[50000], t1 = data->t[50300];
    const DecimatedSeries s = pyramid.decimate(t0, t1, 1000);
    QVERIFY(s.raw);
    QCOMPARE(s.visibleSamples, 301);
    // The visible samples plus one neighbour on each side, exactly.
    QCOMPARE(s.keys.size(), 303);
    for (qsizetype k = 0; k < s.keys.size(); ++k) {
        const std::size_t i = 49999 + std::size_t(k);
        QCOMPARE(s.keys[k], data->t[i]);
        const double v = data->at(i, 0);
        if (std::isnan(v))
            QVERIFY(std::isnan(s.values[k]));
        else
            QCOMPARE(s.values[k], v);
    }
}

void GuiDecimationTest::edgeCases() {
    QCOMPARE(MinMaxPyramid().decimate(0, 1, 100).keys.size(), 0);
    auto empty = std::make_shared<StreamData>(0, 1);
    QCOMPARE(MinMaxPyramid(empty, 0).decimate(0, 1, 100).keys.size(), 0);
    QCOMPARE(MinMaxPyramid(empty, 3).size(), std::size_t(0));  // bad column

    auto one = std::make_shared<StreamData>(1, 1);
    one->t[0] = 2.0;
    one->at(0, 0) = 7.0;
    const DecimatedSeries s = MinMaxPyramid(one, 0).decimate(0, 10, 100);
    QCOMPARE(s.keys.size(), 1);
    QCOMPARE(s.values[0], 7.0);

    // A range entirely between two samples still shows the line through it.
    auto two = std::make_shared<StreamData>(2, 1);
    two->t = {0.0, 10.0};
    two->values = {1.0, 2.0};
    const DecimatedSeries between = MinMaxPyramid(two, 0).decimate(4, 6, 100);
    QCOMPARE(between.keys.size(), 2);
    QCOMPARE(between.visibleSamples, 0);
}

QTEST_GUILESS_MAIN(GuiDecimationTest)
#include "GuiDecimationTest.moc"
