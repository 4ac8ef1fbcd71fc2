#pragma once
// `wrist-cadence`: walking cadence and walking detection from a wrist IMU's accelerometer
// (WristCadence, Fasel thesis ch. 12). One row per 6 s window, shifted by 1 s, at the window's
// centre: cadence (steps/min, NaN when not walking), walking (1/0), likelihood (the comb maximum),
// norm_max and norm_std (m/s², the speed features of eq. 12.6). Kind `wrist-cadence`.
#include "core/processing/Processor.h"
#include "plugins/events/WristCadence.h"

namespace athlos::events {

class WristCadenceProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("wrist-cadence"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // The windows back from a `wrist-cadence` stream (for wrist-speed), or an error naming the input.
    static Expected<std::vector<CadenceWindow>> windowsOf(const RunContext& context, int input);
};

}  // namespace athlos::events
