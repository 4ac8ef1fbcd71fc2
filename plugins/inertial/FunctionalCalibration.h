#pragma once
// The whole functional calibration protocol (spec §4, Fasel ch. 6–7) from one recording of several
// IMUs: upright standing, squats ×3, trunk rotations ×3, hip ab/adduction ×3 per leg and the optional
// arm swings ×3, each found automatically or given as an interval (annotations).
//
// Detection. Rest = every sensor's angular rate, averaged over `smoothing` s, below `restRate`;
// the upright window is the first rest of at least `minUpright` s. The gyroscope bias of each
// sensor is its mean rate there. Between rests of at least `minPause` s lie the movement blocks.
// A block is classified by which segments turn and about which of their axes (the principal axis of
// the angular velocity, with the superior axis Y from gravity in the upright window):
//   squats          — both legs turn (thigh, else shank), about an axis ⟂ Y (medio-lateral);
//   ab/adduction    — one leg turns, the other stays still (< `stillRatio` of its rate), axis ⟂ Y
//                     (one leg instrumented: the pelvis and trunk stay still, else it is a squat);
//   trunk rotations — no leg turns, the sternum turns about an axis ∥ Y (within `axialTolerance`);
//   arm swings      — no leg turns, the midline (pelvis, trunk, head) stays still (< `stillRatio` of
//                     the arm's rate), an arm (upper arm, else forearm) turns about an axis ⟂ its Y
//                     (arm sensors alone cannot tell a swing from a squat: then only given intervals).
// Repetitions: the rotation angle of the driving segment about the block's axis, θ(t) = ∫ω·a dt;
// each excursion beyond half the largest one (in the sign of the first) is one repetition, and
// consecutive repetitions are split at the least-moving instant between them.
//
// Frames (SegmentCalibration.h): Y from gravity; Z from the squats (pelvis/sacrum, sternum, thighs,
// shanks), or X from the ab/adduction of the same side (feet, which stay flat in a squat).
// The upper body follows Fasel's hypotheses (§6.2.3, Table 6.2; §7.2.2): the trunk and head sensors —
// sacrum (lower back), sternum, upper back, head — take Y from gravity in the upright ("the trunk segment
// is perfectly vertical") and Z from the squats ("squat movements occur around the medio-lateral axis"
// for lower back, upper back, sternum and head); the trunk rotations' axis ("performed along the vertical
// axis") is their check against gravity (cross-orthogonality below). The arm sensors take Y from gravity
// in the upright ("the longitudinal axes of the arms and wrists ... parallel to gravity", arms hanging,
// palms on the thighs) and from the arm swings (a pole held horizontally, thumbs medial, straight elbows,
// sagittal swings: "the main rotation ... along the medio-lateral axis of the arm and along the
// anterior-posterior axis of the wrist") Z for the upper arms, X for the forearms. The swing starts
// upward (shoulder flexion, +Z); gripping the pole pronates the forearm by 90°, which turns its X (in
// the upright frame: anterior) medially, so the swing turns the right forearm about −X, the left about +X.
// Quality per segment:
//   χ  — dispersion of the functional axis between repetitions: RMS angle between each repetition's
//        principal axis and the axis of all repetitions (cf. Fasel Table 6.3);
//   orthogonality — angle between the functional axis and the plane ⟂ gravity before
//        re-orthogonalisation; cross-orthogonality — |90° − angle| between the two functional axes
//        that should be orthogonal (squat Z and ab/adduction X of thighs and shanks; for the sternum
//        and the other trunk and head sensors the angle between the trunk-rotation axis and gravity,
//        which should be parallel; none for the arms);
//   CMC — coefficient of multiple correlation of the G repetition curves θ_g(t), each resampled to
//        T = 101 points (Kadaba et al. 1989, as in Fasel §6.2):
//        CMC = sqrt(1 − [Σ_g Σ_t (θ_gt − θ̄_t)² / (T(G − 1))] / [Σ_g Σ_t (θ_gt − θ̄)² / (TG − 1)]),
//        θ̄_t the mean over repetitions at t, θ̄ the grand mean (0 when the ratio exceeds 1).
// Refusals (errors naming the segment and the reason): no upright window, a movement a segment
// needs not found or with fewer than `minRepetitions` repetitions, an axis that is not dominant,
// a dispersion above `maxDispersion`, a functional axis tilted more than `maxAxisTilt` out of the
// horizontal plane (it would be re-orthogonalised into noise: the wrong movement for that segment).
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <limits>
#include <vector>

