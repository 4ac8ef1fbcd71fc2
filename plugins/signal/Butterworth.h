#pragma once
// Digital Butterworth filters as second-order sections (SOS), designed the textbook way: analog
// prototype poles on the unit circle, frequency pre-warping, low-pass→{high,band}-pass/band-stop
// transformation, bilinear transform. Coefficients and filtering follow scipy.signal's conventions
// (butter(..., output='sos'), sosfilt with sosfilt_zi, sosfiltfilt) so results can be compared.
//
// Non-finite samples: filter() and filtFilt() expect finite data; filterSegments() splits a signal
// at NaN/Inf and filters each finite run on its own (the gaps stay NaN), which is what the
// butterworth processor uses so that resampled streams with max_gap holes can still be filtered.
#include "core/util/Expected.h"

#include <Eigen/Core>
#include <QString>
#include <complex>

namespace athlos::signal {

// One row per section: b0 b1 b2 a0 a1 a2 (a0 == 1), the layout of scipy's sos arrays.
using SosMatrix = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

class Butterworth {
public:
    enum class Type { LowPass, HighPass, BandPass, BandStop };

    struct Params {
        Type type = Type::LowPass;
        int order = 2;              // 1..10; band types have 2·order poles
        double cutoff = 0.0;        // Hz: the cut-off, or the lower edge for band types
        double cutoffHigh = 0.0;    // Hz: upper edge, band types only
        double samplingRate = 0.0;  // Hz
    };

    static constexpr int kMaxOrder = 10;

    // Checks params; the error names the offending parameter as the butterworth processor calls
    // it (order, cutoff, cutoff_high) and, for frequencies, the Nyquist frequency.
    static Status check(const Params& params);
    // Parses "lowpass|highpass|bandpass|bandstop".
    static Expected<Type> parseType(const QString& name);
    static bool isBand(Type type) { return type == Type::BandPass || type == Type::BandStop; }

    // Designs the filter; params must pass check().
    explicit Butterworth(const Params& params);

    const Params& params() const { return params_; }
    const SosMatrix& sos() const { return sos_; }
    // Complex frequency response H(e^{jω}) at f (Hz).
    std::complex<double> response(double frequency) const;

    // Section states (n×2, transposed direct form II) for a unit step in steady state, as
    // scipy.signal.sosfilt_zi: filtering a constant c from c·zi gives exactly c·H(1).
    Eigen::MatrixX2d steadyStateInitial() const;
    // scipy's default padding for filtFilt: 3·(2·sections + 1), minus first-order sections.
    int defaultPadLength() const;

    // Causal filtering in place, starting from the steady state of x[0].
    void filter(Eigen::Ref<Eigen::VectorXd> x) const;
    // Zero-phase forward-backward filtering in place with odd-extension padding (scipy's
    // sosfiltfilt). padLength < 0 → defaultPadLength(); always clipped to x.size() − 1.
    void filtFilt(Eigen::Ref<Eigen::VectorXd> x, int padLength = -1) const;
    // Splits x at non-finite samples and filters each finite run separately (causal or zero-phase);
    // non-finite samples are left as they are.
    void filterSegments(Eigen::Ref<Eigen::VectorXd> x, bool zeroPhase) const;

private:
    // Runs all sections over x in place from the given section states (consumed).
    void runSections(Eigen::Ref<Eigen::VectorXd> x, Eigen::MatrixX2d state) const;

    Params params_;
    SosMatrix sos_;
};

}  // namespace athlos::signal
