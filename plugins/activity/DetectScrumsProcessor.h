#pragma once
// `detect-scrums`: scrums of a multi-athlete session by the top-6 torso pitch (ScrumDetector.h,
// seed 000 §5.1.2). A session is one recording with one stream per athlete and sensor (a folder
// import, core/io/MultiImport.h, or simulate-rugby): the input names one upper-back IMU stream of
// it, and the torso pitch (TorsoPitch.h) of every IMU stream of that recording is used. Positions,
// when the recording has lps-position streams with the same athlete (or label) attribute, add the
// check that the six players stand together. Output: `scrum` annotations on the recording.
#include "core/processing/Processor.h"

namespace athlos::activity {

class DetectScrumsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("detect-scrums"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::activity
