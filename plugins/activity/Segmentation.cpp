#include "plugins/activity/Segmentation.h"

#include <algorithm>

namespace athlos::activity {

QStringList Segmentation::kinds() {
    return {QStringLiteral("sliding"), QStringLiteral("events:impact"), QStringLiteral("events:tackle")};
}

Expected<Segmentation> Segmentation::parse(const QString& kind) {
    if (!kinds().contains(kind))
        return makeError(
            QStringLiteral("--segmentation '%1': use one of %2").arg(kind, kinds().join(QStringLiteral(", "))));
    Segmentation s;
    s.kind = kind;
    return s;
}

QJsonObject Segmentation::toJson() const {
    QJsonObject o{{QStringLiteral("kind"), kind}};
    if (kind == QLatin1String("events:impact"))
        o[QStringLiteral("impact")] = QJsonObject{{QStringLiteral("high_pass_hz"), impact.highPass},
                                                  {QStringLiteral("low_pass_hz"), impact.lowPass},
                                                  {QStringLiteral("threshold"), impact.threshold},
                                                  {QStringLiteral("swing_window_s"), impact.swingWindow}};
    if (kind == QLatin1String("events:tackle"))
        o[QStringLiteral("tackle")] = QJsonObject{{QStringLiteral("low_pass_hz"), tackle.lowPass},
                                                  {QStringLiteral("threshold"), tackle.threshold},
                                                  {QStringLiteral("target_recall"), tackle.targetRecall},
                                                  {QStringLiteral("margin"), tackle.margin},
                                                  {QStringLiteral("min_separation_s"), tackle.minSeparation}};
    if (kind == QLatin1String("events:impact")) {
        o[QStringLiteral("use_detection_tree")] = useDetectionTree;
        o[QStringLiteral("detection_target_recall")] = detection.targetRecall;
        if (detectionTree) o[QStringLiteral("detection_tree")] = detectionTree->toJson();
    }
    if (events()) o[QStringLiteral("null_label")] = nullLabel;
    return o;
}

Expected<Segmentation> Segmentation::fromJson(const QJsonValue& json) {
    if (json.isUndefined() || json.isNull()) return Segmentation{};
    if (json.isString()) return parse(json.toString());
    const QJsonObject o = json.toObject();
    auto s = parse(o.value(QStringLiteral("kind")).toString());
    if (!s) return makeError(QStringLiteral("segmentation: ") + s.message());
    const QJsonObject i = o.value(QStringLiteral("impact")).toObject();
    s->impact.highPass = i.value(QStringLiteral("high_pass_hz")).toDouble(s->impact.highPass);
    s->impact.lowPass = i.value(QStringLiteral("low_pass_hz")).toDouble(s->impact.lowPass);
    s->impact.threshold = i.value(QStringLiteral("threshold")).toDouble(s->impact.threshold);
    s->impact.swingWindow = i.value(QStringLiteral("swing_window_s")).toDouble(s->impact.swingWindow);
    const QJsonObject t = o.value(QStringLiteral("tackle")).toObject();
    s->tackle.lowPass = t.value(QStringLiteral("low_pass_hz")).toDouble(s->tackle.lowPass);
    s->tackle.threshold = t.value(QStringLiteral("threshold")).toDouble(s->tackle.threshold);
    s->tackle.targetRecall = t.value(QStringLiteral("target_recall")).toDouble(s->tackle.targetRecall);
    s->tackle.margin = t.value(QStringLiteral("margin")).toDouble(s->tackle.margin);
    s->tackle.minSeparation = t.value(QStringLiteral("min_separation_s")).toDouble(s->tackle.minSeparation);
    s->nullLabel = o.value(QStringLiteral("null_label")).toString(s->nullLabel);
    // A model from before the detection tree has none and keeps every candidate, as it was trained.
    s->useDetectionTree = o.value(QStringLiteral("use_detection_tree")).toBool(false);
    s->detection.targetRecall = o.value(QStringLiteral("detection_target_recall")).toDouble(s->detection.targetRecall);
    if (const QJsonValue tree = o.value(QStringLiteral("detection_tree")); tree.isObject()) {
        auto t = DetectionTree::fromJson(tree.toObject());
        if (!t) return makeError(QStringLiteral("segmentation: ") + t.message());
        s->detectionTree = std::move(*t);
    }
    if (!(s->impact.highPass > 0 && s->impact.lowPass > 0 && s->impact.threshold > 0 && s->tackle.lowPass > 0 &&
          s->tackle.minSeparation >= 0))
        return makeError(QStringLiteral("segmentation: a detector parameter is not positive"));
    if (s->kind == QLatin1String("events:tackle") && !(s->tackle.threshold > 0))
        return makeError(QStringLiteral("segmentation: the tackle detector has no fitted threshold"));
    return *s;
}

Expected<std::vector<DetectedEvent>> Segmentation::detect(const StreamInfo& info, const StreamData& data) const {
    if (kind == QLatin1String("events:impact")) {
        auto events = ImpactDetector::detect(info, data, impact);
        if (!events || !useDetectionTree || !detectionTree) return events;
        std::erase_if(*events, [&](const DetectedEvent& e) { return !detectionTree->keep(e.impact, e.swing); });
        return events;
    }
    if (kind == QLatin1String("events:tackle")) return TackleDetector::detect(info, data, tackle);
    return std::vector<DetectedEvent>{};
}

Window windowAround(const StreamData& data, double t, double length) {
    Window w;
    w.tStart = t - 0.5 * length;
    w.tEnd = t + 0.5 * length;
    w.begin = std::size_t(std::lower_bound(data.t.begin(), data.t.end(), w.tStart) - data.t.begin());
    w.end = std::size_t(std::lower_bound(data.t.begin(), data.t.end(), w.tEnd) - data.t.begin());
    return w;
}

Expected<std::vector<Window>> Segmentation::windows(const StreamInfo& info, const StreamData& data, double length,
                                                    double step) const {
    if (!events()) return slidingWindows(data, length, step);
    auto found = detect(info, data);
    if (!found) return found.error();
    std::vector<Window> out;
    for (const DetectedEvent& e : *found) {
        Window w = windowAround(data, e.t, length);
        if (w.end - w.begin >= 2) out.push_back(w);
    }
    return out;
}

}  // namespace athlos::activity
