#pragma once
// `simulate-track-run`: a simulated LPS recording of a runner on a track with its ground truth (see
// TrackRunSimulator.h for the model and the thesis numbers). No inputs. Outputs
//   <output>        lps-position: t, x, y (m) — noisy, outliers in bursts, non-uniform, outages;
//   <output>-truth  trajectory:   t, x, y (m), speed (m/s), heading (rad) at truth_rate.
#include "core/processing/Processor.h"

namespace athlos::positioning {

class SimulateTrackRunProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-track-run"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::positioning
