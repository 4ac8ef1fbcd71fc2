#pragma once
// GPX 1.1 (and 1.0) tracks (--format gpx; detected from the extension or a <gpx root): every <trkpt>
// of every <trk>/<trkseg> in file order becomes one row of a `gnss` stream: lat, lon (deg), alt (m,
// <ele>), and from Garmin's TrackPointExtension (gpxtpx:hr, cad, speed) hr (Hz, from bpm), cad (Hz,
// from rpm), speed (m/s) where present. t from the first point's <time>; t0_utc set.
// Layout: GPX 1.1 schema, https://www.topografix.com/GPX/1/1/ ; Garmin TrackPointExtension v1/v2.
// Errors name the file, line and column of the element (a point without <time>, a bad number).
#include "core/io/Importer.h"

namespace athlos {

class GpxImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("gpx"); }
    QString description() const override;
    QStringList extensions() const override { return {"gpx"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
