#pragma once
// The plots of the main window: the central tabs (time series, trajectory), further time-series
// panels in docks, the one time controller they all follow, and the window layout (docks and
// their streams), which is kept in the project's metadata so a project reopens as it was left.
#include <QList>
#include <QObject>
#include <QString>
#include <memory>

class QCustomPlot;
class QDockWidget;
class QMainWindow;
class QTabWidget;

namespace athlos {
class Project;
class Stream;
}  // namespace athlos

namespace athlos::ui {

class TimeController;
class TimeSeriesPanel;
class TrajectoryPanel;

class PanelLayout : public QObject {
    Q_OBJECT

public:
    // Creates the central tabs in window.
    explicit PanelLayout(QMainWindow& window);
    ~PanelLayout() override;

    // Empties every panel, removes the docked ones and binds to project (may be null).
    void setProject(std::shared_ptr<Project> project);

    QTabWidget* tabs() const { return tabs_; }
    TimeSeriesPanel* timeSeries() const { return timeSeries_; }
    TrajectoryPanel* trajectory() const { return trajectory_; }
    TimeController* timeController() const { return timeController_; }
    // The central panel first, then the docked ones.
    QList<TimeSeriesPanel*> timeSeriesPanels() const;
    // Another time-series panel in a dock, linked to the cursor, plotting path ("rec/stream").
    TimeSeriesPanel* addTimeSeriesPanel(const QString& path);

    // Plots the stream at path in the central time-series panel and, if it is position-like, on
    // the trajectory. Returns whether the time-series panel got a new stream.
    bool plot(const QString& path);
    // Empties the central panels if they show a stream that a processor run writing output
    // (or output-*) is about to replace in place.
    void releaseStreamsOf(const QString& output);

    void showTimeSeriesView();
    void showTrajectoryView();
    bool isTrajectoryShown() const;
    // The plot of the visible tab.
    QCustomPlot* currentPlot() const;

    void storeLayout();
    void restoreLayout();
    // Blocks until every panel finished loading (before saving or running a processor: the
    // panels' workers may be reading lazy samples).
    void waitForLoads();
    // waitForLoads(), then lays out and replots every panel synchronously.
    void waitForPlots();

signals:
    // A docked panel's plot, for the window's context menu.
    void plotAdded(QCustomPlot* plot);

private:
    struct DockedPanel {
        QDockWidget* dock = nullptr;
        TimeSeriesPanel* panel = nullptr;
        QString path;
    };

    void removeDockedPanels();
    void updateTimeBounds();
    std::shared_ptr<const Stream> sharedStream(const QString& path) const;

    QMainWindow& window_;
    std::shared_ptr<Project> project_;
    QTabWidget* tabs_ = nullptr;
    TimeSeriesPanel* timeSeries_ = nullptr;
    TrajectoryPanel* trajectory_ = nullptr;
    TimeController* timeController_ = nullptr;
    QList<DockedPanel> docked_;
    int nextPanelNumber_ = 1;
};

}  // namespace athlos::ui
