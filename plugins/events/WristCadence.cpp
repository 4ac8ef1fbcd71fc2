#include "plugins/events/WristCadence.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace athlos::events {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of the spectrum s (bin width df) at f; beyond the last bin: the last value.
double at(const std::vector<double>& s, double df, double f) {
    const double x = f / df;
    const auto i = std::size_t(std::floor(x));
    if (i + 1 >= s.size()) return s.back();
    const double w = x - double(i);
    return (1.0 - w) * s[i] + w * s[i + 1];
}

struct Peak {
    double f = kNaN, value = -std::numeric_limits<double>::infinity();
};

// The maximum of CL over the test frequencies within [lo, hi].
Peak maxIn(const std::vector<double>& cl, const WristCadenceParams& p, double lo, double hi) {
    Peak best;
    for (std::size_t i = 0; i < cl.size(); ++i) {
        const double f = p.fMin + double(i) * p.fStep;
        if (f < lo - 1e-9 || f > hi + 1e-9) continue;
        if (cl[i] > best.value) best = {f, cl[i]};
    }
    return best;
}

}  // namespace

std::vector<double> WristCadence::normGrid(const double* t, const double* acc, std::size_t rows, std::size_t stride,
                                           double& gridStart) const {
    gridStart = rows ? t[0] : 0.0;
    if (rows < 2) return {};
    const double dt = 1.0 / p_.gridRate;
    const auto bins = std::size_t(std::floor((t[rows - 1] - t[0]) / dt)) + 1;
    std::vector<double> sum(bins, 0.0), grid(bins, kNaN);
    std::vector<int> count(bins, 0);
    for (std::size_t k = 0; k < rows; ++k) {
        const double* a = acc + k * stride;
        const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (!std::isfinite(norm)) continue;
        const auto b = std::min(bins - 1, std::size_t((t[k] - t[0]) / dt));
        sum[b] += norm;
        ++count[b];
    }
    // Bin means (a boxcar low-pass before the down-sampling), empty bins filled linearly.
    std::size_t last = bins;
    for (std::size_t b = 0; b < bins; ++b) {
        if (count[b] == 0) continue;
        grid[b] = sum[b] / count[b];
        if (last == bins) {
            for (std::size_t j = 0; j < b; ++j) grid[j] = grid[b];
        } else {
            for (std::size_t j = last + 1; j < b; ++j)
                grid[j] = grid[last] + (grid[b] - grid[last]) * double(j - last) / double(b - last);
        }
        last = b;
    }
    if (last == bins) return {};
    for (std::size_t j = last + 1; j < bins; ++j) grid[j] = grid[last];
    return grid;
}

std::vector<double> WristCadence::logSpectrum(const double* window, std::size_t size) const {
    const auto nfft = std::size_t(std::max<int>(p_.fftSize, int(size)));
    // Hann-windowed, mean removed, zero-padded to the FFT length.
    double mean = 0.0;
    for (std::size_t i = 0; i < size; ++i) mean += window[i];
    mean /= double(std::max<std::size_t>(size, 1));
    std::vector<double> x(nfft, 0.0);
    double gain = 0.0;
    for (std::size_t i = 0; i < size; ++i) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(size - 1));
        x[i] = (window[i] - mean) * w;
        gain += w;
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, x);
    // Log of the single-sided amplitude spectrum (eq. 12.2's FFT_n); the floor keeps log finite.
    std::vector<double> logAmp(nfft / 2 + 1);
    for (std::size_t k = 0; k < logAmp.size(); ++k)
        logAmp[k] = std::log(2.0 * std::abs(spectrum[k]) / std::max(gain, 1e-12) + 1e-6);
    return logAmp;
}

std::vector<double> WristCadence::likelihood(const std::vector<double>& logAmp) const {
    const double df = p_.gridRate / double(2 * (logAmp.size() - 1));
    const auto tests = std::size_t(std::lround((p_.fMax - p_.fMin) / p_.fStep)) + 1;
    std::vector<double> cl(tests);
    for (std::size_t i = 0; i < tests; ++i) {
        const double f = p_.fMin + double(i) * p_.fStep;
        double sum = 0.0;
        for (int n = 1; n <= 5; ++n) sum += at(logAmp, df, n * f);          // eq. 12.3: +1 at n f
        for (int m = 1; m <= 4; ++m) sum -= at(logAmp, df, (m + 0.5) * f);  // −1 at 1.5 f … 4.5 f
        cl[i] = sum;
    }
    return cl;
}

