#include "core/io/TdoaLayout.h"

#include <QJsonArray>
#include <QSet>
#include <cmath>
#include <limits>
#include <map>

namespace athlos {

QString tdoaBeaconId(const QString& column) {
    return column.startsWith(QLatin1String("dt_")) ? column.mid(3) : QString();
}

Expected<Stream> tdoaStreamFromSamples(const std::vector<TdoaSample>& samples, const QString& file) {
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
            return makeError(QStringLiteral("%1:%2: time %3 s goes backwards (previous instant %4 s); TDoA rows must be "
                                            "ordered by time")
                                 .arg(file)
                                 .arg(s.line)
                                 .arg(s.t, 0, 'g', 17)
                                 .arg(data.t.back(), 0, 'g', 17));
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
    info.kind = QStringLiteral("lps-tdoa");
    info.frame = QStringLiteral("lps");
    for (const auto& id : ids) info.columns.push_back({tdoaColumnName(id), QStringLiteral("s")});
    info.attributes[QStringLiteral("beacon_ids")] = QJsonArray::fromStringList(ids);
    info.attributes[QStringLiteral("layout")] = QStringLiteral("wide: one row per instant, dt_<id> per beacon, NaN = not received");
    return Stream(std::move(info), std::move(data));
}

void forEachTdoaSample(const StreamInfo& info, const StreamData& data,
                       const std::function<void(double, const QString&, double)>& visit) {
    QStringList ids;
    for (const auto& c : info.columns) ids << tdoaBeaconId(c.name);
    for (std::size_t r = 0; r < data.rows(); ++r)
        for (int c = 0; c < data.columns; ++c) {
            const double dt = data.at(r, c);
            if (!std::isnan(dt) && !ids[c].isEmpty()) visit(data.t[r], ids[c], dt);
        }
}

}  // namespace athlos
