#include "plugins/lps/TdoaSimulator.h"

#include <cmath>

namespace athlos::lps {

const std::vector<Perturbation>& thesisPerturbations() {
    static const std::vector<Perturbation> levels = {{1, 0.5}, {1, 1},   {5, 2.5}, {5, 5},
                                                     {10, 5},  {10, 10}, {20, 10}, {20, 20}};
    return levels;
}

TdoaSimulator::TdoaSimulator(const Params& params, std::uint64_t seed)
    : params_(params), body_(GainPattern::frontLobe(params.bodyExponent, params.bodyBackDb)), rng_(seed) {}

BeaconLayout TdoaSimulator::venue(const VenueParams& venue, const TrackGeometry& track) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double outer =
        track.laneOffset(std::max(1, track.kind() == TrackGeometry::Kind::Oval ? track.ovalParams().lanes : 1)) + 1.0;
    const double length = track.referenceLength();
    BeaconLayout layout;
    for (int i = 0; i < venue.beacons; ++i) {
        // Evenly around the lap with jitter, so every part of the track sees beacons on all sides.
        const double s = (i + 0.3 + 0.4 * unit(rng_)) * length / venue.beacons;
        const double clearance = venue.minClearance + (venue.maxClearance - venue.minClearance) * unit(rng_);
        const TrackPoint p = track.pointAt(s, outer + clearance);
        const double z = venue.minHeight + (venue.maxHeight - venue.minHeight) * unit(rng_);
        layout.ids << QString::number(i + 1);
        layout.positions.emplace_back(p.position.x(), p.position.y(), z);
    }
    return layout;
}

BeaconLayout TdoaSimulator::perturb(const BeaconLayout& layout, const Perturbation& sigma) {
    std::normal_distribution<double> n(0.0, 1.0);
    BeaconLayout guess = layout;
    for (auto& p : guess.positions) {
        p.x() += sigma.sigmaXy * n(rng_);
        p.y() += sigma.sigmaXy * n(rng_);
        p.z() += sigma.sigmaZ * n(rng_);
    }
    return guess;
}

std::vector<TrajectorySample> TdoaSimulator::laps(const TrackGeometry& track, double offset, double speed, double rate,
                                                  double laps, double height, double t0) {
    std::vector<TrajectorySample> samples;
    const double length = track.referenceLength();
    const double dt = 1.0 / rate;
    double s = 0.0;  // arc length along the kerb line
    for (double t = 0.0; s < laps * length; t += dt) {
        const TrackPoint p = track.pointAt(s, offset);
        samples.push_back({t0 + t, Vector3(p.position.x(), p.position.y(), height), p.heading});
        // On a bend the running line is longer than the kerb line by the factor r/r0.
        s += speed * dt * (1.0 - offset * p.curvature);
    }
    return samples;
}

TdoaSimulator::Recording TdoaSimulator::measure(const std::vector<TrajectorySample>& trajectory,
                                                const BeaconLayout& truth) {
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::exponential_distribution<double> exponential(1.0);
    Recording rec;
    rec.truth = trajectory;
    rec.epochs.reserve(trajectory.size());
    rec.nlos.reserve(trajectory.size());
    for (const auto& sample : trajectory) {
        TdoaEpoch epoch{sample.t, {}};
        std::vector<bool> flags;
        for (int i = 0; i < truth.size(); ++i) {
            const Vector3& b = truth.positions[size_t(i)];
            const double geometric = (sample.position - b).norm() - (truth.reference - b).norm();
            double error = params_.noiseSd * normal(rng_);
            if (unit(rng_) < params_.outlierRate) {
                const double e = params_.outlierSd * normal(rng_);
                error = params_.positiveOutliers ? std::abs(e) : e;
            }
            bool shadowed = false;
            if (params_.bodyShadowing) {
                const Vector3 d = b - sample.position;
                const double phi = std::atan2(d.y(), d.x()) - sample.heading;
                const double loss =
                    20.0 * std::log10(std::max(d.norm(), 0.1)) + 20.0 * std::log10(params_.frequency) - 147.55;
                shadowed = body_.gainDb(phi) - loss + params_.linkKappa + params_.fadingDb * normal(rng_) < 0.0;
                if (shadowed) {
                    if (unit(rng_) < params_.nlosDropRate) continue;
                    error += (params_.nlosBiasMin + params_.nlosBiasMean * exponential(rng_)) / kSpeedOfLight;
                }
            }
            epoch.readings.push_back({i, geometric / kSpeedOfLight + params_.timeOffset + error});
            flags.push_back(shadowed);
        }
        rec.epochs.push_back(std::move(epoch));
        rec.nlos.push_back(std::move(flags));
    }
    return rec;
}

}  // namespace athlos::lps
