#include "plugins/inertial/CalibrationPlausibility.h"

#include "core/math/Statistics.h"

#include <cmath>

namespace athlos::inertial {

namespace {
QString num(double v, int precision = 3) { return QString::number(v, 'g', precision); }
}  // namespace

double medianFieldNorm(const double* mag, std::size_t rows, std::size_t stride) {
    std::vector<double> norms;
    norms.reserve(rows);
    for (std::size_t r = 0; r < rows; ++r) {
        const double* m = mag + r * stride;
        const double n = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        if (std::isfinite(n)) norms.push_back(n);
    }
    return math::median(std::move(norms));
}

QStringList checkMagnetometer(double fieldNorm, const PlausibilityLimits& limits) {
    if (std::isfinite(fieldNorm) && fieldNorm >= limits.magFieldMin && fieldNorm <= limits.magFieldMax) return {};
    return {
        QStringLiteral("the magnetic field after calibration is %1 µT (median |m|), outside mag_field_min … "
                       "mag_field_max = %2 … %3 µT, the geomagnetic total intensity at the Earth's surface (World "
                       "Magnetic Model): check the magnetometer's unit and calibrate away from magnetic disturbances")
            .arg(num(fieldNorm, 4), num(limits.magFieldMin), num(limits.magFieldMax))};
}

QStringList checkAccelerometer(const AccCalibration& acc, const std::vector<Vec3>& staticMeans, double gravity,
                               const PlausibilityLimits& limits) {
    QStringList findings;
    const char* axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(acc.scale[i] - 1.0) <= limits.accScaleTolerance))
            findings << QStringLiteral(
                            "the fitted accelerometer scale factor %1 = %2 differs from 1 by more than "
                            "acc_scale_tolerance = %3")
                            .arg(QLatin1String(axes[i]), num(acc.scale[i], 4), num(limits.accScaleTolerance));
    double worst = 0.0, worstNorm = gravity;
    for (const Vec3& m : staticMeans) {
        const double n = acc.apply(m).norm();
        if (!(std::abs(n - gravity) <= worst)) {
            worst = std::isfinite(n) ? std::abs(n - gravity) : INFINITY;
            worstNorm = n;
        }
    }
    if (!(worst <= limits.accNormTolerance * gravity))
        findings << QStringLiteral(
                        "|a| at rest after calibration is %1 m/s² in a static position, %2 % from gravity = "
                        "%3 m/s², more than acc_norm_tolerance = %4 of gravity")
                        .arg(num(worstNorm, 4), num(100.0 * worst / gravity), num(gravity),
                             num(limits.accNormTolerance));
    return findings;
}

}  // namespace athlos::inertial
