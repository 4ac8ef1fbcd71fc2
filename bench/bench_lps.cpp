// LPS positioning speed: 12-beacon planar TDoA fixes per second on one core (target ≥ 50 000/s),
// comparing the TinySolver hot path with a full ceres::Problem per fix (the robust-loss backend),
// and the selection methods' cost; plus the calibration's track-gauge fit of a one-lap walk (TrackGauge.h).
// Figures go to docs/PERFORMANCE.md.
#include "plugins/lps/TdoaPositioning.h"
#include "plugins/lps/TdoaSimulator.h"
#include "plugins/lps/TrackGauge.h"

#include <benchmark/benchmark.h>

using namespace athlos;
using namespace athlos::lps;

namespace {

struct Fixture {
    BeaconLayout beacons;
    std::vector<TdoaEpoch> epochs;
    Fixture() {
        const TrackGeometry track;
        TdoaSimulator sim(TdoaSimulator::Params(), 11);
        beacons = sim.venue(VenueParams(), track);  // 12 beacons
        epochs = sim.measure(TdoaSimulator::laps(track, 1.5, 6.0, 10.0, 1.0, 1.2), beacons).epochs;
    }
};

const Fixture& fixture() {
    static const Fixture f;
    return f;
}

void positioning(benchmark::State& state, BeaconSelection::Method method, TdoaSolver::Loss loss) {
    const Fixture& f = fixture();
    TdoaPositioning::Params p;
    p.selection.method = method;
    p.solver.loss = loss;
    TdoaPositioning positioning(p, f.beacons);
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(positioning.update(f.epochs[k]));
        if (++k == f.epochs.size()) k = 0;
    }
    state.SetItemsProcessed(state.iterations());  // items = fixes
}

// θ and lateral offset of a 290-fix lane-3 walk (1 Hz, one lap) against the 400 m oval.
void trackGaugeFit(benchmark::State& state) {
    const TrackGeometry track;
    std::vector<Vector3> walk;
    for (const auto& s : TdoaSimulator::laps(track, track.laneOffset(3), 1.4, 1.0, 1.0, 1.0))
        walk.push_back(s.position);
    for (auto _ : state) benchmark::DoNotOptimize(fitTrackGauge(walk, Vector3::Zero(), track));
}

}  // namespace

BENCHMARK(trackGaugeFit);
BENCHMARK_CAPTURE(positioning, all_tiny, BeaconSelection::Method::All, TdoaSolver::Loss::None);
BENCHMARK_CAPTURE(positioning, irls_tiny, BeaconSelection::Method::Irls, TdoaSolver::Loss::None);
BENCHMARK_CAPTURE(positioning, largest_residual_tiny, BeaconSelection::Method::LargestResidual, TdoaSolver::Loss::None);
BENCHMARK_CAPTURE(positioning, field_of_view_tiny, BeaconSelection::Method::FieldOfView, TdoaSolver::Loss::None);
BENCHMARK_CAPTURE(positioning, all_ceres_problem_huber, BeaconSelection::Method::All, TdoaSolver::Loss::Huber);

BENCHMARK_MAIN();
