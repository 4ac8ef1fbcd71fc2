#include "ui/PanelLayout.h"

#include "core/model/Project.h"
#include "ui/TimeController.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/TrajectoryPanel.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QJsonArray>
#include <QMainWindow>
#include <QTabWidget>
#include <qcustomplot.h>

#include <algorithm>
#include <limits>

namespace athlos::ui {

namespace {
const QString kLayoutKey = QStringLiteral("ui_layout");
const QString kPanelsKey = QStringLiteral("ui_panels");
const QString kDockPrefix = QStringLiteral("timeSeriesDock");
}  // namespace

PanelLayout::PanelLayout(QMainWindow& window) : QObject(&window), window_(window) {
    timeController_ = new TimeController(&window);
    timeSeries_ = new TimeSeriesPanel(&window);
    timeSeries_->setTimeController(timeController_);
    connect(timeSeries_, &TimeSeriesPanel::loaded, this, &PanelLayout::updateTimeBounds);
    trajectory_ = new TrajectoryPanel(&window);
    trajectory_->setTimeController(timeController_);
    tabs_ = new QTabWidget(&window);
    tabs_->setDocumentMode(true);
    // The tab titles were the main window's strings; that context keeps their translations.
    tabs_->addTab(timeSeries_, QCoreApplication::translate("athlos::ui::MainWindow", "Time series"));
    tabs_->addTab(trajectory_, QCoreApplication::translate("athlos::ui::MainWindow", "Trajectory"));
    window.setCentralWidget(tabs_);
}

PanelLayout::~PanelLayout() = default;

void PanelLayout::setProject(std::shared_ptr<Project> project) {
    // Panels may hold pointers into the old project; they let go before it does.
    removeDockedPanels();
    timeSeries_->clear();
    trajectory_->clear();
    project_ = std::move(project);
}

QList<TimeSeriesPanel*> PanelLayout::timeSeriesPanels() const {
    QList<TimeSeriesPanel*> panels{timeSeries_};
    for (const DockedPanel& docked : docked_) panels << docked.panel;
    return panels;
}

TimeSeriesPanel* PanelLayout::addTimeSeriesPanel(const QString& path) {
    std::shared_ptr<const Stream> stream = sharedStream(path);
    if (!stream) return nullptr;
    DockedPanel docked;
    docked.path = path;
    docked.dock = new QDockWidget(path, &window_);
    // Stable names: saveState/restoreState match docks by object name.
    docked.dock->setObjectName(kDockPrefix + QString::number(nextPanelNumber_++));
    docked.dock->setAttribute(Qt::WA_DeleteOnClose);
    docked.panel = new TimeSeriesPanel(docked.dock);
    docked.panel->setTimeController(timeController_);
    emit plotAdded(docked.panel->plot());
    docked.dock->setWidget(docked.panel);
    window_.addDockWidget(Qt::BottomDockWidgetArea, docked.dock);
    connect(docked.panel, &TimeSeriesPanel::loaded, this, &PanelLayout::updateTimeBounds);
    QDockWidget* dock = docked.dock;
    connect(dock, &QObject::destroyed, this,
            [this, dock] { docked_.removeIf([dock](const DockedPanel& d) { return d.dock == dock; }); });
    docked.panel->setStream(std::move(stream), path);
    docked_ << docked;
    return docked.panel;
}

void PanelLayout::removeDockedPanels() {
    const QList<DockedPanel> panels = docked_;
    docked_.clear();
    for (const DockedPanel& docked : panels) {
        docked.panel->waitForLoad();
        docked.panel->clear();
        window_.removeDockWidget(docked.dock);
        delete docked.dock;
    }
    nextPanelNumber_ = 1;
}

bool PanelLayout::plot(const QString& path) {
    std::shared_ptr<const Stream> stream = sharedStream(path);
    if (!stream) return false;
    bool changed = false;
    if (timeSeries_->stream() != stream.get()) {
        timeSeries_->setStream(stream, path);
        changed = true;
    }
    if (TrajectoryPanel::isPositionStream(stream->info()) && trajectory_->stream() != stream.get())
        trajectory_->setStream(stream, path);
    return changed;
}

void PanelLayout::releaseStreamsOf(const QString& output) {
    if (!project_) return;
    const auto replaced = [&](const Stream* shown) {
        if (!shown) return false;
        for (const QString& path : project_->streamPaths())
            if (project_->stream(path) == shown && (path == output || path.startsWith(output + QLatin1Char('-'))))
                return true;
        return false;
    };
    if (replaced(timeSeries_->stream())) timeSeries_->clear();
    if (replaced(trajectory_->stream())) trajectory_->clear();
}

void PanelLayout::showTimeSeriesView() { tabs_->setCurrentWidget(timeSeries_); }

void PanelLayout::showTrajectoryView() { tabs_->setCurrentWidget(trajectory_); }

bool PanelLayout::isTrajectoryShown() const { return tabs_->currentWidget() == trajectory_; }

QCustomPlot* PanelLayout::currentPlot() const {
    return isTrajectoryShown() ? trajectory_->plot() : timeSeries_->plot();
}

void PanelLayout::updateTimeBounds() {
    double begin = std::numeric_limits<double>::infinity(), end = -begin, step = 0;
    for (TimeSeriesPanel* panel : timeSeriesPanels()) {
        const StreamData* data = panel->data();
        if (!data || data->rows() == 0) continue;
        begin = std::min(begin, data->t.front());
        end = std::max(end, data->t.back());
        if (panel == timeSeries_ || step == 0) step = data->medianInterval();
    }
    if (!(begin <= end)) return;
    // The view the panel chose (its full range) survives the reset of the bounds.
    const double viewBegin = timeSeries_->data() ? timeController_->visibleBegin() : begin;
    const double viewEnd = timeSeries_->data() ? timeController_->visibleEnd() : end;
    timeController_->setBounds(begin, end);
    if (step > 0) timeController_->setStep(step);
    timeController_->setVisibleRange(viewBegin, viewEnd);
}

void PanelLayout::storeLayout() {
    if (!project_) return;
    QJsonArray panels;
    for (const DockedPanel& docked : docked_)
        panels.append(
            QJsonObject{{QStringLiteral("name"), docked.dock->objectName()}, {QStringLiteral("stream"), docked.path}});
    QJsonObject& meta = project_->meta().extra;
    meta[kPanelsKey] = panels;
    meta[kLayoutKey] = QString::fromLatin1(window_.saveState().toBase64());
}

void PanelLayout::restoreLayout() {
    if (!project_) return;
    const QJsonObject& meta = project_->meta().extra;
    int highest = 0;
    for (const QJsonValue& value : meta.value(kPanelsKey).toArray()) {
        const QJsonObject panel = value.toObject();
        const QString name = panel.value(QStringLiteral("name")).toString();
        bool ok = false;
        const int number = name.mid(kDockPrefix.size()).toInt(&ok);
        if (!ok) continue;
        nextPanelNumber_ = number;  // reuse the saved name so restoreState finds the dock
        if (addTimeSeriesPanel(panel.value(QStringLiteral("stream")).toString())) highest = std::max(highest, number);
    }
    nextPanelNumber_ = highest + 1;
    const QByteArray state = QByteArray::fromBase64(meta.value(kLayoutKey).toString().toLatin1());
    if (!state.isEmpty()) window_.restoreState(state);
}

void PanelLayout::waitForLoads() {
    for (const DockedPanel& docked : docked_) docked.panel->waitForLoad();
    timeSeries_->waitForLoad();
    trajectory_->waitForLoad();
}

void PanelLayout::waitForPlots() {
    waitForLoads();
    // Layout first (plot widths decide the decimation), then draw synchronously.
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::processEvents();
        for (TimeSeriesPanel* panel : timeSeriesPanels()) panel->plot()->replot(QCustomPlot::rpImmediateRefresh);
        trajectory_->plot()->replot(QCustomPlot::rpImmediateRefresh);
    }
}

std::shared_ptr<const Stream> PanelLayout::sharedStream(const QString& path) const {
    if (!project_) return {};
    const Stream* stream = project_->stream(path);
    if (!stream) return {};
    // Aliasing pointer: keeps the whole project alive while a worker still reads the stream.
    return std::shared_ptr<const Stream>(project_, stream);
}

}  // namespace athlos::ui
