#pragma once
// A trained activity classifier as stored in a project (TrainedModel, /models/<name>): the feature
// set and its input columns, the window, robust scaling (median/IQR per feature), the classes and
// the OpenCV classifier. classify() turns an IMU stream into predicted annotations that cover the
// whole classified span.
#include "core/model/Annotation.h"
#include "core/model/Stream.h"
#include "core/model/TrainedModel.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"
#include "plugins/activity/Windows.h"
#include "plugins/activity/Classifier.h"
#include "plugins/activity/CnnClassifier.h"
#include "plugins/activity/FeatureSelection.h"
#include "plugins/activity/InteractionGathering.h"
#include "plugins/activity/Segmentation.h"

#include <QJsonObject>
#include <QStringList>
#include <optional>
#include <vector>

namespace athlos::activity {

// Median and interquartile range of each feature (column of samples); an IQR of 0 becomes 1.
struct RobustScaling {
    std::vector<float> centre, scale;
    static RobustScaling fit(const cv::Mat& samples);
    void apply(cv::Mat& samples) const;  // in place: (x − centre) / scale
    QJsonObject toJson() const;
    static std::optional<RobustScaling> fromJson(const QJsonObject& json, int features);
};

class ActivityModel {
public:
    static constexpr const char* kFormat = "opencv-yaml";
    // The CNN: the ONNX bytes as base64 text (a project keeps definitions as text), parsed by cv::dnn only.
    static constexpr const char* kOnnxFormat = "onnx-base64";
    static constexpr double kEventSpan = 1.0;  // s, the interval written for a classified event

    QStringList classes;
    QStringList sensors;              // acc, gyr, mag
    QStringList features;             // names, in the order of FeatureExtractor
    QStringList inputColumns;         // stream columns read
    double window = 3.0, step = 1.5;  // s
    Segmentation segmentation;        // sliding windows, or `window` s around each detected event
    // The features the classifier reads (mutual-information selection, --select-features K); absent: all
    // of `features` (models stored before the selection existed have none). Scaling is of these columns.
    std::optional<FeatureSelection> selection;
    // Multi-athlete interaction features (InteractionGathering.h): their names end `features`; the
    // stream's own features come first. Classifying needs the player's session (PlayerContext).
    std::optional<InteractionOptions> interaction;
    RobustScaling scaling;
    std::optional<Classifier> classifier;  // features → OpenCV ml
    std::optional<CnnClassifier> cnn;      // or: raw windows of inputColumns → ONNX network (no features)
    QJsonObject provenance;                // training recordings, cross-validation, parameters (stored as is)

    // Parses a stored model (its JSON description and the OpenCV YAML text); the error says what is wrong.
    static Expected<ActivityModel> fromStored(const TrainedModel& stored);
    Expected<TrainedModel> toStored(const QString& name) const;

    // Class probabilities of each window (rows) of `samples` (every raw feature; selected and scaled here).
    void probabilities(cv::Mat samples, cv::Mat& out) const;
    // Class probabilities of `windows` of a stream: features and the classifier, or raw windows and the CNN.
    // `player`: the session of the stream, required when the model has interaction features.
    Status windowProbabilities(const StreamInfo& info, const StreamData& data, const std::vector<Window>& windows,
                               cv::Mat& out, const Progress& progress = {},
                               const PlayerContext* player = nullptr) const;

    // Refuses a stream whose columns or sensors do not match what the model was trained on.
    Status checkStream(const StreamInfo& info) const;

    // Predicted annotations for a stream. Sliding windows: windows classified, probabilities averaged
    // over `smoothing` windows on each side, consecutive windows of one class merged; each window owns
    // the time up to half-way to its neighbours' centres, the first and last extend to the ends of the
    // stream. Events: one annotation of kEventSpan s centred on each detected event whose class is
    // not the null label.
    Expected<Annotations> classify(const StreamInfo& info, const StreamData& data, int smoothing,
                                   const Progress& progress = {}, const PlayerContext* player = nullptr) const;
};

// Intervals from window centres and their class probabilities (rows): exposed for tests.
Annotations intervalsFromWindows(const std::vector<double>& centres, const cv::Mat& probabilities,
                                 const QStringList& classes, double tBegin, double tEnd, int smoothing);

}  // namespace athlos::activity
