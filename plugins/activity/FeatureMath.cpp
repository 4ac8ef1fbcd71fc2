#include "plugins/activity/FeatureMath.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace athlos::activity {

Moments moments(const double* x, std::size_t n) {
    Moments m;
    if (n == 0) return m;
    double sum = 0, squares = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += x[i];
        squares += x[i] * x[i];
    }
    const double dn = double(n);
    m.mean = sum / dn;
    m.energy = squares / dn;
    double m2 = 0, m3 = 0, m4 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = x[i] - m.mean;
        const double d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    m2 /= dn;
    m3 /= dn;
    m4 /= dn;
    m.sd = std::sqrt(m2);
    // Relative to the signal's scale, a variance at rounding level is a constant signal.
    if (m2 > 1e-24 * std::max(1.0, m.energy)) {
        m.skewness = m3 / (m2 * m.sd);
        m.kurtosis = m4 / (m2 * m2) - 3.0;
    }
    return m;
}

Extremes extremes(const double* x, std::size_t n) {
    Extremes e;
    if (n == 0) return e;
    std::size_t imax = 0, imin = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (x[i] > x[imax]) imax = i;
        if (x[i] < x[imin]) imin = i;
    }
    e.max = x[imax];
    e.min = x[imin];
    const double last = n > 1 ? double(n - 1) : 1.0;
    e.argmax = double(imax) / last;
    e.argmin = double(imin) / last;
    return e;
}

double median(const double* x, std::size_t n, double* scratch) {
    if (n == 0) return 0.0;
    std::copy(x, x + n, scratch);
    const std::size_t mid = n / 2;
    std::nth_element(scratch, scratch + mid, scratch + n);
    const double upper = scratch[mid];
    if (n % 2) return upper;
    return 0.5 * (upper + *std::max_element(scratch, scratch + mid));
}

Quantiles quantiles(const double* x, std::size_t n, double* scratch) {
    Quantiles q;
    if (n == 0) return q;
    std::copy(x, x + n, scratch);
    const auto at = [&](double p) { return std::size_t(std::floor(p * double(n - 1))); };
    if (n < 8) {  // the nested partial sorts below need i10 ≤ i25 ≤ i50 ≤ i75 ≤ i90
        std::sort(scratch, scratch + n);
        const std::size_t mid = n / 2;
        return {scratch[at(0.10)], scratch[at(0.25)], n % 2 ? scratch[mid] : 0.5 * (scratch[mid - 1] + scratch[mid]),
                scratch[at(0.75)], scratch[at(0.90)]};
    }
    const std::size_t i10 = at(0.10), i25 = at(0.25), i50 = n / 2, i75 = at(0.75), i90 = at(0.90);
    // Each partial sort works inside the part the previous one left (O(n) in all); a value is read
    // before a later partial sort of its part may move it.
    std::nth_element(scratch, scratch + i50, scratch + n);
    q.p50 = n % 2 ? scratch[i50] : 0.5 * (scratch[i50] + *std::max_element(scratch, scratch + i50));
    std::nth_element(scratch, scratch + i25, scratch + i50);
    q.p25 = scratch[i25];
    std::nth_element(scratch, scratch + i10, scratch + i25);
    q.p10 = scratch[i10];
    std::nth_element(scratch + i50, scratch + i75, scratch + n);
    q.p75 = scratch[i75];
    std::nth_element(scratch + i75, scratch + i90, scratch + n);
    q.p90 = scratch[i90];
    return q;
}

void bandShares(const double* magnitude, std::size_t bins, std::size_t length, double rate, const double* edges,
                int bands, double* out) {
    std::fill(out, out + bands, 0.0);
    double total = 0;
    for (std::size_t k = 1; k < bins; ++k) {
        const double power = magnitude[k] * magnitude[k];
        total += power;
        const double f = double(k) * rate / double(length);
        for (int b = 0; b < bands; ++b)
            if (f >= edges[b] && f < edges[b + 1]) out[b] += power;
    }
    if (total > 0)
        for (int b = 0; b < bands; ++b) out[b] /= total;
}

double correlation(const double* x, const double* y, std::size_t n) {
    if (n < 2) return 0.0;
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= double(n);
    my /= double(n);
    double sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = x[i] - mx, dy = y[i] - my;
        sxy += dx * dy;
        sxx += dx * dx;
        syy += dy * dy;
    }
    const double scale = std::max({1.0, mx * mx, my * my}) * double(n);
    if (sxx <= 1e-24 * scale || syy <= 1e-24 * scale) return 0.0;
    return sxy / std::sqrt(sxx * syy);
}

Dominant dominantFromSpectrum(const double* magnitude, std::size_t bins, std::size_t length, std::size_t n,
                              double rate) {
    Dominant d;
    if (bins < 2 || n == 0 || length == 0) return d;
    std::size_t k = 1;
    for (std::size_t i = 2; i < bins; ++i)
        if (magnitude[i] > magnitude[k]) k = i;
    if (magnitude[k] <= 0.0) return d;
    // Jain's ratio interpolation between the peak and its larger neighbour: for a rectangular window
    // of n samples |X| falls off as the Dirichlet kernel, so δ = α/(1+α) with α the neighbour/peak
    // ratio (exact for a pure sine without zero-padding; with padding the bins are length/n finer and
    // the estimate is scaled accordingly).
    double offset = 0.0;
    const double right = k + 1 < bins ? magnitude[k + 1] : 0.0, left = magnitude[k - 1];
    const double binsPerLobe = double(length) / double(n);
    if (right >= left && right > 0) {
        const double a = right / magnitude[k];
        offset = std::min(0.5, binsPerLobe * a / (1.0 + a));
    } else if (left > 0 && k > 1) {
        const double a = left / magnitude[k];
        offset = -std::min(0.5, binsPerLobe * a / (1.0 + a));
    }
    d.frequency = (double(k) + offset) * rate / double(length);
    d.amplitude = 2.0 * magnitude[k] / double(n);
    return d;
}

Dominant dominant(const double* x, std::size_t n, double rate) {
    if (n < 2) return {};
    const int length = cv::getOptimalDFTSize(int(n));
    const double mean = moments(x, n).mean;
    cv::Mat row(1, length, CV_64F, cv::Scalar(0));
    for (std::size_t i = 0; i < n; ++i) row.at<double>(int(i)) = x[i] - mean;
    cv::Mat spectrum;
    cv::dft(row, spectrum, cv::DFT_COMPLEX_OUTPUT);
    const std::size_t bins = std::size_t(length / 2 + 1);
    std::vector<double> magnitude(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        const cv::Vec2d v = spectrum.at<cv::Vec2d>(int(k));
        magnitude[k] = std::hypot(v[0], v[1]);
    }
    return dominantFromSpectrum(magnitude.data(), bins, std::size_t(length), n, rate);
}

}  // namespace athlos::activity
