#pragma once
// Walking cadence from a wrist-worn accelerometer (Fasel et al. 2017, thesis ch. 12.2.3).
//
// The acceleration norm (gravity included: insensitive to placement) is averaged onto a 20 Hz grid
// (the thesis low-passes at 10 Hz and down-samples to 20 Hz), cut into windows of 6 s shifted by
// 1 s, and for each window the cadence likelihood CL_n[f] is a comb filter over the log amplitude
// spectrum (Hann window, FFT of 256, linearly interpolated to 0.01 Hz; eq. 12.2–12.3): +1 at the
// harmonics n·f (n = 1..5), −1 at the half harmonics m·f (m = 1.5..4.5), for stride frequencies
// f = 0.40..2.00 Hz. The cadence (steps/s) is twice the arg max (eq. 12.1). Tracking (eq. 12.4–
// 12.5): when the new stride frequency is more than 0.07 Hz from half the previous cadence, the
// maximum is searched near the previous stride frequency (±0.07 Hz, range A, giving 2f) and near
// the previous step frequency (±0.14 Hz, range B, giving f); the cadence is then smoothed,
// c[n] = 0.33 c[n−1] + 0.67 c[n].
//
// Walking detection is not in the thesis (walking was segmented by hand): a window counts as
// walking when its harmonicity reaches minHarmonicity and the norm's SD minStd. The harmonicity is
// the mean log-amplitude excess of the harmonics n·f (n = 1..4, f the comb's maximum) over the
// mean of their neighbouring half harmonics (n ± 0.5)·f: unlike CL it is ~0 for any smooth
// (e.g. falling) spectrum, so aperiodic arm movements do not pass for walking. Tracking
// restarts after a non-walking window, and after `reacquire` consecutive windows whose maximum lies
// near neither the tracked stride nor the tracked step frequency (a track locked on a wrong
// maximum would otherwise never recover).
#include <vector>

namespace athlos::events {

struct WristCadenceParams {
    double gridRate = 20.0;           // Hz, thesis 20 Hz
    double window = 6.0;              // s, thesis 6 s
    double hop = 1.0;                 // s, thesis 1 s
    int fftSize = 256;                // thesis 256
    double fMin = 0.40, fMax = 2.00;  // Hz, stride frequency search range (eq. 12.1)
    double fStep = 0.01;              // Hz, interpolated resolution
    double trackStride = 0.07;        // Hz, range A half-width (eq. 12.4)
    double trackStep = 0.14;          // Hz, range B half-width (eq. 12.4)
    double smoothing = 0.33;          // weight of c[n−1] (thesis low-pass)
    int reacquire = 3;                // windows in a row unexplained by the track before it restarts (ours)
    double minHarmonicity = 1.8;      // log-amplitude excess of the harmonics for walking (ours)
    double minStd = 0.4;              // m/s², SD of the norm in the window for walking
};

struct CadenceWindow {
    double tStart = 0.0, tEnd = 0.0;                      // s
    double cadence = 0.0;                                 // steps/min (tracked and smoothed; NaN when not walking)
    double rawCadence = 0.0;                              // steps/min, eq. 12.1 without tracking
    double likelihood = 0.0;                              // max of CL_n
    double harmonicity = 0.0;                             // harmonics over half harmonics at the CL maximum (log ratio)
    double normMax = 0.0, normStd = 0.0, normMean = 0.0;  // m/s² (speed features, eq. 12.6)
    bool walking = false;
};

class WristCadence {
public:
    explicit WristCadence(WristCadenceParams params = {}) : p_(params) {}

    // Acceleration norm on the regular grid: the mean of the samples in each 1/gridRate bin, gaps
    // filled linearly. t strictly increasing; acc three columns with `stride` doubles per row.
    std::vector<double> normGrid(const double* t, const double* acc, std::size_t rows, std::size_t stride,
                                 double& gridStart) const;
    // The cadence likelihood CL[f] of one window of the gridded norm (size window·gridRate), at
    // f = fMin, fMin + fStep, ..., fMax.
    std::vector<double> likelihood(const double* window, std::size_t size) const;
    // Log amplitude spectrum of one window (bins 0..fftSize/2) and the comb over it.
    std::vector<double> logSpectrum(const double* window, std::size_t size) const;
    std::vector<double> likelihood(const std::vector<double>& logAmp) const;
    double harmonicity(const std::vector<double>& logAmp, double strideFrequency) const;
    // All windows over the recording, tracked.
    std::vector<CadenceWindow> estimate(const double* t, const double* acc, std::size_t rows, std::size_t stride) const;

    const WristCadenceParams& params() const { return p_; }

private:
    WristCadenceParams p_;
};

}  // namespace athlos::events
