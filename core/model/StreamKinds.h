#pragma once
// The known stream kinds: default stream name under a recording, default frame, and the SI unit
// each known column must have. Importers use it to name streams and to check/convert units.
// TDoA streams (kind "lps-tdoa") are stored wide, one dt_<id> column per beacon, and so are ranges
// (kind "lps-range", range_<id>): see core/io/TdoaLayout.h.
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace athlos {

struct KindColumnRule {
    QString prefix;  // column name or prefix, e.g. "acc_" or "x"
    QString unit;    // SI unit, e.g. "m/s^2"
    // Unit of a column given without one (empty: the SI unit above). Barometer pressure is written
    // in hPa by convention (the interchange format and most sensors), stored in Pa.
    QString assumed = {};
};

struct StreamKind {
    QString kind;          // "imu"
    QString defaultName;   // "imu" → stored as <rec>/imu
    QString defaultFrame;  // "sensor"
    bool table = false;    // beacons: a table, not a time series
    std::vector<KindColumnRule> rules;
    QStringList requiredColumns;  // besides t
    QString help;

    // Unit a column of this kind must have, or empty if the kind says nothing about it.
    QString unitFor(const QString& column) const;
    // Unit a column of this kind is read in when its header gives none (KindColumnRule::assumed),
    // or empty: then it is taken as already in unitFor(column).
    QString assumedUnitFor(const QString& column) const;
};

// All known kinds; unknown kinds are allowed (any columns, units as given).
const std::vector<StreamKind>& streamKinds();
const StreamKind* findStreamKind(const QString& kind);
QStringList streamKindNames();

}  // namespace athlos
