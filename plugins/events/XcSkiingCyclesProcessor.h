#pragma once
// Processor `xc-skiing-cycles`: a ski IMU (and optionally the pole IMU of the same side) in, the
// cross-country cycles out (SkiCycleAnalyzer, PoleEventDetector): a per-cycle table (thrust start
// and end, gliding start, duration, speed, length, elevation, slope, pole plant and lift) and
// predicted annotations ("xc cycle", "thrust", "glide start", "pole push").
#include "core/processing/Processor.h"

#include <vector>

namespace athlos::events {

struct SkiCycle;

class XcSkiingCyclesProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("xc-skiing-cycles"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

// The parameters both ski-cycle processors share (axes, speed threshold, cycle bounds).
ParameterSpecs skiCycleParameters(bool crossCountry);
// A per-cycle table column.
TableColumn numberColumn(const QString& name, const QString& unit, std::vector<double> values);
// The columns both ski-cycle tables share, one row per cycle: cycle (1-based), <phase>_start and
// <phase>_end (the thrust, or the motionless phase of skimo), glide_start if `glide`, end, duration,
// speed, length, elevation and slope.
std::vector<TableColumn> skiCycleColumns(const std::vector<SkiCycle>& cycles, const QString& phase, bool glide);

}  // namespace athlos::events
