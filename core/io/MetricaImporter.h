#pragma once
// Metrica Sports tracking data CSV (--format metrica; detected from its three header rows): one file
// per team, as in Metrica's public sample data (github.com/metrica-sports/sample-data,
// Sample_Game_N_RawTrackingData_{Home,Away}_Team.csv):
//   row 1: ",,,Home,,Home,,..."          the team of each player's column pair
//   row 2: ",,,11,,1,,..."               the jersey numbers
//   row 3: "Period,Frame,Time [s],Player11,,Player1,,...,Ball,"
//   data:  period, frame, time (s), then x, y of every player (and the ball) in pitch units
//          (0..1, x left → right, y top → bottom; empty when the player is not on the pitch).
// Every player (and the ball) becomes a stream <rec>/<team>-<number> (ball: <rec>/ball) of kind
// lps-position in metres on a 105 m × 68 m pitch centred at the origin, x along the pitch, y up
// (attributes: label, team, number, pitch size, period per row in a column "period").
#include "core/io/Importer.h"

namespace athlos {

class MetricaImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("metrica"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
