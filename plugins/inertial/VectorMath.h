#pragma once
// Element-wise acos and atan2 over arrays, two doubles at a time with SLEEF (Shibata & Petrogalli,
// "SLEEF: a portable vectorized library of C standard mathematical functions", IEEE TPDS 31(6), 2020;
// the u10 functions: at most 1.0 ULP error), std::acos / std::atan2 where SSE2 is not available.
// A batch of joint angles spends most of its time in these (three of each per sample): about 2.4×
// faster than one glibc call per element on the machine of docs/PERFORMANCE.md.
#include <span>

namespace athlos::inertial {

// out[i] = acos(clamp(x[i], −1, 1)) (rad); out may be x.
void acosBatch(std::span<const double> x, std::span<double> out);
// out[i] = atan2(y[i], x[i]) (rad); out may be y or x.
void atan2Batch(std::span<const double> y, std::span<const double> x, std::span<double> out);

}  // namespace athlos::inertial
