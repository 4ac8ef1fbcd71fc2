#pragma once
// Importer for CSV exported from ROS bags (`rostopic echo -p` / rqt_bag, --format ros): a header
// `%time,field.…`, `%time` the record time in ns since the Unix epoch, one `field.<path>` column per
// message field. Auto-detected from that header.
//
// The message's own stamp (`field.header.stamp`, else `field.stamp`, else `%time`) becomes t (ns
// precision, t0_utc set); the `field.` prefix is dropped; sequence numbers, the other stamps and text
// fields (frame ids) are left out. Kinds (ImportOptions::kind, or inferred):
//   lps-range  UWB two-way ranging (e.g. Decawave/`field.distanceFromTag`, `field.range`,
//              `field.distance`) with the anchor in `field.id` (or `field.anchor_id`): long t,beacon,range
//   beacons    the anchors' surveyed positions `field.x/y/z` with `field.id`: one row per anchor; an anchor
//              whose position differs between rows by more than 1 mm is an error naming the lines
//   gnss       sensor_msgs/NavSatFix: lat, lon, alt, fix_status (-1 none, 0 fix, 1 SBAS, 2 GBAS)
//   other      the fields under their names (ImportOptions::columns may rename and re-unit them).
#include "core/io/Importer.h"

namespace athlos {

class RosImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("ros"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv", "txt"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
    bool mapsColumns() const override { return true; }
};

}  // namespace athlos
