#pragma once
// Walking speed from a wrist (WristSpeedModel, Fasel thesis ch. 12, eq. 12.6–12.7), in two
// processors that share the inputs' reading:
//   `wrist-speed-train`: wrist-cadence windows + barometer + a reference speed (any stream with a
//     `speed` column, m/s) [+ an earlier model table, whose training rows are kept] → a table of
//     kind `wrist-speed-model`: one row per training window (t, the four features, the reference
//     speed), the fitted model (scaling, 16 centroids, 16 linear models) in its attributes. Chaining
//     runs over several walkers trains one model on all of them.
//   `wrist-speed`: wrist-cadence windows + barometer + a model table → stream `wrist-speed`: speed
//     (m/s, NaN when not walking) and the cluster used, at the cadence windows' times.
#include "core/processing/Processor.h"

namespace athlos::events {

class WristSpeedTrainProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("wrist-speed-train"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

class WristSpeedProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("wrist-speed"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
