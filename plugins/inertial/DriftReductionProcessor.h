#pragma once
// `drift-reduction`: static (rest) inclination correction and joint drift reduction of the segment
// orientations of a body-worn sensor chain (DriftReduction.h; Fasel 2017 ch. 2, 5, 6). Inputs are
// pairs (orientation, IMU) per segment, named by the `segments` parameter; outputs are the corrected
// orientation streams with the input's layout, the root's at --output and the others at
// <output>-<segment>.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class DriftReductionProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("drift-reduction"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

// The segment names drift-reduction knows and the chain among them: the parent of a segment
// ("" for the root "sacrum").
QStringList driftReductionSegments();
QString driftReductionParent(const QString& segment);

}  // namespace athlos::inertial
