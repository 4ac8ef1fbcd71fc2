#include "core/model/StreamKinds.h"

namespace athlos {

QString StreamKind::unitFor(const QString& column) const {
    // An exact name wins over a prefix ("x" must not match "xyz", "acc_" matches "acc_x").
    for (const auto& rule : rules)
        if (rule.prefix == column && !rule.prefix.endsWith(QLatin1Char('_'))) return rule.unit;
    for (const auto& rule : rules)
        if (rule.prefix.endsWith(QLatin1Char('_')) && column.startsWith(rule.prefix) &&
            column.size() > rule.prefix.size())
            return rule.unit;
    return {};
}

QString StreamKind::assumedUnitFor(const QString& column) const {
    for (const auto& rule : rules)
        if (rule.prefix == column && !rule.prefix.endsWith(QLatin1Char('_'))) return rule.assumed;
    for (const auto& rule : rules)
        if (rule.prefix.endsWith(QLatin1Char('_')) && column.startsWith(rule.prefix) &&
            column.size() > rule.prefix.size())
            return rule.assumed;
    return {};
}

const std::vector<StreamKind>& streamKinds() {
    const QString m = QStringLiteral("m"), mps = QStringLiteral("m/s"), one = QStringLiteral("1");
    static const std::vector<StreamKind> kinds{
        {"imu",
         "imu",
         "sensor",
         false,
         {{"acc_", "m/s^2"}, {"gyr_", "rad/s"}, {"mag_", "uT"}, {"temp", "degC"}},
         {},
         "Inertial samples: acc_x..z (m/s^2), gyr_x..z (rad/s), mag_x..z (uT), any subset."},
        {"lps-position",
         "lps",
         "lps",
         false,
         {{"x", m}, {"y", m}, {"z", m}, {"vx", mps}, {"vy", mps}, {"vz", mps}},
         {"x", "y"},
         "Local positioning fixes: x, y[, z] (m) in the LPS frame."},
        {"lps-tdoa",
         "tdoa",
         "lps",
         false,
         {{"dt", "s"}, {"dt_", "s"}},
         {"beacon", "dt"},
         "Time differences of arrival. CSV in long format t, beacon (id), dt (s); stored wide, one dt_<id> "
         "column per beacon (core/io/TdoaLayout.h)."},
        {"lps-range",
         "range",
         "lps",
         false,
         {{"range", m}, {"range_", m}},
         {"beacon", "range"},
         "Two-way-ranging (time of arrival) distances tag-beacon. CSV in long format t, beacon (id), range (m); "
         "stored wide, one range_<id> column per beacon (core/io/TdoaLayout.h)."},
        {"gnss",
         "gnss",
         "WGS84",
         false,
         {{"lat", "deg"},
          {"lon", "deg"},
          {"alt", m},
          {"vn", mps},
          {"ve", mps},
          {"vd", mps},
          {"x", m},
          {"y", m},
          {"z", m},
          {"vx", mps},
          {"vy", mps},
          {"vz", mps},
          {"hdop", one},
          {"sats", one},
          {"fix", one}},
         {},
         "Satellite fixes: lat, lon (deg), alt (m)[, vn, ve, vd (m/s)] or local x, y, z (m) in ENU."},
        {"beacons",
         "beacons",
         "lps",
         true,
         {{"x", m}, {"y", m}, {"z", m}},
         {"id", "x", "y"},
         "Beacon (anchor) positions: a table id (text), x, y, z (m)."},
        {"orientation",
         "orientation",
         "ENU",
         false,
         {{"qw", one}, {"qx", one}, {"qy", one}, {"qz", one}},
         {"qw", "qx", "qy", "qz"},
         "Orientation quaternions, scalar first, sensor to earth (ENU)."},
        {"reference",
         "reference",
         "ENU",
         false,
         {{"qw", one}, {"qx", one}, {"qy", one}, {"qz", one}, {"pos_", m}, {"movement", one}},
         {},
         "Ground truth from a reference system (optical motion capture): orientation, position."},
        {"trajectory",
         "trajectory",
         "lps",
         false,
         {{"x", m}, {"y", m}, {"z", m}, {"vx", mps}, {"vy", mps}, {"vz", mps}},
         {"x", "y"},
         "Estimated positions (m) and velocities (m/s)."},
        {"gait-parameters",
         "gait-parameters",
         "",
         true,
         {{"start", "s"},
          {"end", "s"},
          {"stride_length", m},
          {"stride_height", m},
          {"stride_time", "s"},
          {"stance_time", "s"},
          {"swing_time", "s"},
          {"cadence", "steps/min"},
          {"gait_speed", mps},
          {"max_toe_clearance", m},
          {"turning_angle", "rad"}},
         {"start", "end", "stride_length"},
         "Per-stride gait parameters from a foot IMU (processor gait-parameters): a table, one row per stride."},
        {"joint-angles", "joint-angles", "segment", false, {}, {}, "Joint angles, one column per angle."},
        {"events", "events", "", false, {}, {}, "Detected instants (gait events, strokes, ...)."},
        {"actions", "actions", "", false, {}, {}, "Classified activities per time."},
        {"barometer",
         "barometer",
         "",
         false,
         {{"pressure", "Pa", "hPa"}, {"temp", "degC"}},
         {"pressure"},
         "Barometric pressure: pressure, stored in Pa; a header without a unit ('pressure') means hPa, "
         "any other pressure unit is converted ('pressure[Pa]', 'pressure (mbar)'); optional temp (degC)."},
    };
    return kinds;
}

const StreamKind* findStreamKind(const QString& kind) {
    for (const auto& k : streamKinds())
        if (k.kind == kind) return &k;
    return nullptr;
}

QStringList streamKindNames() {
    QStringList names;
    for (const auto& k : streamKinds()) names << k.kind;
    return names;
}

}  // namespace athlos
