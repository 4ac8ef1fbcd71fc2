#pragma once
// Vendor CSV exports, detected from their header content (--format statsports | catapult | kinexon),
// imported through the CSV engine with the vendor's column names mapped to Athlos channels and units.
// A file with several athletes (an athlete column with more than one value) gives one stream per
// athlete (<rec>/<athlete>), the athlete's name (and number, team where the file has them) on the
// stream's attributes; line numbers in messages stay those of the original file.
//
// The layouts are written from the vendors' published export descriptions as far as known to the
// author (no vendor file was available while writing this; see tests/core/VendorFormatsTest.cpp):
//   statsports  STATSports Apex/Sonra 10 Hz raw export: Player Display Name, Time (clock or date-time),
//               Elapsed Time (s), Lat, Lon, Speed (m/s), Heart Rate (bpm), Instantaneous Acceleration
//               Impulse → gnss (lat, lon, speed, hr, acc_impulse)
//   catapult    Catapult OpenField raw CSV export: '#' preamble (Athlete, ...), Timestamp, Seconds, Velocity,
//               Acceleration, Odometer, Latitude, Longitude, Heart Rate, Player Load, Positional Quality (%),
//               HDOP, #Sats → gnss
//   kinexon     Kinexon position export: ts in ms (Unix), sensor id, full name, x in m, y in m, z in m,
//               speed in m/s → lps-position, one stream per player
#include "core/io/Importer.h"

#include <vector>

namespace athlos {

struct VendorColumn {
    const char* source;  // header name without its unit, compared case-insensitively
    const char* channel;
    const char* unit;  // unit of the values ("" = the header's, or the kind's)
};

struct VendorProfile {
    const char* format;
    const char* description;
    const char* kind;
    std::vector<std::vector<const char*>> signatures;  // any complete set of header names identifies the format
    std::vector<const char*> timeColumns;              // the first present one is t
    const char* timeFormat;  // a TimeFormats name, or "" = ISO, clock or s from the first cell
    std::vector<VendorColumn> columns;
    std::vector<const char*> athleteColumns;  // the first present one names the athlete (one stream each)
};

class VendorCsvImporter final : public Importer {
public:
    explicit VendorCsvImporter(const VendorProfile& profile) : profile_(profile) {}
    QString format() const override;
    QString description() const override;
    QStringList extensions() const override { return {"csv", "txt"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
    bool mapsColumns() const override { return true; }

    static const std::vector<VendorProfile>& profiles();

private:
    const VendorProfile& profile_;
};

}  // namespace athlos
