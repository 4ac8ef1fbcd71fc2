#pragma once
// Processor `gait-events`: a foot IMU stream in, its strides out as predicted annotations
// ("stride left" / "stride right", IC to next IC, confidence from GaitEventDetector) plus a table
// of the events (t, type ic/tc/min_vel, foot).
#include "core/processing/Processor.h"

namespace athlos::events {

class GaitEventsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("gait-events"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("2"); }  // 2: ml_axis = auto
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // "left" / "right" from the stream's name or its "sensor" attribute, else empty.
    static QString footOf(const StreamInfo& info);
};

}  // namespace athlos::events
