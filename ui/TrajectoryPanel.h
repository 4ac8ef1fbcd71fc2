#pragma once
// The 2D path of a position stream (x against y) with equal axis scaling, so a 400 m track looks
// like one, and markers at start and end. Samples load on a worker thread.
#include "ui/PanelLoader.h"

#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>
#include <memory>

class QCPCurve;
class QCPGraph;
class QCustomPlot;
class QLabel;

namespace athlos {
class Stream;
struct StreamInfo;
}  // namespace athlos

namespace athlos::ui {

class TimeController;

class TrajectoryPanel : public QWidget {
    Q_OBJECT

public:
    // A path longer than this is thinned by a stride before plotting (QCPCurve draws every
    // point; 200 k points still draw in a few tens of milliseconds).
    static constexpr int kMaxCurvePoints = 200000;

    explicit TrajectoryPanel(QWidget* parent = nullptr);
    ~TrajectoryPanel() override;

    // Position-like: kind lps-position, trajectory or gnss, with columns x and y.
    static bool isPositionStream(const StreamInfo& info);

    void setStream(std::shared_ptr<const Stream> stream, const QString& title = {});
    void clear();
    const Stream* stream() const { return stream_.get(); }
    bool isLoading() const;
    void waitForLoad();
    QString errorString() const { return error_; }
    // Shown instead of a plot title when nothing is plotted, e.g. why there is no trajectory.
    void setNote(const QString& note);

    // A marker at the position at the window's cursor time (interpolated along the path).
    void setTimeController(TimeController* controller);
    // Marker position, or NaN when the cursor is outside the path's time span.
    QPointF cursorPosition() const;

    QCustomPlot* plot() const { return plot_; }
    QCPCurve* curve() const { return curve_; }
    int pointCount() const;

public slots:
    // Frames the whole path with equal scaling on both axes.
    void showFullRange();

signals:
    void loaded();
    void loadFailed(const QString& message);

private:
    struct Loaded {
        QList<double> t, x, y;
        QString error;
    };
    static std::shared_ptr<Loaded> load(const std::shared_ptr<const Stream>& stream);

    void applyLoaded(std::shared_ptr<Loaded> result);
    void keepEqualScale();
    void updateHeader();

    QCustomPlot* plot_ = nullptr;
    QLabel* titleLabel_ = nullptr;
    QCPCurve* curve_ = nullptr;
    QCPGraph* startMarker_ = nullptr;
    QCPGraph* endMarker_ = nullptr;
    QCPGraph* cursorMarker_ = nullptr;
    TimeController* controller_ = nullptr;
    void updateCursorMarker();
    std::shared_ptr<const Stream> stream_;
    QString title_;
    QString error_;
    QString note_;
    PanelLoader loader_;
    bool hasData_ = false;
    bool userFramed_ = false;  // the user dragged/zoomed: keep the view on resize, just rescale
    double minX_ = 0, maxX_ = 0, minY_ = 0, maxY_ = 0;
    QSize lastAxisRectSize_;
};

}  // namespace athlos::ui
