#pragma once
// How the signal processors treat each column of a stream, decided by its name:
//  - quaternions: four columns <prefix>qw, <prefix>qx, <prefix>qy, <prefix>qz (any prefix, e.g. "ref_");
//    they are one rotation and must never be interpolated or filtered component-wise;
//  - flags: categorical and per-fix columns ("movement", "outlier", "flag", "*_flag"; GNSS fix, fix_quality,
//    sats, satellites, hdop, vdop, pdop) — nearest neighbour only, never filtered;
//  - ordinary: everything else (continuous quantities).
// A quaternion group with a missing component is not a group: its columns count as ordinary.
#include <QString>
#include <QStringList>
#include <array>
#include <vector>

namespace athlos::signal {

struct ColumnGroups {
    std::vector<std::array<int, 4>> quaternions;  // column indices of w, x, y, z
    std::vector<int> flags;
    std::vector<int> ordinary;

    static ColumnGroups detect(const QStringList& names);
    static bool isFlagName(const QString& name);

    bool isQuaternionColumn(int column) const;
    bool isFlagColumn(int column) const;
};

}  // namespace athlos::signal
