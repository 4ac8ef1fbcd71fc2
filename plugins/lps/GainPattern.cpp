#include "plugins/lps/GainPattern.h"

#include <QRegularExpression>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace athlos::lps {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMinGain = 1e-12;  // keeps log10 finite
}  // namespace

GainPattern::GainPattern() { *this = frontLobe(6.0, -30.0); }

GainPattern GainPattern::frontLobe(double exponent, double backGainDb) {
    GainPattern pattern{Empty{}};
    const double back = std::pow(10.0, backGainDb / 10.0);
    const int steps = 72;  // 5° table: interpolation error well below a dB
    for (int k = 0; k < steps; ++k) {
        const double phi = kTwoPi * k / steps;
        pattern.angles_.push_back(phi);
        pattern.gains_.push_back(back + (1.0 - back) * std::pow((1.0 + std::cos(phi)) / 2.0, exponent));
    }
    return pattern;
}

Expected<GainPattern> GainPattern::parse(const QString& text) {
    std::vector<std::pair<double, double>> points;
    for (const QString& item : text.split(QRegularExpression(QStringLiteral("[,;]")), Qt::SkipEmptyParts)) {
        const QStringList parts = item.split(QLatin1Char(':'));
        bool okAngle = false, okGain = false;
        const double deg = parts.size() == 2 ? parts[0].trimmed().toDouble(&okAngle) : 0.0;
        const double g = parts.size() == 2 ? parts[1].trimmed().toDouble(&okGain) : 0.0;
        if (!okAngle || !okGain || !(g > 0.0) || !std::isfinite(deg))
            return makeError(QStringLiteral("gain_pattern: '%1' is not 'angle_deg:gain' with a positive linear gain")
                                 .arg(item.trimmed()));
        points.emplace_back(deg, g);
    }
    if (points.size() < 2) return makeError(QStringLiteral("gain_pattern: give at least two 'angle_deg:gain' points"));
    const bool halfPlane =
        std::all_of(points.begin(), points.end(), [](auto& p) { return p.first >= 0 && p.first <= 180; });
    if (halfPlane) {
        const auto n = points.size();
        for (std::size_t k = 0; k < n; ++k)
            if (points[k].first > 0.0 && points[k].first < 180.0)
                points.emplace_back(360.0 - points[k].first, points[k].second);
    }
    for (auto& p : points) p.first = std::fmod(std::fmod(p.first, 360.0) + 360.0, 360.0) * std::numbers::pi / 180.0;
    std::sort(points.begin(), points.end());
    GainPattern pattern{Empty{}};
    for (const auto& [a, g] : points) {
        if (!pattern.angles_.empty() && a == pattern.angles_.back()) continue;
        pattern.angles_.push_back(a);
        pattern.gains_.push_back(g);
    }
    return pattern;
}

double GainPattern::gain(double phi) const {
    phi = std::fmod(phi, kTwoPi);
    if (phi < 0.0) phi += kTwoPi;
    const auto n = angles_.size();
    // Segment [k, k+1] containing φ, wrapping from the last point to the first (+2π).
    auto upper = std::upper_bound(angles_.begin(), angles_.end(), phi);
    const std::size_t hi = upper == angles_.end() ? 0 : std::size_t(upper - angles_.begin());
    const std::size_t lo = hi == 0 ? n - 1 : hi - 1;
    double a0 = angles_[lo], a1 = angles_[hi];
    if (a1 <= a0) a1 += kTwoPi;
    double x = phi;
    if (x < a0) x += kTwoPi;
    const double f = a1 > a0 ? (x - a0) / (a1 - a0) : 0.0;
    return std::max(kMinGain, gains_[lo] + f * (gains_[hi] - gains_[lo]));
}

double GainPattern::gainDb(double phi) const { return 10.0 * std::log10(gain(phi)); }

QString GainPattern::describe() const {
    QStringList items;
    for (std::size_t k = 0; k < angles_.size(); ++k)
        items
            << QStringLiteral("%1:%2").arg(angles_[k] * 180.0 / std::numbers::pi, 0, 'g', 6).arg(gains_[k], 0, 'g', 6);
    return items.join(QLatin1Char(','));
}

}  // namespace athlos::lps
