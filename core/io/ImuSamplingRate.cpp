#include "core/io/ImuSamplingRate.h"

#include <algorithm>
#include <cmath>

namespace athlos {
namespace {

double median(std::vector<double> v) {
    if (v.empty()) return std::nan("");
    const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

}  // namespace

std::vector<ImuSamplingRate::Candidate> ImuSamplingRate::scores(const std::vector<Imu>& imus,
                                                                const std::vector<double>& rates) const {
    const ImuSamplingRate::Params& p = params_;
    std::vector<Candidate> out;
    for (double rate : rates) out.push_back({rate, 0.0, 0});
    for (const Imu& imu : imus) {
        const std::size_t n = std::min(imu.acc.size(), imu.gyr.size());
        // Still samples: slow rotation, and the accelerometer norm close to that of the slow samples.
        std::vector<double> norms;
        for (std::size_t k = 0; k < n; ++k)
            if (imu.gyr[k].norm() < p.stillRate) norms.push_back(imu.acc[k].norm());
        if (norms.empty()) continue;
        const double g = median(norms);
        std::vector<unsigned char> still(n, 0);
        for (std::size_t k = 0; k < n; ++k)
            still[k] = imu.gyr[k].norm() < p.stillRate && std::abs(imu.acc[k].norm() - g) < p.stillAccTolerance;
        for (Candidate& c : out) {
            const double dt = 1.0 / c.rate;
            std::vector<double> misses;
            math::Quat q;
            math::Vec3 v = math::Vec3::Zero();
            double path = 0.0;
            int length = 0;
            bool started = false;
            for (std::size_t k = 0; k < n; ++k) {
                if (still[k]) {
                    if (started && length >= p.minSegmentSamples && path > 0.0) misses.push_back(v.norm() / path);
                    q = math::Quat::FromTwoVectors(imu.acc[k], math::Vec3::UnitZ());  // levelled
                    v.setZero();
                    path = 0.0;
                    length = 0;
                    started = true;
                    continue;
                }
                if (!started) continue;
                q = math::integrateBodyRate(q, imu.gyr[k], dt);
                const math::Vec3 a = q * imu.acc[k] - g * math::Vec3::UnitZ();
                v += a * dt;
                path += a.norm() * dt;
                ++length;
            }
            if (static_cast<int>(misses.size()) < p.minSegments) continue;
            c.score += median(misses);
            c.segments += static_cast<int>(misses.size());
        }
    }
    return out;
}

Expected<ImuSamplingRate::Candidate> ImuSamplingRate::best(const std::vector<Imu>& imus,
                                                           const std::vector<double>& rates) const {
    return best(scores(imus, rates));
}

Expected<ImuSamplingRate::Candidate> ImuSamplingRate::best(const std::vector<Candidate>& all) const {
    if (all.empty()) return makeError(QStringLiteral("no candidate sampling rate"));
    // Every candidate sees the same segments (the still samples do not depend on the rate).
    if (all.front().segments == 0)
        return makeError(QStringLiteral("too few still phases (fewer than %1 between rotations) to tell the "
                                        "sampling rate from the motion")
                             .arg(params_.minSegments));
    return *std::min_element(all.begin(), all.end(),
                             [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
}

}  // namespace athlos
