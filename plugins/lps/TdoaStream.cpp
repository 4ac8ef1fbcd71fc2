#include "plugins/lps/TdoaStream.h"

#include "core/io/TdoaLayout.h"
#include "plugins/lps/BeaconTable.h"

#include <QJsonArray>
#include <cmath>
#include <map>

namespace athlos::lps {

namespace {

Error unknownBeaconsError(const QString& path, const QStringList& unknown, const BeaconLayout& layout) {
    return makeError(QStringLiteral("TDoA stream '%1' uses beacon id(s) %2 that the beacon table does not have "
                                    "(table ids: %3)")
                         .arg(path, unknown.join(QStringLiteral(", ")), layout.ids.join(QStringLiteral(", "))));
}

Expected<EpochSet> epochsFromWide(const Stream& stream, const StreamData& data, const BeaconLayout& layout,
                                  const QString& path) {
    const StreamInfo& info = stream.info();
    std::vector<int> beaconOf(info.columns.size(), -1);
    QStringList unknown;
    bool any = false;
    for (std::size_t c = 0; c < info.columns.size(); ++c) {
        const QString id = tdoaBeaconId(info.columns[c].name);
        if (id.isEmpty()) continue;
        any = true;
        beaconOf[c] = matchBeaconId(layout, id);
        if (beaconOf[c] < 0) unknown << id;
    }
    if (!any)
        return makeError(QStringLiteral("TDoA stream '%1' has no dt_<beacon> columns (nor beacon and dt); it has: %2")
                             .arg(path, info.columnNames().join(QStringLiteral(", "))));
    if (!unknown.isEmpty()) return unknownBeaconsError(path, unknown, layout);
    EpochSet set;
    set.epochs.reserve(data.rows());
    for (std::size_t r = 0; r < data.rows(); ++r) {
        TdoaEpoch epoch{data.t[r], {}};
        for (int c = 0; c < data.columns; ++c) {
            const double dt = data.at(r, c);
            if (beaconOf[size_t(c)] < 0 || std::isnan(dt)) continue;
            if (!std::isfinite(dt)) {
                ++set.readingsSkipped;
                continue;
            }
            epoch.readings.push_back({beaconOf[size_t(c)], dt});
        }
        set.epochs.push_back(std::move(epoch));
    }
    return set;
}

}  // namespace

Expected<EpochSet> epochsFromStream(const Stream& stream, const StreamData& data, const BeaconLayout& layout,
                                    const QString& path) {
    const StreamInfo& info = stream.info();
    const int beaconColumn = info.columnIndex(QStringLiteral("beacon"));
    const int dtColumn = info.columnIndex(QStringLiteral("dt"));
    if (beaconColumn < 0 || dtColumn < 0) return epochsFromWide(stream, data, layout, path);
    const QJsonArray textIds = info.attributes.value(QStringLiteral("beacon_ids")).toArray();

    // Each distinct stream id is matched once; unknown ids are collected for one message.
    std::map<double, int> indexOfValue;
    QStringList unknown;
    auto resolve = [&](double value) -> int {
        if (auto it = indexOfValue.find(value); it != indexOfValue.end()) return it->second;
        QString id;
        if (!textIds.isEmpty()) {
            const auto k = static_cast<qsizetype>(value);
            id = (value >= 0 && k < textIds.size() && double(k) == value) ? textIds[k].toString()
                                                                          : QString::number(value, 'g', 17);
        } else {
            id = QString::number(value, 'g', 17);
        }
        const int index = matchBeaconId(layout, id);
        if (index < 0) unknown << id;
        indexOfValue.emplace(value, index);
        return index;
    };

    EpochSet set;
    const double tolerance = 1e-9;  // instants of one epoch share t exactly; allow float round-off
    for (std::size_t r = 0; r < data.rows(); ++r) {
        const double t = data.t[r];
        const double beacon = data.at(r, beaconColumn);
        const double dt = data.at(r, dtColumn);
        if (!std::isfinite(dt) || !std::isfinite(beacon)) {
            ++set.readingsSkipped;
            continue;
        }
        const int index = resolve(beacon);
        if (index < 0) continue;
        if (set.epochs.empty() || t > set.epochs.back().t + tolerance) {
            if (!set.epochs.empty() && t < set.epochs.back().t - tolerance)
                return makeError(QStringLiteral("TDoA stream '%1': time goes back at row %2 (%3 s after %4 s)")
                                     .arg(path)
                                     .arg(r + 1)
                                     .arg(t, 0, 'g', 12)
                                     .arg(set.epochs.back().t, 0, 'g', 12));
            set.epochs.push_back({t, {}});
        }
        auto& readings = set.epochs.back().readings;
        bool duplicate = false;
        for (const auto& reading : readings) duplicate = duplicate || reading.beacon == index;
        if (duplicate)
            return makeError(QStringLiteral("TDoA stream '%1': beacon %2 appears twice at t = %3 s (row %4)")
                                 .arg(path, layout.ids[index])
                                 .arg(t, 0, 'g', 12)
                                 .arg(r + 1));
        readings.push_back({index, dt});
    }
    if (!unknown.isEmpty()) return unknownBeaconsError(path, unknown, layout);
    return set;
}

Stream streamFromEpochs(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& layout, const QString& name) {
    std::vector<TdoaSample> samples;
    for (const auto& e : epochs)
        for (const auto& reading : e.readings) samples.push_back({e.t, layout.ids[reading.beacon], reading.dt, 0});
    auto stream = tdoaStreamFromSamples(samples, name);
    // Only fails on times going backwards or duplicate beacons, which the epochs cannot contain.
    Stream out = stream ? std::move(*stream) : Stream();
    out.info().name = name;
    return out;
}

}  // namespace athlos::lps
