#pragma once
// The per-axis window statistics of the activity features (seed 000, thesis ch. 5, Table 5.1):
// moments, dominant frequency and its amplitude, extremes and their positions, energy, and the
// Pearson correlation between two axes. Plain functions on contiguous samples, no allocation.
#include <cstddef>

namespace athlos::activity {

struct Moments {
    double mean = 0, sd = 0;  // population standard deviation
    double skewness = 0;      // m3 / m2^1.5 (0 for a constant signal)
    double kurtosis = 0;      // excess kurtosis m4 / m2^2 − 3 (0 for a constant signal)
    double energy = 0;        // mean square, sum(x²)/n
};
Moments moments(const double* x, std::size_t n);

struct Extremes {
    double max = 0, min = 0;
    double argmax = 0, argmin = 0;  // position of the first maximum/minimum in the window, 0 (first) .. 1 (last)
};
Extremes extremes(const double* x, std::size_t n);

// Median of x (sorts `scratch`, which must hold n values; x is left as it is).
double median(const double* x, std::size_t n, double* scratch);

struct Quantiles {
    double p10 = 0, p25 = 0, p50 = 0, p75 = 0, p90 = 0;  // order statistics at ⌊q (n − 1)⌋ (p50: the median)
};
// Quantiles of x by partial sorts of `scratch` (n values; x is left as it is).
Quantiles quantiles(const double* x, std::size_t n, double* scratch);

// Share of the spectral energy (|X_k|², k ≥ 1) in [lo, hi) Hz for each of `bands` bands given as
// edges[0..bands]; out[b] in 0..1 (0 for a constant signal).
void bandShares(const double* magnitude, std::size_t bins, std::size_t length, double rate, const double* edges,
                int bands, double* out);

// Pearson correlation of x and y; 0 when either is constant.
double correlation(const double* x, const double* y, std::size_t n);

struct Dominant {
    double frequency = 0;  // Hz, ratio interpolation between DFT bins (0 for a constant signal)
    double amplitude = 0;  // amplitude of that sinusoid, 2|X_k|/n at the peak bin
};
// Largest non-DC peak of the spectrum of one channel, given its DFT magnitude over bins 0..bins-1
// of a transform of length `length` (zero-padded from n samples) at sampling rate rate (Hz).
Dominant dominantFromSpectrum(const double* magnitude, std::size_t bins, std::size_t length, std::size_t n,
                              double rate);
// The same from the samples (cv::dft of the mean-removed signal, zero-padded to an efficient length).
Dominant dominant(const double* x, std::size_t n, double rate);

}  // namespace athlos::activity
