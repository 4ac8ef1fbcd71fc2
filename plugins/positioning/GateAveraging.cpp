#include "plugins/positioning/GateAveraging.h"

#include <complex>

namespace athlos::positioning {

using math::Vec3;

Expected<std::vector<Vec3>> GateAveraging::average(const std::vector<std::vector<Vec3>>& runs) {
    if (runs.empty()) return makeError(QStringLiteral("no runs to average"));
    const std::size_t M = runs.front().size();
    if (M < 2) return makeError(QStringLiteral("needs at least two gates per run"));
    for (std::size_t r = 0; r < runs.size(); ++r)
        if (runs[r].size() != M)
            return makeError(QStringLiteral("run %1 has %2 gates, run 1 has %3: the gates cannot be paired in order")
                                 .arg(r + 1)
                                 .arg(runs[r].size())
                                 .arg(M));
    Vec3 first = Vec3::Zero(), last = Vec3::Zero();
    for (const auto& run : runs) {
        first += run.front();
        last += run.back();
    }
    first /= double(runs.size());
    last /= double(runs.size());
    using C = std::complex<double>;
    const C F(first.x(), first.y()), L(last.x(), last.y());
    std::vector<Vec3> mean(M, Vec3::Zero());
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const auto& run = runs[r];
        const C f(run.front().x(), run.front().y()), l(run.back().x(), run.back().y());
        if (std::abs(l - f) < 1e-6)
            return makeError(QStringLiteral("run %1: its first and last gates coincide").arg(r + 1));
        const C a = (L - F) / (l - f);  // rotation and scale
        const double dz = run.back().z() - run.front().z();
        const double sz = std::abs(dz) > 1e-6 ? (last.z() - first.z()) / dz : 1.0;
        for (std::size_t m = 0; m < M; ++m) {
            const C p = F + a * (C(run[m].x(), run[m].y()) - f);
            mean[m] += Vec3(p.real(), p.imag(), first.z() + sz * (run[m].z() - run.front().z()));
        }
    }
    for (auto& g : mean) g /= double(runs.size());
    return mean;
}

}  // namespace athlos::positioning
