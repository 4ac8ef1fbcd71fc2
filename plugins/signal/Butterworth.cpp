#include "plugins/signal/Butterworth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace athlos::signal {

namespace {

using Complex = std::complex<double>;

QString hz(double value) { return QString::number(value, 'g', 6) + QStringLiteral(" Hz"); }

// An analog section before the bilinear transform: one conjugate pole pair (p, p*), two real poles,
// or a single real pole (second == nullopt).
struct AnalogSection {
    Complex first;
    std::optional<Complex> second;  // absent: first-order section; equal to conj(first) for pairs
};

// Bilinear transform z = (1 + s)/(1 − s): the s-plane here is pre-warped with Ω = tan(πf/fs),
// i.e. the sampling period is folded into the pre-warping (scipy uses fs2 = 2·fs, same result).
Complex bilinear(Complex s) { return (1.0 + s) / (1.0 - s); }

}  // namespace

Status Butterworth::check(const Params& params) {
    if (params.order < 1 || params.order > kMaxOrder)
        return makeError(QStringLiteral("order must be between 1 and %1, got %2").arg(kMaxOrder).arg(params.order));
    if (!(params.samplingRate > 0.0) || !std::isfinite(params.samplingRate))
        return makeError(QStringLiteral("the sampling rate must be positive, got %1").arg(hz(params.samplingRate)));
    const double nyquist = params.samplingRate / 2.0;
    // A rate estimated from time stamps (1/0.005 s = 200.00000000000003 Hz) must not let a cut-off
    // "at" Nyquist slip through: there tan(πf/fs) diverges.
    const double limit = nyquist * (1.0 - 1e-9);
    const QString nyquistText = QStringLiteral("the Nyquist frequency %1 (half the sampling rate %2)")
                                    .arg(hz(nyquist), hz(params.samplingRate));
    if (!(params.cutoff > 0.0) || !(params.cutoff < limit))
        return makeError(
            QStringLiteral("cutoff must be above 0 Hz and below %1, got %2").arg(nyquistText, hz(params.cutoff)));
    if (isBand(params.type)) {
        if (!(params.cutoffHigh > params.cutoff))
            return makeError(QStringLiteral("cutoff_high (%1) must be above cutoff (%2) for a band filter")
                                 .arg(hz(params.cutoffHigh), hz(params.cutoff)));
        if (!(params.cutoffHigh < limit))
            return makeError(
                QStringLiteral("cutoff_high must be below %1, got %2").arg(nyquistText, hz(params.cutoffHigh)));
    }
    return {};
}

Expected<Butterworth::Type> Butterworth::parseType(const QString& name) {
    if (name == QLatin1String("lowpass")) return Type::LowPass;
    if (name == QLatin1String("highpass")) return Type::HighPass;
    if (name == QLatin1String("bandpass")) return Type::BandPass;
    if (name == QLatin1String("bandstop")) return Type::BandStop;
    return makeError(QStringLiteral("type must be one of lowpass, highpass, bandpass, bandstop, got '%1'").arg(name));
}

