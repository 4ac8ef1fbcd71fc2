#include "plugins/lps/RangeStream.h"

#include "core/io/TdoaLayout.h"
#include "plugins/lps/BeaconTable.h"

#include <cmath>
#include <limits>
#include <map>

namespace athlos::lps {

Expected<RangeSet> rangesFromStream(const Stream& stream, const StreamData& data, const BeaconLayout& layout,
                                    const QString& path) {
    const LongLayout* ranges = longLayoutOf(QStringLiteral("lps-range"));
    const StreamInfo& info = stream.info();
    if (info.kind != ranges->kind)
        return makeError(QStringLiteral("stream '%1' is of kind '%2', not lps-range").arg(path, info.kind));
    std::map<QString, int> indexOf;
    QStringList unknown;
    for (const auto& column : info.columns) {
        const QString id = ranges->beaconId(column.name);
        if (id.isEmpty()) continue;
        const int index = matchBeaconId(layout, id);
        if (index < 0) unknown << id;
        indexOf.emplace(id, index);
    }
    if (indexOf.empty())
        return makeError(QStringLiteral("range stream '%1' has no range_<beacon> columns; it has: %2")
                             .arg(path, info.columnNames().join(QStringLiteral(", "))));
    if (!unknown.isEmpty())
        return makeError(QStringLiteral("range stream '%1' uses beacon id(s) %2 that the beacon table does not have "
                                        "(table ids: %3)")
                             .arg(path, unknown.join(QStringLiteral(", ")), layout.ids.join(QStringLiteral(", "))));
    RangeSet set;
    forEachLongSample(*ranges, info, data, [&](double t, const QString& id, double range) {
        if (!std::isfinite(t) || !std::isfinite(range) || range < 0) {
            ++set.readingsSkipped;
            return;
        }
        set.readings.push_back({t, indexOf.at(id), range});
    });
    return set;
}

}  // namespace athlos::lps

namespace athlos::lps {

std::vector<TdoaEpoch> mergeRangeEpochs(const std::vector<RangeReading>& readings, int beacons, double step,
                                        double maxAge, int minBeacons) {
    std::vector<TdoaEpoch> epochs;
    if (readings.empty() || !(step > 0)) return epochs;
    std::vector<double> lastT(std::size_t(beacons), -std::numeric_limits<double>::infinity());
    std::vector<double> lastRange(std::size_t(beacons), 0.0);
    const double t0 = std::ceil(readings.front().t / step) * step;
    std::size_t k = 0;
    for (long long n = 0;; ++n) {
        const double t = t0 + double(n) * step;
        if (t > readings.back().t + step) break;
        while (k < readings.size() && readings[k].t <= t) {
            lastT[std::size_t(readings[k].beacon)] = readings[k].t;
            lastRange[std::size_t(readings[k].beacon)] = readings[k].range;
            ++k;
        }
        TdoaEpoch epoch{t, {}};
        for (int b = 0; b < beacons; ++b)
            if (t - lastT[std::size_t(b)] <= maxAge) epoch.readings.push_back({b, lastRange[std::size_t(b)]});
        if (int(epoch.readings.size()) >= minBeacons) epochs.push_back(std::move(epoch));
    }
    return epochs;
}

}  // namespace athlos::lps
