#include "plugins/inertial/VectorMath.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <sleef.h>
#endif

namespace athlos::inertial {

void acosBatch(std::span<const double> x, std::span<double> out) {
    assert(out.size() >= x.size());
    const std::size_t n = x.size();
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128d lo = _mm_set1_pd(-1.0), hi = _mm_set1_pd(1.0);
    for (; i + 2 <= n; i += 2) {
        // max/min return their second operand when one is NaN: a NaN stays NaN, as with std::clamp.
        const __m128d v = _mm_min_pd(hi, _mm_max_pd(lo, _mm_loadu_pd(x.data() + i)));
        _mm_storeu_pd(out.data() + i, Sleef_acosd2_u10(v));
    }
#endif
    for (; i < n; ++i) out[i] = std::acos(std::clamp(x[i], -1.0, 1.0));
}

void atan2Batch(std::span<const double> y, std::span<const double> x, std::span<double> out) {
    assert(x.size() == y.size() && out.size() >= y.size());
    const std::size_t n = y.size();
    std::size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= n; i += 2)
        _mm_storeu_pd(out.data() + i, Sleef_atan2d2_u10(_mm_loadu_pd(y.data() + i), _mm_loadu_pd(x.data() + i)));
#endif
    for (; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

}  // namespace athlos::inertial
