#pragma once
// Training an activity classifier from annotated recordings (seed 000 §5.2–5.3; digest §7–§9):
// windows labelled by annotation overlap, features, cross-validation grouped by recording or
// athlete (leave-subjects-out, as Table 5.2), metrics, and the final model trained on everything.
#include "core/model/Project.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"
#include "plugins/activity/ActivityModel.h"
#include "plugins/activity/Classifier.h"
#include "plugins/activity/InteractionGathering.h"
#include "plugins/activity/Segmentation.h"
#include "plugins/activity/Windows.h"

#include <QJsonObject>
#include <QStringList>
#include <memory>
#include <vector>

namespace athlos::activity {

// One annotated recording to learn from.
struct TrainingSource {
    QString recording;
    QString athlete;  // the stream's attribute "athlete", else the recording's metadata "athlete", else its name
    StreamInfo info;
    std::shared_ptr<const StreamData> data;
    Annotations annotations;    // ground truth (manual or imported)
    PlayerContext interaction;  // the other athletes of the session (attachInteraction), with interaction features
    // Team sessions with event segmentation (attributeSessionEvents): annotated events of other athletes of
    // the recording; no candidate inside them is trained on (neither as their class nor as null).
    Annotations excluded;
};

struct TrainingOptions {
    double window = 3.0;  // s
    double step = 1.5;    // s
    QStringList sensors{QStringLiteral("acc"), QStringLiteral("gyr")};
    QStringList classes;            // empty: every label found
    double minLabelFraction = 0.5;  // a window's label must cover this much of it
    ClassifierOptions classifier;
    QString validation = QStringLiteral("leave-one-athlete-out");  // or leave-one-recording-out, k-fold, none
    int folds = 5;
    int maxGroups = 10;         // leave-one-*-out with more subjects: subjects dealt into this many folds
    int rawLength = 0;          // raw windows (CNN): samples per window; 0: the window at the first recording's rate
    Segmentation segmentation;  // sliding windows or windows around detected events
    // Mutual-information feature selection (FeatureSelection.h): the classifier reads the K features of
    // highest I(feature; class), ranked on the training windows of each cross-validation fold (the test
    // fold never chooses its features) and on all windows for the stored model; 0: every feature.
    int selectFeatures = 0;
    int miBins = FeatureSelection::kDefaultBins;
    // Multi-athlete interaction features (InteractionGathering.h, --interaction k=3): appended to each
    // window's IMU features; event segmentation only (the thesis's tackle candidates, seed 000 §5.1.2).
    std::optional<InteractionOptions> interaction;
    // Team sessions (several sources in one recording share its annotations, which do not say whose
    // action it was): an annotated event is the action of the `actors` sources whose detector signal
    // peaks highest inside it (2: a tackle's carrier and tackler, seed 000 §5.1.2).
    int actors = 2;
};

// A window of a source with its label (index into the classes).
struct LabelledWindow {
    Window window;
    int label = -1;
};

// The windows of `source` that carry one of `classes`: sliding windows labelled by annotation overlap,
// or windows around detected events labelled by the annotation holding the event (else the null label).
Expected<std::vector<LabelledWindow>> labelledWindows(const TrainingSource& source, const TrainingOptions& options,
                                                      const Segmentation& segmentation, const QStringList& classes);
// options.segmentation ready to use: the tackle detector's threshold fitted on the annotations of
// `classes` (other than the null label) so that it reaches its target recall; for events:impact the
// cost-sensitive detection tree trained on the candidates (DetectionTree.h).
Expected<Segmentation> fitSegmentation(const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                                       const QStringList& classes);
// The classes: options.classes, else every ground-truth label of the sources (sorted; with event
// segmentation the null label too).
QStringList trainingClasses(const std::vector<TrainingSource>& sources, const TrainingOptions& options);

struct Dataset {
    cv::Mat samples;          // windows × features, CV_32F (unscaled)
    std::vector<int> labels;  // class index per window
    std::vector<int> source;  // index into the sources per window
    QStringList classes;
    QStringList features, inputColumns, sensors;
    QJsonObject units;          // column → unit of the training streams
    Segmentation segmentation;  // as fitted (tackle threshold)
};

struct Evaluation {
    QStringList classes;
    std::vector<std::vector<long long>> confusion;  // [truth][predicted]
    double balancedAccuracy = 0;                    // mean recall over classes present
    double accuracy = 0;
    std::vector<double> recall, precision;  // NaN when undefined
    QJsonObject toJson() const;
    QString toText() const;
};

// Ground truth: annotations made by hand ("manual"), imported ("import") or written by a simulator as
// the truth of what it simulated (processor id "simulate-…", e.g. simulate-rugby's tackles); predictions
// (classify-actions, detect-scrums, …) are never trained on.
bool isGroundTruth(const Annotation& annotation);
// Sources in `project`: recordings (all when `recordings` is empty) that have stream `stream` and
// ground-truth annotations (isGroundTruth). `stream` may
// be a wildcard pattern (`sim-imu-*`): every matching stream of a recording is a source of its own (one
// per player of a team session; they share the recording's annotations).
Expected<std::vector<TrainingSource>> trainingSources(const Project& project, const QString& stream,
                                                      const QStringList& recordings);
// With event segmentation, each annotated event of a recording shared by several sources kept only on
// the options.actors sources whose detector signal peaks highest inside it (others get it in `excluded`).
Expected<std::vector<TrainingSource>> attributeSessionEvents(std::vector<TrainingSource> sources,
                                                             const TrainingOptions& options);
// Gathers each source's session (the other athletes' positions and torso pitch, InteractionGathering.h),
// once per recording; the error names what is missing.
Status attachInteraction(const Project& project, std::vector<TrainingSource>& sources,
                         const InteractionOptions& options, const Progress& progress = {});
// The streams read for the interaction features of `sources` ("rec/stream", content hash), for provenance.
QJsonArray interactionStreams(const std::vector<TrainingSource>& sources);

Expected<Dataset> buildDataset(const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                               const Progress& progress = {});

Evaluation evaluate(const std::vector<int>& truth, const std::vector<int>& predicted, const QStringList& classes);

// Cross-validated predictions of every window (grouped by `groups`: one id per window).
Expected<Evaluation> crossValidate(const Dataset& dataset, const std::vector<int>& groups,
                                   const TrainingOptions& options, const Progress& progress = {});
// The fold groups of each window for options.validation ("k-fold": windows of one recording stay
// together, recordings dealt into `folds` folds).
Expected<std::vector<int>> foldGroups(const Dataset& dataset, const std::vector<TrainingSource>& sources,
                                      const TrainingOptions& options);

// progress: the random forest's parts (cancellation stops between them).
Expected<ActivityModel> trainModel(const Dataset& dataset, const TrainingOptions& options,
                                   const Progress& progress = {});

// Every feature of the dataset ranked by mutual information with the class (on all its windows).
FeatureSelection rankFeatures(const Dataset& dataset, const TrainingOptions& options);

// The training parameters as stored in a model's provenance ("parameters"), the same from CLI and GUI.
QJsonObject trainingParameters(const TrainingOptions& options);

}  // namespace athlos::activity
