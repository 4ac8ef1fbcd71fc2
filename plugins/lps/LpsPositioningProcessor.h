#pragma once
// `lps-positioning`: per-instant TDoA fixes (thesis Eqn. 2.5) with beacon selection (§3.2).
// Inputs: a TDoA stream (long form, see TdoaStream.h), a beacon table from any recording, and
// optionally an orientation stream (heading for the field-of-view rule).
// Output (kind lps-position): t, x, y, z (m), offset (s, t_off), rms_residual (m), n_beacons, dop (dilution
// of precision over the beacons that reported: σ_pos ≈ dop·σ_range; BeaconGeometry.h); attribute `geometry`:
// "ok" or why the beacon layout cannot give observable fixes (clustered, collinear, coplanar).
// Two-way ranges (lps-range) instead of TDoA: ToA fixes (RangeSolver.h) every `epoch` seconds from each
// anchor's newest range (mergeRangeEpochs), with selection all or irls; offset is then 0.
// Instants with fewer than min_beacons readings or without a plausible solution are left out
// (counted in the stream attributes fixes_total / fixes_dropped).
#include "core/processing/Processor.h"
#include "plugins/lps/TdoaPositioning.h"

namespace athlos::lps {

class LpsPositioningProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("lps-positioning"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // Planar unless the beacons' height span is at least 30 % of their horizontal extent.
    static bool geometryAllows3d(const BeaconLayout& layout);

private:
    struct Plan;
    Expected<Plan> makePlan(const RunContext& context) const;
    Expected<Plan> makeRangePlan(const RunContext& context) const;
    static std::optional<std::vector<TagFix>> solveRanges(const Plan& plan, const RunContext& context);
};

}  // namespace athlos::lps
