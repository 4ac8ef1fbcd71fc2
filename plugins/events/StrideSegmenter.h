#pragma once
// Strides of one foot-mounted IMU between consecutive mid-stance (minimum-velocity) instants,
// as gaitmap does for spatial parameters (Rampp et al. 2015; Küderle et al., gaitmap 2024):
//  - swing: a peak of the medio-lateral angular velocity ω_ml (signed swing-positive, see
//    GaitEventDetector::swingSign) above swingThreshold, the largest within ±minStrideTime/2 and
//    at least minStrideTime after the previous one;
//  - mid-stance between two swings: the minimum of the gyroscope norm averaged over restWindow
//    (the foot is flat and still, "low gyro energy", cf. the SHOE detector of Skog et al. 2010 and
//    gaitmap's NormZuptDetector), however fast the foot still rolls (running); before the first
//    swing and after the last one, where the data may start or end in motion, it must be at most
//    restThreshold. A pause between two swings (the mean norm below staticThreshold for at
//    least standDuration) ends the stride before at the quietest instant of the pause's first
//    standDuration/2 and starts the next one in its last standDuration/2. Swings more than
//    maxStrideTime apart without such a pause: the stride before ends at the quietest instant within
//    stanceSearch after its swing, the stride after starts at the quietest instant within
//    stanceSearch before its swing;
//  - one stride per swing whose mid-stances on both sides are accepted; toe-off is the most
//    negative ω_ml within tcWindow before the swing peak, initial contact the most negative
//    within icWindow after it (the event definitions of GaitEventDetector).
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace athlos::events {

struct StrideSegmentationParams {
    Eigen::Vector3d mlAxis = Eigen::Vector3d::UnitY();  // unit vector along the medio-lateral direction
    int swingSign = 0;              // +1 / −1, 0: GaitEventDetector::swingSign
    double swingThreshold = 1.5;    // rad/s, as GaitEventParams::swingThreshold
    double minStrideTime = 0.5;     // s
    double maxStrideTime = 2.5;     // s: swings further apart have a standing foot between them
    double restWindow = 0.15;       // s: gaitmap NormZuptDetector window_length_s
    double restThreshold = 2.0;     // rad/s: mean gyroscope norm accepted at the first/last mid-stance
    double stanceSearch = 0.6;      // s: search for the mid-stance next to a long gap
    double staticThreshold = 0.26;  // rad/s: standing (gaitmap NormZuptDetector, 15 deg/s)
    double standDuration = 0.75;    // s: shortest pause that splits the stance between two strides
    double tcWindow = 0.4;          // s, as GaitEventParams::tcWindow
    double icWindow = 0.35;         // s, as GaitEventParams::icWindow
};

struct StrideSegment {
    std::size_t start = 0, end = 0;         // sample indices of the mid-stances (start < end)
    std::size_t peak = 0;                   // swing peak
    std::size_t tc = 0, ic = 0;             // toe-off and initial contact (start ≤ tc < peak < ic ≤ end)
    double restStart = 0.0, restEnd = 0.0;  // mean gyroscope norm at the mid-stances (rad/s)
};

struct StrideSegmentation {
    int swingSign = 1;
    std::size_t swings = 0;  // swing peaks found (strides need accepted mid-stances on both sides)
    std::vector<StrideSegment> strides;
};

// t: sample times (s), gyr: gyr_x of the first sample (rad/s), `stride` doubles between samples.
StrideSegmentation segmentStrides(const StrideSegmentationParams& params, const double* t, const double* gyr,
                                  std::size_t rows, std::size_t stride);

// Centred moving average of the gyroscope norm over `window` seconds.
std::vector<double> meanGyroNorm(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                 double window);

}  // namespace athlos::events
