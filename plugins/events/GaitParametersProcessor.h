#pragma once
// Processor `gait-parameters`: a foot IMU stream in; one table row per stride (mid-stance to
// mid-stance, StrideSegmenter) with the spatial parameters from zero-velocity-aided integration
// (StrideIntegrator, or with method = rts the zero-velocity Kalman smoother over the whole recording,
// ZuptKalmanSmoother) and the temporal ones from the gyroscope events, plus the foot trajectory as a
// stream (suffix "trajectory"). Version 2: the `method` parameter and the rts parameters. Version 3:
// ml_axis = auto (the default, MediolateralAxis.h) and heading changes independent of the mounting.
// Version 4: strides of a foot that rolls through its stance. Version 5: the smoother's velocity noise
// follows the dynamics (ZuptKalmanSmoother eq. 3a). Version 6: missing samples up to max_gap bridged
// (ImuGaps.h) instead of a trajectory of NaN; complete recordings give the same results as version 5.
#include "core/processing/Processor.h"

namespace athlos::events {

class GaitParametersProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("gait-parameters"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("6"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
