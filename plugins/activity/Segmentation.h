#pragma once
// How a stream is cut into windows to classify (seed 000 §5.2): sliding windows for continuous
// activities, or a window centred on each event an EventDetector finds for discrete actions
// (`events:impact`, `events:tackle`). A model stores its segmentation (with a fitted threshold), so
// classify-actions cuts new recordings exactly as training did.
#include "core/model/Stream.h"
#include "core/util/Expected.h"
#include "plugins/activity/DetectionTree.h"
#include "plugins/activity/EventDetectors.h"
#include "plugins/activity/Windows.h"

#include <QJsonObject>
#include <QJsonValue>
#include <optional>

namespace athlos::activity {

struct Segmentation {
    QString kind = QStringLiteral("sliding");  // sliding, events:impact, events:tackle
    ImpactDetector::Params impact;
    TackleDetector::Params tackle;
    // events:impact: the cost-sensitive detection tree on the impact and swing indicators (§5.2), fitted
    // by training to keep detection.targetRecall of the annotated actions; off when useDetectionTree is
    // false (every candidate goes to the classifier, whose null class sorts them).
    bool useDetectionTree = true;
    DetectionTree::Params detection;
    std::optional<DetectionTree> detectionTree;
    // Events not inside an annotation are trained as this class (the detector's false alarms, the
    // thesis's "Null"); a predicted null is not written as an annotation.
    QString nullLabel = QStringLiteral("null");

    static QStringList kinds();
    static Expected<Segmentation> parse(const QString& kind);  // the error names --segmentation
    bool events() const { return kind != QLatin1String("sliding"); }
    QJsonObject toJson() const;
    // An object, a kind name, or nothing (a model from before segmentations: sliding).
    static Expected<Segmentation> fromJson(const QJsonValue& json);

    // Detected events (empty for sliding); impact candidates the detection tree rejects are left out.
    Expected<std::vector<DetectedEvent>> detect(const StreamInfo& info, const StreamData& data) const;
    // Windows: sliding (length, step), or `length` s centred on each event.
    Expected<std::vector<Window>> windows(const StreamInfo& info, const StreamData& data, double length,
                                          double step) const;
};

// A window of `length` s centred on t, with the rows inside it.
Window windowAround(const StreamData& data, double t, double length);

}  // namespace athlos::activity
