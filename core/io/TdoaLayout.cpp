#include "core/io/TdoaLayout.h"

#include <QJsonArray>
#include <QSet>
#include <cmath>
#include <limits>
#include <map>

namespace athlos {

const LongLayout* longLayoutOf(const QString& kind) {
    static const LongLayout kLayouts[] = {
        {QStringLiteral("lps-tdoa"), QStringLiteral("dt"), QStringLiteral("s")},
        {QStringLiteral("lps-range"), QStringLiteral("range"), QStringLiteral("m")},
    };
    for (const LongLayout& l : kLayouts)
        if (l.kind == kind) return &l;
    return nullptr;
}

QString LongLayout::beaconId(const QString& column) const {
    const QString prefix = value + QLatin1Char('_');
    return column.startsWith(prefix) ? column.mid(prefix.size()) : QString();
}

QString tdoaBeaconId(const QString& column) { return longLayoutOf(QStringLiteral("lps-tdoa"))->beaconId(column); }

Expected<Stream> tdoaStreamFromSamples(const std::vector<TdoaSample>& samples, const QString& file) {
    return longStreamFromSamples(samples, file, *longLayoutOf(QStringLiteral("lps-tdoa")));
}

void forEachTdoaSample(const StreamInfo& info, const StreamData& data,
                       const std::function<void(double, const QString&, double)>& visit) {
    forEachLongSample(*longLayoutOf(QStringLiteral("lps-tdoa")), info, data, visit);
}

Expected<Stream> longStreamFromSamples(const std::vector<TdoaSample>& samples, const QString& file,
                                       const LongLayout& layout) {
    // Column order: order of first appearance, so the stream reads like the file.
    QStringList ids;
    std::map<QString, int> columnOf;
    for (const auto& s : samples) {
        if (columnOf.emplace(s.beacon, int(ids.size())).second) ids << s.beacon;
    }
    const int columns = int(ids.size());
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    StreamData data;
    data.columns = columns;
    QSet<int> seenAtInstant;
    for (const auto& s : samples) {
        if (!std::isfinite(s.t))
            return makeError(QStringLiteral("%1:%2: time '%3' is not a finite number").arg(file).arg(s.line).arg(s.t));
        const bool newInstant = data.t.empty() || s.t > data.t.back();
        if (!newInstant && s.t < data.t.back())
            return makeError(QStringLiteral("%1:%2: time %3 s goes backwards (previous instant %4 s); %5 rows must be "
                                            "ordered by time")
                                 .arg(file)
                                 .arg(s.line)
                                 .arg(s.t, 0, 'g', 17)
                                 .arg(data.t.back(), 0, 'g', 17)
                                 .arg(layout.kind));
        if (newInstant) {
            data.t.push_back(s.t);
            data.values.insert(data.values.end(), std::size_t(columns), nan);
            seenAtInstant.clear();
        }
        const int c = columnOf.at(s.beacon);
        if (seenAtInstant.contains(c))
            return makeError(QStringLiteral("%1:%2: beacon '%3' appears twice at t = %4 s")
                                 .arg(file)
                                 .arg(s.line)
                                 .arg(s.beacon)
                                 .arg(s.t, 0, 'g', 17));
        seenAtInstant.insert(c);
        data.at(data.rows() - 1, c) = s.dt;
    }

    StreamInfo info;
    info.kind = layout.kind;
    info.frame = QStringLiteral("lps");
    for (const auto& id : ids) info.columns.push_back({layout.columnName(id), layout.unit});
    info.attributes[QStringLiteral("beacon_ids")] = QJsonArray::fromStringList(ids);
    info.attributes[QStringLiteral("layout")] =
        QStringLiteral("wide: one row per instant, %1_<id> per beacon, NaN = not received").arg(layout.value);
    return Stream(std::move(info), std::move(data));
}

void forEachLongSample(const LongLayout& layout, const StreamInfo& info, const StreamData& data,
                       const std::function<void(double, const QString&, double)>& visit) {
    QStringList ids;
    for (const auto& c : info.columns) ids << layout.beaconId(c.name);
    for (std::size_t r = 0; r < data.rows(); ++r)
        for (int c = 0; c < data.columns; ++c) {
            const double dt = data.at(r, c);
            if (!std::isnan(dt) && !ids[c].isEmpty()) visit(data.t[r], ids[c], dt);
        }
}

}  // namespace athlos
