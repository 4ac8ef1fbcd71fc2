#pragma once
// Second-order Butterworth low-pass for N channels, parametrised by a time constant (Laidig & Seel,
// "VQF", Information Fusion 2023, Sec. 3.2 / Appendix): cut-off f_c = √2 / (2π τ), bilinear
// transform with pre-warping, direct form II transposed.
//
// Start-up: for the first τ seconds the output is the running mean of the inputs, then the filter
// state is set to the steady state of that mean. A Butterworth started from zero would need several τ
// to forget its initial state; the mean gives a good estimate as soon as the first sample arrives.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace athlos::inertial {

template <int N>
class LowPass2 {
public:
    using Vec = Eigen::Matrix<double, N, 1>;

    LowPass2() = default;
    LowPass2(double tau, double ts) { setup(tau, ts); }

    void setup(double tau, double ts) {
        tau_ = tau;
        ts_ = ts;
        const double fc = std::numbers::sqrt2 / (2.0 * std::numbers::pi) / tau;
        const double c = std::tan(std::numbers::pi * fc * ts);
        const double d = c * c + std::numbers::sqrt2 * c + 1.0;
        b0_ = c * c / d;
        b1_ = 2.0 * b0_;
        b2_ = b0_;
        a1_ = 2.0 * (c * c - 1.0) / d;
        a2_ = (1.0 - std::numbers::sqrt2 * c + c * c) / d;
        reset();
    }
    void reset() {
        s0_.setZero();
        s1_.setZero();
        count_ = 0;
        sum_.setZero();
    }

    Vec step(const Vec& x) {
        if (count_ >= 0) {  // initial averaging phase
            sum_ += x;
            ++count_;
            const Vec mean = sum_ / static_cast<double>(count_);
            if (static_cast<double>(count_) * ts_ >= tau_) {
                // steady state for constant input `mean` (y = x): s0 = y - b0 x, s1 = b2 x - a2 y
                s0_ = mean * (1.0 - b0_);
                s1_ = mean * (b2_ - a2_);
                count_ = -1;
            }
            return mean;
        }
        const Vec y = b0_ * x + s0_;
        s0_ = b1_ * x - a1_ * y + s1_;
        s1_ = b2_ * x - a2_ * y;
        return y;
    }

private:
    double tau_ = 1.0, ts_ = 0.01;
    double b0_ = 0, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
    Vec s0_ = Vec::Zero(), s1_ = Vec::Zero(), sum_ = Vec::Zero();
    long long count_ = 0;
};

// First-order low-pass gain for a time constant: y += k (x - y), k = 1 - exp(-Ts/τ).
inline double gainFromTau(double tau, double ts) {
    if (tau < 0.0) return 0.0;
    if (tau == 0.0) return 1.0;
    return 1.0 - std::exp(-ts / tau);
}

}  // namespace athlos::inertial
