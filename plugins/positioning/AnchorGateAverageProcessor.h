#pragma once
// `anchor-gate-average`: GNSS-free gate positions (Fasel thesis ch. 10) from the crossings tables of
// several `anchor-smoother` runs on the same course (their est_east/north/up: the ZUPT-only gate
// estimates; run the smoother with passes=0 when no gates table exists yet — any gates table with
// the right number of rows serves as a placeholder). Inputs run1 … run8 (tables, run1 and run2
// required); output a gates table (id, east, north, up) in the mean frame of the runs, which
// `anchor-smoother` then takes as its gates input.
#include "core/processing/Processor.h"

namespace athlos::positioning {

class AnchorGateAverageProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("anchor-gate-average"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override { return {}; }
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::positioning
