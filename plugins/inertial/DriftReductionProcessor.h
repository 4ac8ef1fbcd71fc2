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
    QString version() const override { return QStringLiteral("1.1"); }
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
// static_correction=auto: whether the static correction's model (an inclination error that grows
// between rests, DriftReduction::Params::staticCorrection) fits an orientation stream whose `algorithm`
// attribute is this: only a plain gyroscope integration ("strapdown"); not a filter that corrects its
// inclination with the accelerometer (vqf, madgwick, mahony, kalman) nor an unknown source ("").
bool staticCorrectionSuits(const QString& orientationAlgorithm);

}  // namespace athlos::inertial
