#pragma once
// Importer for NMEA-0183 text logs (--format nmea): RMC, GGA and VTG sentences of any talker
// (GP, GN, GL, GA, BD, ...) are merged per epoch (same UTC time of day) into one `gnss` stream:
//   lat, lon (deg, WGS84), alt (m above mean sea level, GGA), vn, ve (m/s, from speed over ground and
//   course), vd (NaN: NMEA has no vertical speed), fix (GGA quality: 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK
//   float), sats (1), hdop (1).
// t is seconds since the first fix; attributes.t0_utc is its UTC time, the date from RMC (or
// ImportOptions::date; without either only the time of day is known, with a warning). A time that
// jumps back by more than 12 h is past midnight; sentences without a fix never move the day.
// Anything before a line's '$' (binary noise) is ignored.
// Epochs without a valid fix (RMC status V, GGA quality 0) are left out. Sentences with a wrong
// checksum are skipped with a warning naming the line; a sentence with a valid checksum but an
// unreadable field is an error naming the line and field. Other sentences are ignored.
#include "core/io/Importer.h"

namespace athlos {

class NmeaImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("nmea"); }
    QString description() const override;
    QStringList extensions() const override { return {"nmea", "nma", "gps", "txt", "log"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
    // The parser on text (file names the source in messages); used by read() and tests.
    static Expected<ImportResult> parse(const QByteArray& text, const QString& file, const ImportOptions& options = {});
};

}  // namespace athlos
