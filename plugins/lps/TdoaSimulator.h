#pragma once
// Simulated TDoA venues and recordings with the thesis' parameters (§3.1.3, Eqn. 3.5):
//   Δt_i = (|m − b_i| − |r − b_i|)/c + t_off,  t_off = 7 µs, Gaussian noise 3.336·10⁻¹⁰ s (0.1 m),
//   1 % outliers with the noise widened to the equivalent of 20 m (positive by default: late
//   detections), beacons 3–8 m high around a 400 m track, reference node at the origin.
// Initial-guess perturbations follow Table 3.2 (σx/σy/σz per configuration).
//
// Body-shadowing NLOS model for runners [model of this project, after §3.2.2 and Eqns. 2.1, 3.8]:
// the direct path is received when its link margin G_body(φ) − L_fs(d) + κ_link + F > 0, with φ the
// bearing to the beacon relative to the running direction, G_body the tag-on-body pattern
// (front lobe ((1 + cos φ)/2)^8, −35 dB behind; deliberately not the selector's default), L_fs the
// free-space loss at 5.8 GHz and F log-normal shadow fading (σ 3 dB per reading). Otherwise the
// beacon either misses the instant (nlosDropRate) or detects a reflection delayed by
// nlosBiasMin + Exp(nlosBiasMean) metres: positive and unbounded, as NLOS errors are in the thesis.
#include "core/geometry/TrackGeometry.h"
#include "plugins/lps/GainPattern.h"
#include "plugins/lps/Tdoa.h"

#include <cstdint>
#include <random>

namespace athlos::lps {

struct TrajectorySample {
    double t = 0.0;
    Vector3 position = Vector3::Zero();
    double heading = 0.0;  // rad, direction the body faces (= running direction)
};

struct VenueParams {
    int beacons = 12;
    double minHeight = 3.0, maxHeight = 8.0;         // m
    double minClearance = 3.0, maxClearance = 20.0;  // m outside the outer lane
};

// Initial-guess perturbation levels of thesis Table 3.2: {σxy, σz} (m).
struct Perturbation {
    double sigmaXy = 1.0;
    double sigmaZ = 0.5;
};
const std::vector<Perturbation>& thesisPerturbations();

class TdoaSimulator {
public:
    struct Params {
        double timeOffset = 7e-6;              // s
        double noiseSd = 0.1 / kSpeedOfLight;  // s (3.336·10⁻¹⁰)
        double outlierRate = 0.01;
        double outlierSd = 20.0 / kSpeedOfLight;  // s
        bool positiveOutliers = true;
        bool bodyShadowing = false;
        double bodyExponent = 8.0;  // front-lobe exponent of the body pattern
        double bodyBackDb = -35.0;  // dB, gain behind the body
        double linkKappa = 112.0;   // dB, link budget constant (Pt, losses, detection threshold)
        double fadingDb = 3.0;      // dB, shadow-fading σ per reading
        double frequency = 5.8e9;   // Hz
        double nlosDropRate = 0.3;
        double nlosBiasMin = 1.0;   // m
        double nlosBiasMean = 4.0;  // m
    };

    struct Recording {
        std::vector<TdoaEpoch> epochs;
        std::vector<std::vector<bool>> nlos;  // per epoch and reading: body-shadowed
        std::vector<TrajectorySample> truth;  // per epoch
    };

    TdoaSimulator(const Params& params, std::uint64_t seed);

    // Beacons spread around the track outside the outer lane (ids "1".."B"); reference at the origin.
    BeaconLayout venue(const VenueParams& venue, const TrackGeometry& track);
    // The layout with Gaussian errors added to every beacon (reference node unchanged).
    BeaconLayout perturb(const BeaconLayout& layout, const Perturbation& sigma);
    // Constant-speed laps on the running line at lateral offset `offset` (m) from the kerb.
    static std::vector<TrajectorySample> laps(const TrackGeometry& track, double offset, double speed, double rate,
                                              double laps, double height, double t0 = 0.0);
    // TDoA readings of every beacon for each trajectory sample.
    Recording measure(const std::vector<TrajectorySample>& trajectory, const BeaconLayout& truth);

private:
    Params params_;
    GainPattern body_;
    std::mt19937_64 rng_;
};

}  // namespace athlos::lps