Butterworth::Butterworth(const Params& params) : params_(params) {
    const int n = params.order;
    const double pi = std::numbers::pi;
    // Pre-warping: the digital filter has its edges exactly at the requested frequencies.
    const double omegaLow = std::tan(pi * params.cutoff / params.samplingRate);
    const double omegaHigh = isBand(params.type) ? std::tan(pi * params.cutoffHigh / params.samplingRate) : 0.0;
    const double bandwidth = omegaHigh - omegaLow;
    const double centre2 = omegaLow * omegaHigh;  // Ω0² (geometric centre)

    // Analog prototype (Ωc = 1): poles p_k = exp(jπ(2k + n − 1)/(2n)), k = 1..n, on the left half of
    // the unit circle. k = 1..⌊n/2⌋ are the upper-half poles (one per conjugate pair); odd n adds −1.
    std::vector<Complex> prototype;
    for (int k = 1; k <= n / 2; ++k) prototype.push_back(std::polar(1.0, pi * (2 * k + n - 1) / (2.0 * n)));
    const bool hasRealPole = n % 2 == 1;

    // Frequency transformation of each prototype pole, kept in sections so that conjugate pairs
    // stay exact. Band transforms map one pole p to the two roots of s² − p·bw·s + Ω0² = 0 (band-pass)
    // resp. of s² − (bw/p)·s + Ω0² = 0 (band-stop).
    std::vector<AnalogSection> analog;
    auto addPair = [&](Complex p) {  // p and conj(p)
        if (p.imag() < 0.0) p = std::conj(p);
        analog.push_back({p, std::conj(p)});
    };
    auto bandRoots = [&](Complex half) {  // roots of s² − 2·half·s + Ω0²
        const Complex root = std::sqrt(half * half - centre2);
        return std::pair{half + root, half - root};
    };
    for (const Complex& p : prototype) {
        switch (params.type) {
            case Type::LowPass:
                addPair(omegaLow * p);
                break;
            case Type::HighPass:
                addPair(omegaLow / p);
                break;
            case Type::BandPass: {
                auto [s1, s2] = bandRoots(p * bandwidth / 2.0);
                addPair(s1);
                addPair(s2);
                break;
            }
            case Type::BandStop: {
                auto [s1, s2] = bandRoots(bandwidth / 2.0 / p);
                addPair(s1);
                addPair(s2);
                break;
            }
        }
    }
    if (hasRealPole) {
        switch (params.type) {
            case Type::LowPass:   // Ωc·p with p = −1
            case Type::HighPass:  // Ωc/p with p = −1
                analog.push_back({Complex(-omegaLow), std::nullopt});
                break;
            case Type::BandPass:
            case Type::BandStop: {
                // Both transforms give half = −bw/2 for p = −1. A real half gives either a conjugate pair
                // (exactly, via sqrt of a negative real) or two real poles; both fit one section.
                auto [s1, s2] = bandRoots(Complex(-bandwidth / 2.0));
                analog.push_back({s1, s2});
                break;
            }
        }
    }

    // Order sections like scipy's zpk2sos: poles farthest from the unit circle first (after the
    // bilinear transform), so that the last sections hold the sharpest resonances.
    struct Digital {
        Complex p1;
        std::optional<Complex> p2;
        double radius;
    };
    std::vector<Digital> digital;
    Complex analogPoleProduct = 1.0;  // ∏(1 − p) over all analog poles, for the bilinear gain
    for (const AnalogSection& a : analog) {
        Digital d{bilinear(a.first), std::nullopt, 0.0};
        analogPoleProduct *= 1.0 - a.first;
        d.radius = std::abs(d.p1);
        if (a.second) {
            d.p2 = bilinear(*a.second);
            analogPoleProduct *= 1.0 - *a.second;
            d.radius = std::max(d.radius, std::abs(*d.p2));
        }
        digital.push_back(d);
    }
    std::stable_sort(digital.begin(), digital.end(),
                     [](const Digital& a, const Digital& b) { return a.radius < b.radius; });

    // Zeros: s = ∞ maps to z = −1, s = 0 to z = +1, s = ±jΩ0 to z = e^{±jω0}.
    const double cosNotch = (1.0 - centre2) / (1.0 + centre2);  // cos ω0 with Ω0 = tan(ω0/2)
    // Gain of the bilinear transform: k_d = k_a · ∏(1 − z_a) / ∏(1 − p_a) over finite analog zeros.
    double analogGain = 1.0;  // k_a · ∏(1 − z_a)
    switch (params.type) {
        case Type::LowPass:
            analogGain = std::pow(omegaLow, n);
            break;
        case Type::HighPass:
            analogGain = 1.0;
            break;
        case Type::BandPass:
            analogGain = std::pow(bandwidth, n);
            break;
        case Type::BandStop:
            analogGain = std::pow(1.0 + centre2, n);
            break;
    }
    const double gain = analogGain / analogPoleProduct.real();

    sos_.resize(static_cast<Eigen::Index>(digital.size()), 6);
    for (std::size_t i = 0; i < digital.size(); ++i) {
        const Digital& d = digital[i];
        double b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
        if (!d.p2) {  // first-order section: a single real pole and its zero at z = ∓1
            b1 = params.type == Type::LowPass ? 1.0 : -1.0;
            a1 = -d.p1.real();
        } else {
            // (1 − p1 z⁻¹)(1 − p2 z⁻¹) = 1 − (p1 + p2) z⁻¹ + p1 p2 z⁻²; the zero pair likewise.
            a1 = -(d.p1 + *d.p2).real();
            a2 = (d.p1 * *d.p2).real();
            b2 = params.type == Type::BandPass ? -1.0 : 1.0;
            switch (params.type) {
                case Type::LowPass:
                    b1 = 2.0;
                    break;  // z = −1, −1
                case Type::HighPass:
                    b1 = -2.0;
                    break;  // z = +1, +1
                case Type::BandPass:
                    b1 = 0.0;
                    break;  // z = +1, −1
                case Type::BandStop:
                    b1 = -2.0 * cosNotch;
                    break;  // z = e^{±jω0}
            }
        }
        sos_.row(static_cast<Eigen::Index>(i)) << 1.0, b1, b2, 1.0, a1, a2;
    }
    sos_.block(0, 0, 1, 3) *= gain;  // scipy keeps the whole gain in the first section
}

