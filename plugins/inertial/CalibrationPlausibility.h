#pragma once
// Plausibility of an IMU calibration result (issue #13 item 8: a magnetometer calibration that turned
// a ~40 µT field into ~700 µT was applied without a word). Each limit is a processor parameter of
// `imu-calibration`; the defaults and their sources:
//  - magnetic field magnitude after calibration within [22, 67] µT: the total intensity F of the
//    geomagnetic main field at the Earth's surface ranges from about 22 000 nT (South Atlantic
//    Anomaly) to about 67 000 nT (near the south magnetic pole), World Magnetic Model 2020
//    technical report (NOAA NCEI / BGS), map of F; IGRF-13 gives the same range;
//  - |a| at rest after calibration within 3 % of gravity: the factory sensitivity tolerance of a
//    consumer MEMS accelerometer (InvenSense MPU-6000/6050 product specification PS-MPU-6000A-00
//    rev. 3.4, §6.2, "initial calibration tolerance ±3 %") — a calibration that leaves the rest
//    magnitude further from g than an uncalibrated sensor made it worse;
//  - fitted accelerometer scale factors within 1 ± 0.10: the same tolerance (±3 %) plus cross-axis
//    sensitivity (±2 %) and temperature drift (±0.02 %/°C over 0…70 °C, §6.2), rounded up.
#include "plugins/inertial/ImuCalibration.h"

#include <QStringList>
#include <vector>

namespace athlos::inertial {

struct PlausibilityLimits {
    double magFieldMin = 22.0;        // µT
    double magFieldMax = 67.0;        // µT
    double accNormTolerance = 0.03;   // fraction of gravity
    double accScaleTolerance = 0.10;  // |s − 1|
};

// Median of |m| over the rows whose three components are finite; NaN when there are none.
double medianFieldNorm(const double* mag, std::size_t rows, std::size_t stride);

// Findings (one sentence each, naming the parameter and the values); empty when plausible.
// `fieldNorm` is the median magnitude after calibration in µT.
QStringList checkMagnetometer(double fieldNorm, const PlausibilityLimits& limits);
// `staticMeans` are the raw accelerometer means of the static segments (m/s²).
QStringList checkAccelerometer(const AccCalibration& acc, const std::vector<Vec3>& staticMeans, double gravity,
                               const PlausibilityLimits& limits);

}  // namespace athlos::inertial
