#pragma once
// Scoring detected initial contacts against a reference segmentation (gaitmap's stride borders from
// motion capture: one row per stride, start = IC, end = next IC, sample indices per foot).
//
// The reference covers only the walking bouts inside the capture volume, so detections are judged
// inside the reference bouts (first start − tolerance … last end + tolerance of each chain of
// consecutive strides); detections outside them cannot be scored and are not counted as false.
#include "core/util/Expected.h"
#include "plugins/events/GaitEventDetector.h"

#include <QString>
#include <memory>
#include <vector>

namespace athlos {
class Project;
}

namespace athlos::events {

// A new project in dir (which must outlive it) with a gaitmap IMU CSV imported as recording "walk"
// (walk/left-foot, walk/right-foot; the rate from the file). Errors name the file.
Expected<std::unique_ptr<Project>> importGaitmapWalk(const QString& dir, const QString& imuCsv);

struct ReferenceStride {
    QString foot;       // "left" / "right"
    double tStart = 0;  // s
    double tEnd = 0;    // s
};

// Reads gaitmap's stride_borders CSV (columns s_id, foot, start, end[, …]); sample indices are
// divided by rate (Hz). Errors name the file, line and column.
Expected<std::vector<ReferenceStride>> readStrideBorders(const QString& path, double rate);

struct IcScore {
    int referenceIcs = 0;  // distinct reference ICs
    int matchedIcs = 0;    // reference ICs with a detected IC within the tolerance
    int falseIcs = 0;      // detected ICs inside a reference bout that match no reference IC
    int referenceStrides = 0;
    int matchedStrides = 0;    // reference strides whose start and end both matched a detected stride
    double meanErrorMs = 0.0;  // detected − reference over matched ICs
    double sdErrorMs = 0.0;
    std::vector<double> errorsMs;

    double icRate() const { return referenceIcs ? double(matchedIcs) / referenceIcs : 0.0; }
    double strideRate() const { return referenceStrides ? double(matchedStrides) / referenceStrides : 0.0; }
    void add(const IcScore& other);  // pools two scores (e.g. left and right foot)
};

// reference: the strides of one foot; detectedIcs (s, ascending) and detectedStrides as (start, end) (s).
IcScore scoreInitialContacts(const std::vector<ReferenceStride>& reference, const std::vector<double>& detectedIcs,
                             const std::vector<std::pair<double, double>>& detectedStrides, double toleranceS);

// Detection on one foot of an imported gaitmap recording.
struct FootDetection {
    QString foot;       // "left" / "right"
    double rate = 0.0;  // Hz
    int swingSign = 0;
    std::vector<double> ics;
    std::vector<GaitStride> strides;
};

// Imports a gaitmap IMU CSV (both feet) and runs GaitEventDetector on each foot (ML axis y, swing
// sign auto). Errors name the file.
Expected<std::vector<FootDetection>> detectGaitmapFile(const QString& imuCsv,
                                                       const GaitEventDetector::Params& params = {});

struct GaitValidation {
    IcScore left, right, total;
};
// detectGaitmapFile + readStrideBorders (at the IMU's rate) + scoreInitialContacts per foot.
Expected<GaitValidation> validateGaitmap(const QString& imuCsv, const QString& bordersCsv, double toleranceS,
                                         const GaitEventDetector::Params& params = {});

}  // namespace athlos::events
