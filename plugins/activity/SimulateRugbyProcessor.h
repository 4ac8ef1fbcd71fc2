#pragma once
// `simulate-rugby`: a simulated rugby sevens match (RugbySimulator.h) with truth annotations. No
// inputs. Like simulate-team and a folder import of a session (core/io/MultiImport.h), one
// recording holds one stream per player and sensor: "<output>-imu-home-01" (kind imu, 200 Hz, acc
// m/s², gyr rad/s) and "<output>-pos-home-01" (kind lps-position, ~80 Hz, frame "pitch"), the
// stream attributes carrying athlete, label, team and number; the true `scrum` and `tackle`
// intervals are annotations of the recording.
#include "core/processing/Processor.h"

namespace athlos::activity {

class SimulateRugbyProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-rugby"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::activity
