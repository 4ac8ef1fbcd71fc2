#include "plugins/positioning/SimulateTrackRunProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/positioning/TrackRunSimulator.h"

#include <limits>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "SimulateTrackRunProcessor"};
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

QString SimulateTrackRunProcessor::name() const { return tr("Simulate track run"); }

QString SimulateTrackRunProcessor::description() const {
    return tr(
        "Simulates an LPS recording of a runner on a track (start acceleration, near-constant speed, lane "
        "changes) with tag noise, outlier bursts, non-uniform sampling and outages, plus the ground truth.");
}

ParameterSpecs SimulateTrackRunProcessor::parameters() const {
    const TrackRunSimulator::Params d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed (deterministic).")),
        PS::number(QStringLiteral("distance"), d.distance, 1.0, 1e5, QStringLiteral("m"), tr("Race distance.")),
        PS::integer(QStringLiteral("lane"), d.lane, 1, 12, tr("Start lane.")),
        PS::number(QStringLiteral("top_speed"), d.topSpeed, 0.5, 15.0, QStringLiteral("m/s"),
                   tr("Speed after the start.")),
        PS::number(QStringLiteral("accel_time"), d.accelTime, 0.1, 20.0, QStringLiteral("s"),
                   tr("Time constant of the start acceleration.")),
        PS::number(QStringLiteral("fatigue"), d.fatigue, 0.0, 0.9, QString(),
                   tr("Fraction of the top speed lost linearly over the distance.")),
        PS::number(QStringLiteral("speed_sd"), d.speedSd, 0.0, 5.0, QStringLiteral("m/s"),
                   tr("SD of the speed fluctuation (Ornstein–Uhlenbeck, 3 s).")),
        PS::number(QStringLiteral("pre_start"), d.preStart, 0.0, 600.0, QStringLiteral("s"),
                   tr("Standing time before the start.")),
        PS::number(QStringLiteral("post_finish"), d.postFinish, 0.0, 600.0, QStringLiteral("s"),
                   tr("Recorded time after the finish.")),
        PS::boolean(QStringLiteral("lane_changes"), d.laneChanges,
                    tr("800 m break to lane 1 after the first bend and random overtakes.")),
        PS::number(QStringLiteral("noise_var_x"), d.noiseVarX, 0.0, 1e3, QStringLiteral("m^2"),
                   tr("Tag noise variance in x.")),
        PS::number(QStringLiteral("noise_var_y"), d.noiseVarY, 0.0, 1e3, QStringLiteral("m^2"),
                   tr("Tag noise variance in y.")),
        PS::number(QStringLiteral("outlier_fraction"), d.outlierFraction, 0.0, 0.9, QString(),
                   tr("Fraction of outliers.")),
        PS::number(QStringLiteral("outlier_burst"), d.outlierBurst, 1.0, 1e3, QString(),
                   tr("Mean outlier burst length (samples).")),
        PS::number(QStringLiteral("outlier_sd"), d.outlierSd, 0.0, 1e3, QStringLiteral("m"),
                   tr("SD of outliers per axis.")),
        PS::number(QStringLiteral("outages"), d.outagesPer400m, 0.0, 100.0, QString(),
                   tr("Mean number of outages per 400 m.")),
        PS::number(QStringLiteral("outage_min"), d.outageMin, 0.0, 600.0, QStringLiteral("s"), tr("Shortest outage.")),
        PS::number(QStringLiteral("outage_max"), d.outageMax, 0.0, 600.0, QStringLiteral("s"), tr("Longest outage.")),
        PS::number(QStringLiteral("truth_rate"), d.truthRate, 1.0, 1000.0, QStringLiteral("Hz"),
                   tr("Sampling rate of the truth (a divisor of 1000).")),
        PS::text(QStringLiteral("track"), QStringLiteral("iaaf-400m"),
                 tr("Track geometry: a name under the project's /geometry or a built-in.")),
        PS::number(QStringLiteral("track_x"), 0.0, -kInf, kInf, QStringLiteral("m"),
                   tr("Track origin x in LPS coordinates.")),
        PS::number(QStringLiteral("track_y"), 0.0, -kInf, kInf, QStringLiteral("m"),
                   tr("Track origin y in LPS coordinates.")),
        PS::number(QStringLiteral("track_rotation"), 0.0, -10.0, 10.0, QStringLiteral("rad"),
                   tr("Rotation of the track frame.")),
    };
}