namespace athlos::inertial {

enum class CalibrationMovement { Upright = 0, Squats, TrunkRotations, RightAbduction, LeftAbduction, ArmSwings };
inline constexpr int kCalibrationMovements = 6;
// "upright", "squats", "trunk-rotations", "right-abduction", "left-abduction", "arm-swings" (optional:
// only the arm sensors need it)
QString calibrationMovementName(CalibrationMovement movement);
Expected<CalibrationMovement> parseCalibrationMovement(const QString& name);

struct TimeInterval {
    double begin = 0.0, end = 0.0;  // s
};

class FunctionalCalibration {
public:
    struct Params {
        double smoothing = 0.5;   // s, moving average of the rate for rest detection
        double restRate = 0.2;    // rad/s (11°/s): every sensor below = rest
        double minUpright = 5.0;  // s of rest for the upright window (protocol: 10 s, spec §4)
        double minPause = 0.8;    // s of rest that separates two movement blocks
        double moveRate = 0.14;   // rad/s RMS (8°/s): a segment turns in a block
        double stillRatio = 0.3;  // the other leg's RMS rate below this share = still
        double axialTolerance = 30.0 * 0.017453292519943295;  // rad, trunk rotation axis to Y
        int minRepetitions = 3;                               // spec §4: ×3
        double maxDispersion = 10.0 * 0.017453292519943295;   // rad; Fasel reports χ ≤ 5.5° (shank)
        double maxAxisTilt = 30.0 * 0.017453292519943295;     // rad, functional axis out of the plane ⟂ gravity
    };

    struct Segment {
        // sacrum|pelvis|lower-back, sternum|trunk|thorax, upper-back, head, right-/left-thigh, -shank, -foot,
        // right-/left-upper-arm, -forearm (the segment names of body-model, plugins/body/Anthropometry.h)
        QString name;
        std::vector<double> t;             // s
        std::vector<math::Vec3> acc, gyr;  // sensor frame, m/s², rad/s
    };

    struct Movement {
        CalibrationMovement movement = CalibrationMovement::Upright;
        TimeInterval interval;
        std::vector<TimeInterval> repetitions;
        bool given = false;  // from the caller (annotations) rather than detected
    };

    struct SegmentResult {
        QString name;
        math::Quat mount = math::Quat::Identity();                   // segment → sensor
        CalibrationMovement movement = CalibrationMovement::Squats;  // the one that gave the frame
        double axisShare = 0.0;
        double dispersion = 0.0;                                               // χ, rad
        double orthogonality = 0.0;                                            // rad
        double crossOrthogonality = std::numeric_limits<double>::quiet_NaN();  // rad, NaN if not measured
        double cmc = 0.0;
        int repetitions = 0;
    };

    struct Result {
        std::vector<Movement> movements;  // found (or given), in time order
        std::vector<SegmentResult> segments;
    };

    FunctionalCalibration() = default;
    explicit FunctionalCalibration(const Params& params) : params_(params) {}

    // Finds the movements (those in `given` are taken as they are) and calibrates every segment.
    Expected<Result> calibrate(const std::vector<Segment>& segments, const std::vector<Movement>& given = {}) const;

    // Only the movement detection (for the wizard's preview and the tests).
    Expected<std::vector<Movement>> detect(const std::vector<Segment>& segments,
                                           const std::vector<Movement>& given = {}) const;

private:
    Params params_;
};

}  // namespace athlos::inertial
