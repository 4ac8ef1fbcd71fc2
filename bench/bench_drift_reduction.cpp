// Drift reduction + joint angles (issue #17 item 7): 7 segments (pelvis, thighs, shanks, feet) at
// 500 Hz over 10 minutes of simulated skiing, on one core; target < 1 s for the whole chain.
// Input: the body simulator's IMUs and its true sensor orientations with a growing drift of 0.15°/s
// about a random axis per sensor (the drift reduction does the same work whatever the orientation
// source). Static correction, sensor-to-joint fit, both passes and the six hip/knee/ankle angles.
#include "core/math/Angles.h"
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/DriftReduction.h"
#include "plugins/inertial/JointAngles.h"

#include <benchmark/benchmark.h>

#include <random>

using namespace athlos;
using namespace athlos::inertial;

namespace {
constexpr std::array<BodySegment, 7> kSegments{BodySegment::Sacrum,    BodySegment::RightThigh, BodySegment::RightShank,
                                               BodySegment::RightFoot, BodySegment::LeftThigh,  BodySegment::LeftShank,
                                               BodySegment::LeftFoot};
constexpr double kRate = 500.0;

struct Input {
    std::vector<DriftReduction::Segment> segments;
    std::vector<DriftReduction::Link> links;
    std::vector<JointAngles::Params> joints;
    std::size_t samples = 0;
};

const Input& input() {
    static const Input in = [] {
        BodySimulatorParams p;
        p.rate = kRate;
        p.uprightDuration = 10.0;
        p.squats = 3;
        p.standDuration = 3.0;
        p.motionDuration = 600.0 - 10.0 - 12.0 - 6.0;  // 10 minutes in all
        const BodySimulation sim = simulateBody(p);
        Input r;
        r.samples = sim.t.size();
        std::mt19937_64 rng(5);
        std::normal_distribution<double> normal;
        for (BodySegment s : kSegments) {
            const BodySensor& sensor = sim[s];
            DriftReduction::Segment seg;
            seg.acc = sensor.acc;
            seg.gyr = sensor.gyr;
            const math::Vec3 axis = math::Vec3(normal(rng), normal(rng), normal(rng)).normalized();
            seg.q.resize(sim.t.size());
            for (std::size_t k = 0; k < sim.t.size(); ++k)
                seg.q[k] = math::quatFromAxisAngle(axis, 0.15 * math::kDeg * sim.t[k]) * sensor.sensor[k];
            r.segments.push_back(std::move(seg));
        }
        const auto index = [](BodySegment s) {
            return static_cast<int>(std::find(kSegments.begin(), kSegments.end(), s) - kSegments.begin());
        };
        for (int j = 1; j < kBodyJoints; ++j) {  // not the lumbar joint: no sternum here
            const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
            r.links.push_back({index(info.proximal), index(info.distal)});
            JointAngles::Params jp;
            jp.joint = info.joint;
            jp.side = info.side;
            jp.proximalMount = sim[info.proximal].mount;
            jp.distalMount = sim[info.distal].mount;
            r.joints.push_back(jp);
        }
        return r;
    }();
    return in;
}

void driftReductionAndJointAngles(benchmark::State& state) {
    const Input& in = input();
    for (auto _ : state) {
        const DriftReduction::Result r =
            DriftReduction(DriftReduction::onSnow()).run(in.segments, in.links, 1.0 / kRate);
        for (std::size_t j = 0; j < in.links.size(); ++j) {
            const auto angles = JointAngles(in.joints[j])
                                    .updateBatch(r.q[static_cast<std::size_t>(in.links[j].proximal)],
                                                 r.q[static_cast<std::size_t>(in.links[j].distal)]);
            benchmark::DoNotOptimize(angles.data());
        }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(in.samples * kSegments.size()));
}

void jointAnglesOnly(benchmark::State& state) {
    const Input& in = input();
    for (auto _ : state)
        for (std::size_t j = 0; j < in.links.size(); ++j) {
            const auto angles = JointAngles(in.joints[j])
                                    .updateBatch(in.segments[static_cast<std::size_t>(in.links[j].proximal)].q,
                                                 in.segments[static_cast<std::size_t>(in.links[j].distal)].q);
            benchmark::DoNotOptimize(angles.data());
        }
}
}  // namespace

BENCHMARK(driftReductionAndJointAngles)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(jointAnglesOnly)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
