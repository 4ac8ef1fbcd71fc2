#pragma once
// Horizontal radiation pattern of the tag worn on the body (thesis Fig. 3.15, Eqn. 3.10):
// gain(φ) in linear scale, φ = bearing to the beacon relative to the body's forward direction.
//
// The thesis' pattern (a λ/2 monopole at 5.8 GHz on the chest, simulated with CST) exists only as a
// plot. The default is the front-lobe stand-in gain(φ) = g_b + (1 − g_b)·((1 + cos φ)/2)^n with
// n = 6 and a back gain g_b of −30 dB (−5 dB at ±49°, −15 dB at ±84°, −27 dB at ±112°) (the body's water attenuates signals sent backwards).
// A measured pattern can be given as a table "angle_deg:gain, …" (linear gains); a table that only
// covers 0…180° is mirrored (left/right symmetric body).
#include "core/util/Expected.h"

#include <QString>
#include <vector>

namespace athlos::lps {

class GainPattern {
public:
    GainPattern();  // frontLobe(6, −30 dB)
    static GainPattern frontLobe(double exponent, double backGainDb);
    static Expected<GainPattern> parse(const QString& text);

    double gain(double phi) const;    // linear, periodic in φ (rad)
    double gainDb(double phi) const;  // G_t(φ) = 10 log10 gain(φ)   (Eqn. 3.10)
    QString describe() const;         // the table as "deg:gain,…"

private:
    struct Empty {};
    explicit GainPattern(Empty) {}
    std::vector<double> angles_;  // rad in [0, 2π), increasing
    std::vector<double> gains_;   // linear, > 0
};

}  // namespace athlos::lps
