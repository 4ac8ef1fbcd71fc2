#pragma once
// How TDoA measurements are stored.
//
// Interchange (CSV) is long: `t,beacon,dt`, one row per (instant, beacon), so t repeats. A stream
// needs strictly increasing t, so a TDoA stream (kind "lps-tdoa") is stored wide: one row per
// instant, one column per beacon named "dt_<id>" (unit s), NaN where that beacon did not receive
// the fix. attributes["beacon_ids"] lists the ids (text, as in the file) in column order.
// Export writes the long form back (NaN cells are skipped), so CSV round-trips.
//
// Two-way ranging (kind "lps-range", long CSV `t,beacon,range`, m) is stored the same way with
// "range_<id>" columns (unit m): the LongLayout of a kind says which.
#include "core/model/Stream.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

namespace athlos {

struct TdoaSample {
    double t = 0.0;      // s
    QString beacon;      // id as written in the file
    double dt = 0.0;     // s (the range in m for lps-range)
    long long line = 0;  // source line, for error messages (0 if unknown)
};

// A per-beacon measurement stored wide: kind, the long-form value column and its unit.
struct LongLayout {
    QString kind;   // "lps-tdoa", "lps-range"
    QString value;  // "dt", "range": the long column; wide columns are "<value>_<id>"
    QString unit;   // "s", "m"
    QString columnName(const QString& beaconId) const { return value + QLatin1Char('_') + beaconId; }
    QString beaconId(const QString& column) const;  // empty for other columns
};
// The layout of a long-format kind, or nullptr.
const LongLayout* longLayoutOf(const QString& kind);

// Groups long-form samples (ordered by non-decreasing t) into a wide stream of layout's kind.
Expected<Stream> longStreamFromSamples(const std::vector<TdoaSample>& samples, const QString& file,
                                       const LongLayout& layout);
// Calls visit(t, beaconId, value) for every measurement of a wide stream in time order.
void forEachLongSample(const LongLayout& layout, const StreamInfo& info, const StreamData& data,
                       const std::function<void(double, const QString&, double)>& visit);

inline QString tdoaColumnName(const QString& beaconId) { return QStringLiteral("dt_") + beaconId; }
// Beacon id of a "dt_<id>" column, or empty for other columns.
QString tdoaBeaconId(const QString& column);

// Groups long-form samples (ordered by non-decreasing t) into a wide TDoA stream.
// Errors: a time that goes backwards (line named), the same beacon twice at one instant (line named).
// file is only used in messages.
Expected<Stream> tdoaStreamFromSamples(const std::vector<TdoaSample>& samples, const QString& file);

// Calls visit(t, beaconId, dt) for every measurement of a wide TDoA stream in time order.
void forEachTdoaSample(const StreamInfo& info, const StreamData& data,
                       const std::function<void(double, const QString&, double)>& visit);

}  // namespace athlos
