#pragma once
// Plots columns of one stream against time with QCustomPlot, in stacked lanes (one axis rect per
// channel family and unit, PlotLanes.h) that share the time axis. Samples load and their decimation
// pyramids build on a worker thread; on every x-range change the plot is fed ~2 points per pixel
// column (min and max, in time order), or the raw samples once few enough are visible. That keeps
// dragging and zooming fluid with 10 million samples per column.
#include "ui/MinMaxPyramid.h"
#include "ui/PanelLoader.h"

#include <QStringList>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QCPAxis;
class QCPAxisRect;
class QCPItemStraightLine;
class QCPLegend;
class QCPMarginGroup;
class QCPRange;
class QCustomPlot;
class QLabel;
class QMenu;
class QKeyEvent;
class QMouseEvent;
class QTimer;
class QToolButton;

namespace athlos {
class Stream;
}

namespace athlos::ui {

class TimeController;

class TimeSeriesPanel : public QWidget {
    Q_OBJECT

public:
    explicit TimeSeriesPanel(QWidget* parent = nullptr);
    ~TimeSeriesPanel() override;

    // Plots stream (the pointer keeps it alive, e.g. an aliasing pointer into a shared project).
    // columns: names to show; empty shows all. Returns at once; loaded() or loadFailed() follows.
    void setStream(std::shared_ptr<const Stream> stream, const QString& title = {}, const QStringList& columns = {});
    void clear();
    const Stream* stream() const { return stream_.get(); }
    QString title() const { return title_; }

    QStringList visibleColumns() const;
    void setVisibleColumns(const QStringList& columns);

    // Time axis labels as clock time (t0_utc + t, or t0_time_of_day + t) instead of elapsed seconds;
    // only for streams whose file gave an absolute time (canShowClockTime()).
    bool canShowClockTime() const { return t0_.has_value(); }
    bool clockTime() const { return clockTime_; }
    void setClockTime(bool on);

    // Fit the y axis to what is visible after every x change (then y is not dragged by mouse).
    bool autoFitY() const { return autoFitY_; }
    void setAutoFitY(bool on);

    bool isLoading() const;
    // Blocks until the pending load finished and its graphs are in place (tests, screenshots,
    // and before anything that must not run concurrently with a load, such as saving).
    void waitForLoad();
    QString errorString() const { return error_; }

    // Follows the window's time cursor: x range linked both ways, a cursor line, click sets
    // the cursor, and a read-out of values at the cursor and statistics of the visible range.
    void setTimeController(TimeController* controller);
    TimeController* timeController() const { return controller_; }
    QCPItemStraightLine* cursorLine() const { return cursorLine_; }
    // The read-out as shown (HTML); refreshed at once by updateReadout().
    QString readoutText() const;
    void updateReadout();
    // Samples of the loaded stream, or nullptr while none is loaded.
    const StreamData* data() const;

    QCustomPlot* plot() const { return plot_; }
    // The stacked lanes, top to bottom; lane 0 is the plot's main axis rect (plot()->axisRect()).
    int laneCount() const { return int(lanes_.size()); }
    QCPAxisRect* laneRect(int lane) const { return lanes_.at(std::size_t(lane)).rect; }
    // The lane of graph g (plot()->graph(g)).
    int laneOfGraph(int graph) const { return graphLane_.at(std::size_t(graph)); }
    // Points currently handed to QCustomPlot, over all graphs.
    long long plottedPointCount() const;
    // Pixel columns the last decimation was computed for.
    int decimationWidth() const { return decimatedWidth_; }

public slots:
    void showFullRange();
    // Recomputes the plotted points for the current x range and plot width.
    void redecimate();

signals:
    void loaded();
    void loadFailed(const QString& message);
    // The stacked lanes were rebuilt (other axis rects now; overlays such as annotations redraw).
    void lanesChanged();

protected:
    // Transport keys (space, arrows, J/K/L) go to the time controller while the panel has focus.
    void keyPressEvent(QKeyEvent* event) override;

private:
    struct Loaded {
        std::shared_ptr<const StreamData> data;
        std::vector<MinMaxPyramid> pyramids;  // one per stream column
        QString error;
    };
    static std::shared_ptr<Loaded> load(const std::shared_ptr<const Stream>& stream);

    void applyLoaded(std::shared_ptr<Loaded> result);
    void rebuildGraphs();
    void rebuildColumnMenu();
    void updateHeader();
    struct Lane {
        QCPAxisRect* rect = nullptr;
        QCPLegend* legend = nullptr;
        QCPItemStraightLine* cursor = nullptr;
    };
    void fitY(QCPAxis* axis, const Extremes& extremes);
    void fitAllY(const std::vector<Extremes>& perLane);
    void addLane(const QString& unit);
    void removeExtraLanes();
    void applyRangeInteractions();
    void applyTimeAxis();
    void onXRangeChanged(const QCPRange& range);
    void onAfterLayout();
    int plotWidthPixels() const;
    void onCursorChanged(double t);
    void onControllerRange(double begin, double end);
    void onPlotClicked(QMouseEvent* event);

    QCustomPlot* plot_ = nullptr;
    QLabel* titleLabel_ = nullptr;
    QToolButton* columnsButton_ = nullptr;
    QMenu* columnsMenu_ = nullptr;
    QCheckBox* fitYBox_ = nullptr;
    QCheckBox* clockBox_ = nullptr;
    QLabel* readout_ = nullptr;
    QCPItemStraightLine* cursorLine_ = nullptr;
    TimeController* controller_ = nullptr;
    QTimer* readoutTimer_ = nullptr;
    bool followingController_ = false;  // applying the controller's range: do not echo it back
    QPoint pressPos_;
    bool replotted_ = false;

    std::shared_ptr<const Stream> stream_;
    QString title_;
    QString error_;
    QStringList requestedColumns_;
    std::vector<int> visible_;    // stream column indices with a graph, in graph order
    std::vector<Lane> lanes_;     // lanes_[0] is the main axis rect, its legend and cursor line
    std::vector<int> graphLane_;  // per graph
    QCPMarginGroup* marginGroup_ = nullptr;
    bool syncingX_ = false;     // copying the main x range into the other lanes
    std::optional<double> t0_;  // of the loaded stream: s since the epoch (or midnight) at t = 0
    bool t0IsTimeOfDay_ = false;
    bool clockTime_ = false;
    std::shared_ptr<Loaded> loaded_;
    PanelLoader loader_;
    bool autoFitY_ = true;
    bool decimating_ = false;
    int decimatedWidth_ = 0;
};

}  // namespace athlos::ui
