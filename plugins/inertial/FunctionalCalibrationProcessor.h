#pragma once
// `functional-calibration`: the whole functional calibration protocol (FunctionalCalibration.h) from
// one recording of up to sixteen IMUs. The movements are found automatically, or taken from interval
// annotations of the recording labelled with a movement's name (upright, squats, trunk-rotations,
// right-abduction, left-abduction, arm-swings) or from the `intervals` parameter. Writes the segment-calibration
// table that joint-angles reads, plus "<output>-quality" (per segment: χ, orthogonality, CMC and the
// movement that gave the frame) and "<output>-movements" (what was found, with the repetitions).
// A separate processor rather than a mode of segment-calibration: its inputs (named by `segments`,
// up to sixteen) and outputs differ, and segment-calibration keeps its simple two-window contract.
#include "core/processing/Processor.h"

namespace athlos::inertial {

inline const QString kCalibrationQualityKind = QStringLiteral("functional-calibration-quality");
inline const QString kCalibrationMovementsKind = QStringLiteral("functional-calibration-movements");

class FunctionalCalibrationProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("functional-calibration"); }
    QString name() const override;
    QString description() const override;
    // 1.1: head, upper back, upper arms and forearms; arm swings.
    QString version() const override { return QStringLiteral("1.1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