std::complex<double> Butterworth::response(double frequency) const {
    const Complex zInv = std::polar(1.0, -2.0 * std::numbers::pi * frequency / params_.samplingRate);
    Complex h = 1.0;
    for (Eigen::Index s = 0; s < sos_.rows(); ++s) {
        const auto c = sos_.row(s);
        h *= (c(0) + zInv * (c(1) + zInv * c(2))) / (c(3) + zInv * (c(4) + zInv * c(5)));
    }
    return h;
}

Eigen::MatrixX2d Butterworth::steadyStateInitial() const {
    // Transposed direct form II in steady state for input 1 and output G = Σb / Σa:
    //   z2 = b2 − a2·G,  z1 = b1 − a1·G + z2.
    // Section s sees the constant DC gain of the sections before it as its input.
    Eigen::MatrixX2d zi(sos_.rows(), 2);
    double input = 1.0;
    for (Eigen::Index s = 0; s < sos_.rows(); ++s) {
        const auto c = sos_.row(s);
        const double g = (c(0) + c(1) + c(2)) / (c(3) + c(4) + c(5));
        const double z2 = c(2) - c(5) * g;
        zi(s, 1) = input * z2;
        zi(s, 0) = input * (c(1) - c(4) * g + z2);
        input *= g;
    }
    return zi;
}

int Butterworth::defaultPadLength() const {
    const auto sections = static_cast<int>(sos_.rows());
    const int firstOrder = static_cast<int>(((sos_.col(2).array() == 0.0) && (sos_.col(5).array() == 0.0)).count());
    return 3 * (2 * sections + 1 - firstOrder);
}

void Butterworth::runSections(Eigen::Ref<Eigen::VectorXd> x, Eigen::MatrixX2d state) const {
    // Sample-outer, section-inner: each section's state stays in cache and the out-of-order core
    // overlaps section s at sample i with section s−1 at sample i+1.
    const Eigen::Index sections = sos_.rows();
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        double v = x[i];
        for (Eigen::Index s = 0; s < sections; ++s) {
            const double* c = sos_.data() + 6 * s;  // b0 b1 b2 a0 a1 a2, row-major
            const double y = c[0] * v + state(s, 0);
            state(s, 0) = c[1] * v - c[4] * y + state(s, 1);
            state(s, 1) = c[2] * v - c[5] * y;
            v = y;
        }
        x[i] = v;
    }
}

void Butterworth::filter(Eigen::Ref<Eigen::VectorXd> x) const {
    if (x.size() == 0) return;
    runSections(x, steadyStateInitial() * x[0]);
}

void Butterworth::filtFilt(Eigen::Ref<Eigen::VectorXd> x, int padLength) const {
    const Eigen::Index n = x.size();
    if (n == 0) return;
    const Eigen::Index edge = std::clamp<Eigen::Index>(padLength < 0 ? defaultPadLength() : padLength, 0, n - 1);

    // Odd extension about the end points keeps value and slope continuous, so the start-up
    // transient of each pass happens in the padding, not in the data.
    Eigen::VectorXd ext(n + 2 * edge);
    ext.segment(edge, n) = x;
    for (Eigen::Index i = 1; i <= edge; ++i) {
        ext[edge - i] = 2.0 * x[0] - x[i];
        ext[edge + n - 1 + i] = 2.0 * x[n - 1] - x[n - 1 - i];
    }
    const Eigen::MatrixX2d zi = steadyStateInitial();
    runSections(ext, zi * ext[0]);
    ext.reverseInPlace();
    runSections(ext, zi * ext[0]);
    ext.reverseInPlace();
    x = ext.segment(edge, n);
}

void Butterworth::filterSegments(Eigen::Ref<Eigen::VectorXd> x, bool zeroPhase) const {
    const Eigen::Index n = x.size();
    Eigen::Index begin = 0;
    while (begin < n) {
        while (begin < n && !std::isfinite(x[begin])) ++begin;
        Eigen::Index end = begin;
        while (end < n && std::isfinite(x[end])) ++end;
        if (end > begin) {
            auto run = x.segment(begin, end - begin);
            if (zeroPhase)
                filtFilt(run);
            else
                filter(run);
        }
        begin = end;
    }
}

}  // namespace athlos::signal