QList<OutputSpec> SimulateTrackRunProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("lps-position"), false, QString(), tr("Simulated LPS fixes t, x, y (m).")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("truth"),
                       tr("Ground truth t, x, y (m), speed (m/s), heading (rad).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateTrackRunProcessor::run(const RunContext& c) const {
    TrackRunSimulator::Params p;
    p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    p.distance = c.number(QStringLiteral("distance"));
    p.lane = c.integer(QStringLiteral("lane"));
    p.topSpeed = c.number(QStringLiteral("top_speed"));
    p.accelTime = c.number(QStringLiteral("accel_time"));
    p.fatigue = c.number(QStringLiteral("fatigue"));
    p.speedSd = c.number(QStringLiteral("speed_sd"));
    p.preStart = c.number(QStringLiteral("pre_start"));
    p.postFinish = c.number(QStringLiteral("post_finish"));
    p.laneChanges = c.flag(QStringLiteral("lane_changes"));
    p.noiseVarX = c.number(QStringLiteral("noise_var_x"));
    p.noiseVarY = c.number(QStringLiteral("noise_var_y"));
    p.outlierFraction = c.number(QStringLiteral("outlier_fraction"));
    p.outlierBurst = c.number(QStringLiteral("outlier_burst"));
    p.outlierSd = c.number(QStringLiteral("outlier_sd"));
    p.outagesPer400m = c.number(QStringLiteral("outages"));
    p.outageMin = c.number(QStringLiteral("outage_min"));
    p.outageMax = c.number(QStringLiteral("outage_max"));
    p.truthRate = c.number(QStringLiteral("truth_rate"));
    if (p.outageMax < p.outageMin) return makeError(QStringLiteral("outage_max must be >= outage_min"));
    if (std::abs(1000.0 / p.truthRate - std::round(1000.0 / p.truthRate)) > 1e-9)
        return makeError(QStringLiteral("truth_rate must divide 1000 Hz (e.g. 100, 200, 500)"));
    auto track = TrackGeometry::resolve(c.project().geometry(), c.text(QStringLiteral("track")));
    if (!track) return makeError(QStringLiteral("track: %1").arg(track.message()));
    track->setPose({c.number(QStringLiteral("track_x")), c.number(QStringLiteral("track_y")),
                    c.number(QStringLiteral("track_rotation"))});
    p.track = *track;

    c.report(0.0, QStringLiteral("simulating"));
    if (c.isCancelled()) return cancelledError();
    const auto sim = TrackRunSimulator::simulate(p);
    if (c.isCancelled()) return cancelledError();

    StreamData meas(sim.measured.t.size(), 2);
    meas.t = sim.measured.t;
    for (std::size_t k = 0; k < meas.rows(); ++k) {
        meas.at(k, 0) = sim.measured.p[k].x();
        meas.at(k, 1) = sim.measured.p[k].y();
    }
    StreamInfo mi;
    mi.kind = QStringLiteral("lps-position");
    mi.frame = QStringLiteral("lps");
    mi.columns = {{QStringLiteral("x"), QStringLiteral("m")}, {QStringLiteral("y"), QStringLiteral("m")}};
    int outliers = 0;
    for (char o : sim.outlier) outliers += o;
    mi.attributes = QJsonObject{{QStringLiteral("simulated"), true},
                                {QStringLiteral("outliers"), outliers},
                                {QStringLiteral("outage_seconds"), sim.outageSeconds}};

    const auto& tr = sim.truth;
    StreamData truth(tr.t.size(), 4);
    truth.t = tr.t;
    for (std::size_t k = 0; k < truth.rows(); ++k) {
        truth.at(k, 0) = tr.x[k];
        truth.at(k, 1) = tr.y[k];
        truth.at(k, 2) = tr.speed[k];
        truth.at(k, 3) = tr.heading[k];
    }
    StreamInfo ti;
    ti.kind = QStringLiteral("trajectory");
    ti.frame = QStringLiteral("lps");
    ti.columns = {{QStringLiteral("x"), QStringLiteral("m")},
                  {QStringLiteral("y"), QStringLiteral("m")},
                  {QStringLiteral("speed"), QStringLiteral("m/s")},
                  {QStringLiteral("heading"), QStringLiteral("rad")}};
    ti.attributes = QJsonObject{{QStringLiteral("simulated"), true}, {QStringLiteral("sampling_rate"), p.truthRate}};

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), Stream(std::move(mi), std::move(meas))});
    outputs.push_back({QStringLiteral("truth"), Stream(std::move(ti), std::move(truth))});
    c.report(1.0);
    return outputs;
}

}  // namespace athlos::positioning
