#include "plugins/activity/FeatureSelection.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace athlos::activity {

namespace {
// NaN after every number, so the sort is a strict weak ordering whatever the features hold.
bool lessNanLast(float a, float b) { return a < b || (!std::isnan(a) && std::isnan(b)); }
bool same(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }
}  // namespace

std::vector<double> mutualInformation(const cv::Mat& samples, const std::vector<int>& labels, int classCount,
                                      int bins) {
    const int n = samples.rows;
    std::vector<double> out(std::size_t(samples.cols), 0.0);
    if (n == 0 || classCount < 1 || bins < 1 || int(labels.size()) != n) return out;
    std::vector<double> classCounts(std::size_t(classCount), 0.0);
    for (int c : labels) classCounts[std::size_t(c)] += 1.0;
    std::vector<int> order(static_cast<std::size_t>(n));
    std::vector<float> column(static_cast<std::size_t>(n));
    std::vector<double> joint(static_cast<std::size_t>(bins) * std::size_t(classCount)),
        binCounts(static_cast<std::size_t>(bins));
    for (int j = 0; j < samples.cols; ++j) {
        for (int i = 0; i < n; ++i) column[std::size_t(i)] = samples.at<float>(i, j);
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](int a, int b) { return lessNanLast(column[std::size_t(a)], column[std::size_t(b)]); });
        std::fill(joint.begin(), joint.end(), 0.0);
        std::fill(binCounts.begin(), binCounts.end(), 0.0);
        // Equal-frequency bins by rank; a run of equal values takes the bin of its first rank.
        std::size_t bin = 0;
        for (int r = 0; r < n; ++r) {
            const int row = order[std::size_t(r)];
            if (r == 0 || !same(column[std::size_t(row)], column[std::size_t(order[std::size_t(r - 1)])]))
                bin = std::min(std::size_t(bins - 1), std::size_t((long long)r * bins / n));
            joint[bin * std::size_t(classCount) + std::size_t(labels[std::size_t(row)])] += 1.0;
            binCounts[bin] += 1.0;
        }
        // I(X; C) = Σ p(x, c) log2 p(x, c) / (p(x) p(c))  (Cover & Thomas eq. 2.28), counts over N.
        double mi = 0;
        for (std::size_t b = 0; b < std::size_t(bins); ++b)
            for (std::size_t c = 0; c < std::size_t(classCount); ++c) {
                const double nbc = joint[b * std::size_t(classCount) + c];
                if (nbc > 0) mi += nbc * std::log2(nbc * double(n) / (binCounts[b] * classCounts[c]));
            }
        out[std::size_t(j)] = std::max(0.0, mi / double(n));
    }
    return out;
}

FeatureSelection FeatureSelection::top(const std::vector<double>& mi, int k, const QStringList& names, int bins) {
    FeatureSelection s;
    s.bins = bins;
    std::vector<int> order(mi.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return mi[std::size_t(a)] > mi[std::size_t(b)]; });
    if (k > 0 && std::size_t(k) < order.size()) order.resize(std::size_t(k));
    for (int c : order) {
        s.columns.push_back(c);
        s.names << names.value(c);
        s.bits.push_back(mi[std::size_t(c)]);
    }
    return s;
}

FeatureSelection FeatureSelection::fit(const cv::Mat& samples, const std::vector<int>& labels, int classCount, int k,
                                       const QStringList& names, int bins) {
    return top(mutualInformation(samples, labels, classCount, bins), k, names, bins);
}

cv::Mat FeatureSelection::apply(const cv::Mat& samples) const {
    cv::Mat out(samples.rows, int(columns.size()), CV_32F);
    for (int i = 0; i < samples.rows; ++i) {
        const float* in = samples.ptr<float>(i);
        float* o = out.ptr<float>(i);
        for (std::size_t j = 0; j < columns.size(); ++j) o[j] = in[columns[j]];
    }
    return out;
}

QJsonObject FeatureSelection::toJson() const {
    QJsonArray mi;
    for (double b : bits) mi.append(b);
    return {{QStringLiteral("method"), QStringLiteral("mutual-information")},
            {QStringLiteral("estimator"), QStringLiteral("equal-frequency bins, plug-in")},
            {QStringLiteral("bins"), bins},
            {QStringLiteral("k"), size()},
            {QStringLiteral("features"), QJsonArray::fromStringList(names)},
            {QStringLiteral("mi_bits"), mi}};
}

Expected<FeatureSelection> FeatureSelection::fromJson(const QJsonObject& json, const QStringList& features) {
    FeatureSelection s;
    s.bins = json.value(QStringLiteral("bins")).toInt(kDefaultBins);
    const QJsonArray names = json.value(QStringLiteral("features")).toArray();
    const QJsonArray mi = json.value(QStringLiteral("mi_bits")).toArray();
    if (names.isEmpty()) return makeError(QStringLiteral("its feature selection lists no features"));
    for (qsizetype i = 0; i < names.size(); ++i) {
        const QString name = names[i].toString();
        const int column = int(features.indexOf(name));
        if (column < 0)
            return makeError(
                QStringLiteral("its feature selection names '%1', which is not one of its features").arg(name));
        s.columns.push_back(column);
        s.names << name;
        s.bits.push_back(mi.at(i).toDouble());
    }
    return s;
}

QString FeatureSelection::toText(int count) const {
    QString out;
    int width = 8;
    for (const QString& n : names) width = std::max(width, int(n.size()));
    for (int i = 0; i < std::min(count, size()); ++i)
        out += QStringLiteral("%1  %2  %3 bits\n")
                   .arg(i + 1, 4)
                   .arg(names[i], -width)
                   .arg(bits[std::size_t(i)], 0, 'f', 3);
    return out;
}

}  // namespace athlos::activity
