#include "plugins/signal/ColumnGroups.h"

#include <algorithm>

namespace athlos::signal {

bool ColumnGroups::isFlagName(const QString& name) {
    // Satellite fix quality, satellite count and dilution of precision (NMEA GGA/GSA fields, vendor
    // exports) are per-fix indicators: a value between two fixes was never observed (issue #13).
    static const QStringList kGnssQuality{"fix",      "fix_quality", "quality", "sats", "satellites",
                                          "num_sats", "nsat",        "hdop",    "vdop", "pdop"};
    const QString lower = name.toLower();
    return lower == QLatin1String("movement") || lower == QLatin1String("outlier") || lower == QLatin1String("flag") ||
           lower.endsWith(QLatin1String("_flag")) || kGnssQuality.contains(lower);
}

ColumnGroups ColumnGroups::detect(const QStringList& names) {
    ColumnGroups groups;
    std::vector<bool> taken(static_cast<std::size_t>(names.size()), false);
    for (int w = 0; w < names.size(); ++w) {
        if (!names[w].endsWith(QLatin1String("qw"))) continue;
        const QString prefix = names[w].chopped(2);
        const int x = static_cast<int>(names.indexOf(prefix + QLatin1String("qx")));
        const int y = static_cast<int>(names.indexOf(prefix + QLatin1String("qy")));
        const int z = static_cast<int>(names.indexOf(prefix + QLatin1String("qz")));
        if (x < 0 || y < 0 || z < 0) continue;
        groups.quaternions.push_back({w, x, y, z});
        for (int c : {w, x, y, z}) taken[static_cast<std::size_t>(c)] = true;
    }
    for (int c = 0; c < names.size(); ++c) {
        if (taken[static_cast<std::size_t>(c)]) continue;
        (isFlagName(names[c]) ? groups.flags : groups.ordinary).push_back(c);
    }
    return groups;
}

bool ColumnGroups::isQuaternionColumn(int column) const {
    return std::any_of(quaternions.begin(), quaternions.end(), [column](const std::array<int, 4>& q) {
        return std::find(q.begin(), q.end(), column) != q.end();
    });
}

bool ColumnGroups::isFlagColumn(int column) const {
    return std::find(flags.begin(), flags.end(), column) != flags.end();
}

}  // namespace athlos::signal
