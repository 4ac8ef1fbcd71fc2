#pragma once
// What the LPS processor tests share: running a processor as the CLI does, and the horizontal RMSE
// of fixes against the simulated truth.
#include "core/processing/ProcessorRunner.h"

#include <cmath>

namespace athlos::lps::testsupport {

inline Status run(Project& project, const Processor& p, QStringList inputs, QString output, QVariantMap params = {},
                  const Progress& progress = {}) {
    auto outcome = runProcessor(project, p, RunRequest{p.id(), inputs, output, params}, progress);
    return outcome ? Status() : Status(outcome.error());
}

// Over the fixes whose time stamp the truth has (to 1 ns); NaN when there are none.
inline double rmse(const Stream& fixes, const Stream& truth) {
    const auto f = *fixes.data();
    const auto g = *truth.data();
    double sum = 0.0;
    std::size_t n = 0, j = 0;
    for (std::size_t k = 0; k < f->rows(); ++k) {
        while (j < g->rows() && g->t[j] < f->t[k] - 1e-9) ++j;
        if (j == g->rows() || std::abs(g->t[j] - f->t[k]) > 1e-9) continue;
        sum += std::pow(f->at(k, 0) - g->at(j, 0), 2) + std::pow(f->at(k, 1) - g->at(j, 1), 2);
        ++n;
    }
    return n ? std::sqrt(sum / double(n)) : NAN;
}

}  // namespace athlos::lps::testsupport
