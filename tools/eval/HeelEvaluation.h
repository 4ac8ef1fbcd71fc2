#pragma once
// Stride lengths of gait-parameters against a heel marker (docs/validation/gait-parameters.md, "Real
// data with a heel marker"): gaitmap's example walk imu_sample.csv with mocap_sample.csv (markers in mm,
// two header rows marker/axis, heel = L_FCC / R_FCC, synchronised with the IMU from sample 0) and
// stride_borders_sample.csv (reference strides in IMU samples).
#include "core/util/Expected.h"
#include "tools/eval/GaitEvaluation.h"

#include <Eigen/Core>
#include <QString>
#include <QVariantMap>
#include <vector>

namespace athlos::events {

// Horizontal heel positions (m) of both feet, one per motion-capture sample.
struct HeelTrack {
    double rate = 100.0;  // Hz
    std::vector<Eigen::Vector2d> left, right;
    const std::vector<Eigen::Vector2d>& of(const QString& foot) const {
        return foot == QLatin1String("left") ? left : right;
    }
};

// Reads L_FCC / R_FCC x, y (mm → m) from a gaitmap mocap CSV; the first column is the sample index.
// Errors name the file, line and column.
Expected<HeelTrack> readGaitmapHeel(const QString& path, double rate = 100.0);

// One row of a gait-parameters table.
struct EstimatedStride {
    double tStart = 0.0, tEnd = 0.0;  // s
    double length = 0.0;              // m
    double turningAngle = 0.0;        // rad
};

// Steady-state stride length of one foot (gait-summary's strides: GaitSummary.h) from gait-summary's
// table and from the heel between the same strides' own start and end.
struct SteadyLength {
    QString foot;                                // "left", "right", "both"
    int used = 0;                                // steady strides
    double estimatedMean = 0.0, heelMean = 0.0;  // m
    double estimatedCv = 0.0, heelCv = 0.0;      // %, sample SD / mean
    double estimatedSi = 0.0, heelSi = 0.0;      // %, symmetry index (row "both" only)
};

struct HeelScore {
    int reference = 0;                  // reference strides
    int matchedOnce = 0;                // reference strides holding the midpoint of exactly one estimated stride
    std::vector<double> error;          // estimate / heel − 1 over the matched reference strides
    std::vector<double> straightError;  // the same, estimated |turning angle| < maxTurn
    std::vector<double> ownError;       // heel between each estimated stride's own start and end
    std::vector<SteadyLength> steady;   // gait-summary (defaults) of both feet: left, right, both
};

// Scores one foot (reference: that foot's strides) and adds to score. maxTurn: rad, a straight
// stride; minOwnLength: m, own-border strides where the heel moved less are left out (a shuffle on
// the spot has no meaningful relative error).
void scoreAgainstHeel(const std::vector<ReferenceStride>& reference, const std::vector<Eigen::Vector2d>& heel,
                      double heelRate, const std::vector<EstimatedStride>& strides, HeelScore& score,
                      double maxTurn = 0.3, double minOwnLength = 0.2);

// Imports imuCsv (gaitmap format, rate from the file), runs gait-parameters on each foot with
// `parameters`, and scores it against the heel marker and the reference strides; then runs gait-summary
// on both feet's tables and compares its steady-state stride length with the heel's.
Expected<HeelScore> evaluateGaitParametersAgainstHeel(const QString& imuCsv, const QString& mocapCsv,
                                                      const QString& bordersCsv, const QVariantMap& parameters);

}  // namespace athlos::events
