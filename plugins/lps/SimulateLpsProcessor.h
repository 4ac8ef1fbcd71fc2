#pragma once
// `simulate-lps`: a simulated venue (beacons 3–8 m high around a 400 m track, reference node at the
// origin) and one recording on it with the thesis' TDoA error model (TdoaSimulator.h). No inputs.
// Outputs: <output> the TDoA stream exactly as the CSV importer produces it (kind lps-tdoa),
// "<output>-beacons" the surveyed table, "<output>-guess" the perturbed initial table (Table 3.2
// levels via sigma_xy/sigma_z), "<output>-truth" the tag trajectory t, x, y, z (m).
// venue_seed fixes the venue so that a walk and a test run can share it.
#include "core/processing/Processor.h"

namespace athlos::lps {

class SimulateLpsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-lps"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::lps
