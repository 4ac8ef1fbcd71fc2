#include "plugins/lps/SimulateLpsProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/TdoaSimulator.h"
#include "plugins/lps/TdoaStream.h"

#include <cmath>

namespace athlos::lps {

namespace {
constexpr Translator tr{"athlos::lps", "SimulateLpsProcessor"};
}  // namespace

QString SimulateLpsProcessor::name() const { return tr("Simulate LPS venue and recording"); }

QString SimulateLpsProcessor::description() const {
    return tr(
        "Simulated TDoA venue around a 400 m track and a calibration walk or a run on it: 7 µs offset, 0.1 m noise, "
        "1 % positive outliers of 20 m, optional body-shadowing NLOS; plus surveyed and perturbed beacon tables "
        "and the true trajectory.");
}

ParameterSpecs SimulateLpsProcessor::parameters() const {
    const int maxInt = std::numeric_limits<int>::max();
    return {
        ParameterSpec::choice(
            QStringLiteral("scenario"), {QStringLiteral("walk"), QStringLiteral("run")}, QStringLiteral("walk"),
            tr("walk: calibration walk in lane 1 (1.4 m/s, 1 Hz, 1.0 m); run: a runner (6 m/s, 10 Hz, 1.2 m).")),
        ParameterSpec::integer(QStringLiteral("seed"), 1, 0, maxInt, tr("Seed of the measurement noise.")),
        ParameterSpec::integer(QStringLiteral("venue_seed"), 1, 0, maxInt,
                               tr("Seed of the venue and the initial guess.")),
        ParameterSpec::integer(QStringLiteral("beacons"), 12, 4, 64, tr("Number of beacons.")),
        ParameterSpec::number(QStringLiteral("laps"), 1.0, 0.01, 100, QString(), tr("Laps of the 400 m track.")),
        ParameterSpec::integer(QStringLiteral("lane"), 1, 1, 8, tr("Lane whose running line is followed.")),
        ParameterSpec::number(QStringLiteral("speed"), 0.0, 0.0, 20, QStringLiteral("m/s"),
                              tr("Speed; 0 = scenario default.")),
        ParameterSpec::number(QStringLiteral("rate"), 0.0, 0.0, 1000, QStringLiteral("Hz"),
                              tr("Fix rate; 0 = scenario default.")),
        ParameterSpec::number(QStringLiteral("tag_height"), -1.0, -1.0, 100, QStringLiteral("m"),
                              tr("Tag height; negative = scenario default (walk 1.0 m, run 1.2 m).")),
        ParameterSpec::number(QStringLiteral("start_time"), 0.0, 0.0, 1e9, QStringLiteral("s"),
                              tr("Time of the first instant.")),
        ParameterSpec::number(QStringLiteral("sigma_xy"), 1.0, 0.0, 1000, QStringLiteral("m"),
                              tr("Horizontal error of the initial guess (thesis Table 3.2).")),
        ParameterSpec::number(QStringLiteral("sigma_z"), 0.5, 0.0, 1000, QStringLiteral("m"),
                              tr("Vertical error of the initial guess.")),
        ParameterSpec::number(QStringLiteral("noise"), 0.1, 0.0, 100, QStringLiteral("m"),
                              tr("TDoA noise σ as a distance (c·σ_t).")),
        ParameterSpec::number(QStringLiteral("outlier_rate"), 0.01, 0.0, 1.0, QString(),
                              tr("Share of readings that are outliers.")),
        ParameterSpec::number(QStringLiteral("outlier_sigma"), 20.0, 0.0, 10000, QStringLiteral("m"),
                              tr("Outlier σ as a distance (positive errors).")),
        ParameterSpec::boolean(QStringLiteral("nlos"), false,
                               tr("Body-shadowing NLOS of a chest-worn tag (run scenario).")),
        ParameterSpec::number(QStringLiteral("time_offset"), 7e-6, -1, 1, QStringLiteral("s"),
                              tr("Offset t_off common to all beacons.")),
    };
}

QList<OutputSpec> SimulateLpsProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("lps-tdoa"), false, QString(), tr("TDoA readings t, beacon, dt (s).")},
            OutputSpec{QStringLiteral("beacons"), true, QStringLiteral("beacons"), tr("Surveyed beacon table.")},
            OutputSpec{QStringLiteral("beacons"), true, QStringLiteral("guess"), tr("Perturbed initial beacon table.")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("truth"),
                       tr("True tag trajectory t, x, y, z (m).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateLpsProcessor::run(const RunContext& context) const {
    const bool walk = context.text(QStringLiteral("scenario")) == QLatin1String("walk");
    const double speed =
        context.number(QStringLiteral("speed")) > 0 ? context.number(QStringLiteral("speed")) : (walk ? 1.4 : 6.0);
    const double rate =
        context.number(QStringLiteral("rate")) > 0 ? context.number(QStringLiteral("rate")) : (walk ? 1.0 : 10.0);
    const double height = context.number(QStringLiteral("tag_height")) >= 0
                              ? context.number(QStringLiteral("tag_height"))
                              : (walk ? 1.0 : 1.2);
    const TrackGeometry track = TrackGeometry::iaaf400m();
    const auto venueSeed = std::uint64_t(context.integer(QStringLiteral("venue_seed")));

    // The venue and the guess depend on venue_seed only; the readings on seed.
    TdoaSimulator venueSim(TdoaSimulator::Params(), venueSeed);
    VenueParams venue;
    venue.beacons = context.integer(QStringLiteral("beacons"));
    const BeaconLayout surveyed = venueSim.venue(venue, track);
    const BeaconLayout guess = venueSim.perturb(
        surveyed, {context.number(QStringLiteral("sigma_xy")), context.number(QStringLiteral("sigma_z"))});

    TdoaSimulator::Params p;
    p.noiseSd = context.number(QStringLiteral("noise")) / kSpeedOfLight;
    p.outlierRate = context.number(QStringLiteral("outlier_rate"));
    p.outlierSd = context.number(QStringLiteral("outlier_sigma")) / kSpeedOfLight;
    p.bodyShadowing = context.flag(QStringLiteral("nlos"));
    p.timeOffset = context.number(QStringLiteral("time_offset"));
    TdoaSimulator sim(p, std::uint64_t(context.integer(QStringLiteral("seed"))) * 7919u + venueSeed);
    const auto trajectory = TdoaSimulator::laps(track, track.laneOffset(context.integer(QStringLiteral("lane"))), speed,
                                                rate, context.number(QStringLiteral("laps")), height,
                                                context.number(QStringLiteral("start_time")));
    if (context.isCancelled()) return cancelledError();
    const auto recording = sim.measure(trajectory, surveyed);
    context.report(0.9, QStringLiteral("writing"));

    StreamData truth(recording.truth.size(), 3);
    for (std::size_t k = 0; k < recording.truth.size(); ++k) {
        truth.t[k] = recording.truth[k].t;
        for (int c = 0; c < 3; ++c) truth.at(k, c) = recording.truth[k].position(c);
    }
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), streamFromEpochs(recording.epochs, surveyed)});
    outputs.push_back({QStringLiteral("beacons"), tableFromLayout(surveyed)});
    outputs.push_back({QStringLiteral("guess"), tableFromLayout(guess, QStringLiteral("guess"))});
    outputs.push_back(
        {QStringLiteral("truth"), outputStream(QStringLiteral("trajectory"), QStringLiteral("lps"),
                                               columnsOf({"x", "y", "z"}, {"m", "m", "m"}), std::move(truth))});
    context.report(1.0);
    return outputs;
}

}  // namespace athlos::lps