std::vector<double> WristCadence::likelihood(const double* window, std::size_t size) const {
    return likelihood(logSpectrum(window, size));
}

double WristCadence::harmonicity(const std::vector<double>& logAmp, double f) const {
    const double df = p_.gridRate / double(2 * (logAmp.size() - 1));
    double sum = 0.0;
    for (int n = 1; n <= 4; ++n)
        sum += at(logAmp, df, n * f) - 0.5 * (at(logAmp, df, (n - 0.5) * f) + at(logAmp, df, (n + 0.5) * f));
    return sum / 4.0;
}

std::vector<CadenceWindow> WristCadence::estimate(const double* t, const double* acc, std::size_t rows,
                                                  std::size_t stride) const {
    double start = 0.0;
    const std::vector<double> grid = normGrid(t, acc, rows, stride, start);
    const auto size = std::size_t(std::lround(p_.window * p_.gridRate));
    const auto hop = std::max<std::size_t>(1, std::size_t(std::lround(p_.hop * p_.gridRate)));
    std::vector<CadenceWindow> out;
    if (size < 8 || grid.size() < size) return out;
    double previous = kNaN;  // tracked cadence of the previous walking window (steps/s)
    int disagreements = 0;   // consecutive windows whose own maximum the tracking overruled
    for (std::size_t first = 0; first + size <= grid.size(); first += hop) {
        const double* w = grid.data() + first;
        CadenceWindow win;
        win.tStart = start + double(first) / p_.gridRate;
        win.tEnd = win.tStart + p_.window;
        double sum = 0.0, sq = 0.0, mx = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < size; ++i) {
            sum += w[i];
            mx = std::max(mx, w[i]);
        }
        win.normMean = sum / double(size);
        for (std::size_t i = 0; i < size; ++i) sq += (w[i] - win.normMean) * (w[i] - win.normMean);
        win.normStd = std::sqrt(sq / double(size - 1));
        win.normMax = mx;
        const std::vector<double> logAmp = logSpectrum(w, size);
        const std::vector<double> cl = likelihood(logAmp);
        const Peak global = maxIn(cl, p_, p_.fMin, p_.fMax);
        win.likelihood = global.value;
        win.harmonicity = harmonicity(logAmp, global.f);
        win.rawCadence = 120.0 * global.f;
        win.walking = win.harmonicity >= p_.minHarmonicity && win.normStd >= p_.minStd;
        if (!win.walking) {
            win.cadence = kNaN;
            previous = kNaN;
            disagreements = 0;
            out.push_back(win);
            continue;
        }
        double cadence = 2.0 * global.f;  // steps/s, eq. 12.1
        // Re-acquisition (not in the thesis): a track that more than `reacquire` windows in a row had
        // a maximum near neither its stride (A) nor its step frequency (B) started on a wrong one
        // (e.g. a doubled cadence at gait initiation, whose range B lies outside the search range);
        // start again from the maximum.
        // A maximum at the previous step frequency (range B: weak arm swing) agrees with the track.
        const bool explained =
            std::abs(global.f - 0.5 * previous) <= p_.trackStride || std::abs(global.f - previous) <= p_.trackStep;
        if (explained)
            disagreements = 0;
        else if (std::isfinite(previous) && ++disagreements > p_.reacquire) {
            previous = kNaN;
            disagreements = 0;
        }
        if (std::isfinite(previous) && std::abs(global.f - 0.5 * previous) > p_.trackStride) {
            // eq. 12.4–12.5: keep the more prominent maximum near the previous stride (A) or step (B).
            const Peak a = maxIn(cl, p_, 0.5 * previous - p_.trackStride, 0.5 * previous + p_.trackStride);
            const Peak b = maxIn(cl, p_, previous - p_.trackStep, previous + p_.trackStep);
            if (std::isfinite(a.f) && (!std::isfinite(b.f) || a.value >= b.value))
                cadence = 2.0 * a.f;
            else if (std::isfinite(b.f))
                cadence = b.f;
        }
        if (std::isfinite(previous)) cadence = p_.smoothing * previous + (1.0 - p_.smoothing) * cadence;
        previous = cadence;
        win.cadence = 60.0 * cadence;
        out.push_back(win);
    }
    return out;
}

}  // namespace athlos::events
