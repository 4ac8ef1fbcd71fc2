#pragma once
// `simulate-team`: a simulated football match (TeamSimulator.h), 22 players at a fixed rate. No
// inputs. One lps-position stream (t, x, y in m, frame "pitch": 105 × 68 m centred at the origin,
// x along the length) per player, named "<output>-home-01" … "<output>-away-11" (team and shirt
// number); the stream attributes carry label, team, number, role and top speed, and venue
// "football" so views draw the pitch.
//
// Why 22 declared outputs and not one table or a dynamic list: each player is a time series like any
// other position stream (plots, filters, export work on it unchanged), and the runner checks and
// snapshots exactly the declared output names (pipeline undo, refusal to overwrite imported data).
#include "core/processing/Processor.h"

namespace athlos::team {

class SimulateTeamProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-team"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // "home-01" … "away-11": the output suffix of a player (team, shirt number).
    static QString suffixOf(const QString& team, int number);
};

}  // namespace athlos::team
