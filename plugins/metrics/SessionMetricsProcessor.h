#pragma once
// `session-metrics`: the coach's table of a session — one row per period (the whole session, the
// halves or drills given by annotation intervals, consecutive windows) with distance, maximum speed,
// zone distances, high-speed running, sprints, accelerations and decelerations, peak distances,
// metabolic power and energy, PlayerLoad from an IMU and action counts from annotations. Positions are
// smoothed first by default (MotionFromPositions.h); the smoothed motion is a second output.
#include "core/processing/Processor.h"
#include "core/geometry/TrackGeometry.h"
#include "plugins/metrics/MotionFromPositions.h"
#include "plugins/metrics/TrackSplits.h"

#include <optional>

namespace athlos::metrics {

class SessionMetricsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("session-metrics"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    struct Plan {
        MetricsParams metrics;
        MotionParams motion;
        QString filterMode;                  // "auto" or "none"
        double window = 300.0;               // s, 0 = no windows
        QString periods;                     // "auto" or a list of labels
        QString periodPattern;               // regular expression of period labels (periods=auto)
        std::optional<TrackGeometry> track;  // lap and split rows when given
        TrackSplits::Params splits;
    };
    Expected<Plan> makePlan(const RunContext& context) const;
};

}  // namespace athlos::metrics
