#pragma once
// A position-filter result on its track: raw fixes (grey dots), the filtered trajectory (coloured
// by speed), rejected fixes (red) and the track's kerb and lane lines. Everything it shows is read
// from the result's provenance (input stream, track and pose), so it draws any stored result the
// way it was computed.
#include "core/geometry/TrackGeometry.h"
#include "core/util/Expected.h"

#include <QList>
#include <QString>
#include <QVector>
#include <QWidget>
#include <memory>

class QCPCurve;
class QCPColorScale;
class QCustomPlot;
class QLabel;

namespace athlos {
class Project;
}

namespace athlos::ui {

class EqualAspectFrame;
class TrackOverlay;

class TrackTrajectoryView : public QWidget {
    Q_OBJECT

public:
    explicit TrackTrajectoryView(QWidget* parent = nullptr);
    ~TrackTrajectoryView() override;

    // "rec/stream" of the first position-filter output (kind trajectory) in the project, or empty.
    static QString findResult(const Project& project);
    // The track a result was computed with (the provenance's track and pose), or the default 400 m.
    static TrackGeometry trackOf(const Project& project, const QString& trajectoryPath);

    Status setResult(const Project& project, const QString& trajectoryPath);

    QCustomPlot* plot() const { return plot_; }
    TrackOverlay* overlay() const { return overlay_.get(); }
    QCPCurve* rawCurve() const { return raw_; }
    QCPCurve* outlierCurve() const { return outliers_; }
    QCPCurve* trajectoryCurve() const { return trajectory_; }
    QString summary() const;
    // Frames everything with equal metres per pixel on both axes.
    void showFullRange();

private:
    void clearSpeedRuns();
    void addSpeedRuns(const QVector<double>& x, const QVector<double>& y, const QVector<double>& speed);

    QCustomPlot* plot_ = nullptr;
    QLabel* summaryLabel_ = nullptr;
    std::unique_ptr<TrackOverlay> overlay_;
    QCPCurve* raw_ = nullptr;
    QCPCurve* outliers_ = nullptr;
    QCPCurve* trajectory_ = nullptr;
    QList<QCPCurve*> speedRuns_;
    QCPColorScale* colorScale_ = nullptr;
    EqualAspectFrame* aspect_ = nullptr;
    QString summary_;
};

}  // namespace athlos::ui
