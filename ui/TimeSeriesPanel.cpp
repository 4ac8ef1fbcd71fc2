#include "ui/TimeSeriesPanel.h"

#include "core/model/Stream.h"
#include "ui/ClockTimeTicker.h"
#include "ui/PlotLanes.h"
#include "ui/PlotStyle.h"
#include "ui/RangeStatistics.h"
#include "ui/TimeController.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace athlos::ui {

namespace {
// Samples at least this many pixels apart get a marker, so single samples are visible when
// zoomed far in.
constexpr double kMarkerSpacingPixels = 6.0;
}  // namespace

TimeSeriesPanel::TimeSeriesPanel(QWidget* parent) : QWidget(parent) {
    titleLabel_ = new QLabel(this);
    titleLabel_->setTextFormat(Qt::PlainText);
    QFont bold = titleLabel_->font();
    bold.setBold(true);
    titleLabel_->setFont(bold);

    columnsMenu_ = new QMenu(this);
    columnsButton_ = new QToolButton(this);
    columnsButton_->setText(tr("Columns"));
    columnsButton_->setToolTip(tr("Choose the columns to plot"));
    columnsButton_->setPopupMode(QToolButton::InstantPopup);
    columnsButton_->setMenu(columnsMenu_);
    columnsButton_->setEnabled(false);

    fitYBox_ = new QCheckBox(tr("Fit y to visible range"), this);
    fitYBox_->setChecked(autoFitY_);
    connect(fitYBox_, &QCheckBox::toggled, this, &TimeSeriesPanel::setAutoFitY);

    clockBox_ = new QCheckBox(tr("Clock time"), this);
    clockBox_->setObjectName(QStringLiteral("clockTimeBox"));
    clockBox_->setToolTip(
        tr("Label the time axis with the time of day (UTC) the file gives, instead of seconds "
           "since the first sample"));
    clockBox_->setEnabled(false);
    connect(clockBox_, &QCheckBox::toggled, this, &TimeSeriesPanel::setClockTime);

    auto* resetButton = new QToolButton(this);
    resetButton->setText(tr("Full range"));
    resetButton->setToolTip(tr("Show the whole recording (double-click the plot does the same)"));
    connect(resetButton, &QToolButton::clicked, this, &TimeSeriesPanel::showFullRange);

    plot_ = new QCustomPlot(this);
    PlotStyle::apply(plot_);
    // Clicking the plot focuses the panel, so the transport keys reach it.
    setFocusPolicy(Qt::StrongFocus);
    plot_->setFocusPolicy(Qt::ClickFocus);
    plot_->setFocusProxy(this);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->axisRect()->setRangeZoom(Qt::Horizontal);
    plot_->axisRect()->setRangeDrag(Qt::Horizontal);
    plot_->xAxis->setLabel(tr("t [s]"));
    plot_->legend->setVisible(false);
    connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, &TimeSeriesPanel::onXRangeChanged);
    connect(plot_, &QCustomPlot::afterLayout, this, &TimeSeriesPanel::onAfterLayout);
    connect(plot_, &QCustomPlot::afterReplot, this, [this] { replotted_ = true; });
    connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { showFullRange(); });
    connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* event) {
        pressPos_ = event->pos();
        // Ctrl+drag: zoom to the dragged time span (all linked panels follow the x range).
        plot_->setSelectionRectMode(event->modifiers() & Qt::ControlModifier ? QCP::srmZoom : QCP::srmNone);
    });
    connect(plot_, &QCustomPlot::mouseRelease, this, &TimeSeriesPanel::onPlotClicked);

    // The cursor lives on its own buffered layer so moving it does not redraw 10^7-sample graphs.
    plot_->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmBuffered);
    cursorLine_ = new QCPItemStraightLine(plot_);
    cursorLine_->setPen(QPen(QColor(0xd5, 0x5e, 0x00), 1.5));
    cursorLine_->setSelectable(false);
    cursorLine_->setVisible(false);
    cursorLine_->setLayer(QStringLiteral("overlay"));
    marginGroup_ = new QCPMarginGroup(plot_);
    plot_->axisRect()->setMarginGroup(QCP::msLeft | QCP::msRight, marginGroup_);
    lanes_.push_back({plot_->axisRect(), plot_->legend, cursorLine_});

    readout_ = new QLabel(this);
    readout_->setTextFormat(Qt::RichText);
    readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    readout_->setContentsMargins(6, 0, 6, 4);
    readout_->setVisible(false);
    // Statistics walk every visible sample: computed once the range settles, not per drag step.
    readoutTimer_ = new QTimer(this);
    readoutTimer_->setSingleShot(true);
    readoutTimer_->setInterval(60);
    connect(readoutTimer_, &QTimer::timeout, this, &TimeSeriesPanel::updateReadout);

    auto* header = new QHBoxLayout;
    header->setContentsMargins(6, 4, 6, 0);
    header->addWidget(titleLabel_, 1);
    header->addWidget(columnsButton_);
    header->addWidget(clockBox_);
    header->addWidget(fitYBox_);
    header->addWidget(resetButton);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(header);
    layout->addWidget(plot_, 1);
    layout->addWidget(readout_);

    updateHeader();
}

TimeSeriesPanel::~TimeSeriesPanel() = default;

std::shared_ptr<TimeSeriesPanel::Loaded> TimeSeriesPanel::load(const std::shared_ptr<const Stream>& stream) {
    auto result = std::make_shared<Loaded>();
    auto data = stream->data();
    if (!data) {
        result->error = data.message();
        return result;
    }
    result->data = data.value();
    // Every column gets its pyramid now, so toggling columns later is instant.
    result->pyramids.reserve(static_cast<std::size_t>(result->data->columns));
    for (int c = 0; c < result->data->columns; ++c) result->pyramids.emplace_back(result->data, c);
    return result;
}

void TimeSeriesPanel::setStream(std::shared_ptr<const Stream> stream, const QString& title,
                                const QStringList& columns) {
    clear();
    if (!stream) return;
    stream_ = std::move(stream);
    title_ = title.isEmpty() ? stream_->name() : title;
    requestedColumns_ = columns;
    loader_.start<std::shared_ptr<Loaded>>([stream = stream_] { return load(stream); },
                                           [this](std::shared_ptr<Loaded> result) { applyLoaded(std::move(result)); });
    updateHeader();
}

void TimeSeriesPanel::clear() {
    loader_.cancel();  // the result of a load still running is dropped when it arrives
    stream_.reset();
    loaded_.reset();
    title_.clear();
    error_.clear();
    visible_.clear();
    requestedColumns_.clear();
    t0_.reset();
    clockBox_->setEnabled(false);
    plot_->clearGraphs();
    removeExtraLanes();
    applyTimeAxis();
    graphLane_.clear();
    emit lanesChanged();
    plot_->legend->setVisible(false);
    plot_->yAxis->setLabel({});
    readout_->clear();
    readout_->setVisible(false);
    rebuildColumnMenu();
    updateHeader();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

bool TimeSeriesPanel::isLoading() const { return loader_.isLoading(); }

void TimeSeriesPanel::waitForLoad() { loader_.waitForLoad(); }

void TimeSeriesPanel::applyLoaded(std::shared_ptr<Loaded> result) {
    if (!result->error.isEmpty()) {
        error_ = result->error;
        updateHeader();
        emit loadFailed(error_);
        return;
    }
    loaded_ = std::move(result);
    t0_ = ClockTimeTicker::t0Of(stream_->info().attributes);
    t0IsTimeOfDay_ = !stream_->info().attributes.contains(QStringLiteral("t0_utc"));
    clockBox_->setEnabled(t0_.has_value());

    visible_.clear();
    const StreamInfo& info = stream_->info();
    for (int c = 0; c < loaded_->data->columns; ++c) {
        const QString name = c < int(info.columns.size()) ? info.columns[std::size_t(c)].name : QString();
        if (requestedColumns_.isEmpty() || requestedColumns_.contains(name)) visible_.push_back(c);
    }
    rebuildColumnMenu();
    rebuildGraphs();
    updateHeader();
    showFullRange();
    updateReadout();
    emit loaded();
}

QStringList TimeSeriesPanel::visibleColumns() const {
    QStringList names;
    if (!stream_) return names;
    for (int c : visible_) names << stream_->info().columns.at(std::size_t(c)).name;
    return names;
}

void TimeSeriesPanel::setVisibleColumns(const QStringList& columns) {
    requestedColumns_ = columns;
    if (!loaded_) return;
    visible_.clear();
    const Columns& cols = stream_->info().columns;
    for (int c = 0; c < int(cols.size()) && c < loaded_->data->columns; ++c)
        if (columns.contains(cols[std::size_t(c)].name)) visible_.push_back(c);
    rebuildColumnMenu();
    rebuildGraphs();
    redecimate();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void TimeSeriesPanel::setAutoFitY(bool on) {
    autoFitY_ = on;
    fitYBox_->setChecked(on);
    // With auto-fit the y range belongs to the panel; without it the user may drag it too.
    applyRangeInteractions();
    if (on) {
        redecimate();
        plot_->replot(QCustomPlot::rpQueuedReplot);
    }
}

void TimeSeriesPanel::rebuildColumnMenu() {
    columnsMenu_->clear();
    columnsButton_->setEnabled(loaded_ != nullptr);
    if (!loaded_) return;
    const Columns& cols = stream_->info().columns;
    for (int c = 0; c < int(cols.size()) && c < loaded_->data->columns; ++c) {
        QAction* action =
            columnsMenu_->addAction(PlotStyle::columnLabel(cols[std::size_t(c)].name, cols[std::size_t(c)].unit));
        action->setCheckable(true);
        action->setChecked(std::find(visible_.begin(), visible_.end(), c) != visible_.end());
        action->setData(cols[std::size_t(c)].name);
        connect(action, &QAction::toggled, this, [this] {
            QStringList names;
            for (QAction* a : columnsMenu_->actions())
                if (a->isChecked()) names << a->data().toString();
            // Deferred: setVisibleColumns() rebuilds this menu, which deletes the sender.
            QMetaObject::invokeMethod(
                this, [this, names] { setVisibleColumns(names); }, Qt::QueuedConnection);
        });
    }
}

void TimeSeriesPanel::rebuildGraphs() {
    plot_->clearGraphs();
    removeExtraLanes();
    graphLane_.clear();
    if (!loaded_) return;
    const Columns& cols = stream_->info().columns;
    std::vector<PlotLanes::Column> shown;
    for (int c : visible_) shown.push_back({cols[std::size_t(c)].name, cols[std::size_t(c)].unit});
    const PlotLanes::Assignment lanes = PlotLanes::assign(shown);
    for (int l = 1; l < lanes.count(); ++l) addLane(lanes.unit[std::size_t(l)]);
    for (std::size_t g = 0; g < visible_.size(); ++g) {
        const int c = visible_[g];
        const Column& column = cols[std::size_t(c)];
        const Lane& lane = lanes_[std::size_t(lanes.laneOf[g])];
        QCPGraph* graph = plot_->addGraph(lane.rect->axis(QCPAxis::atBottom), lane.rect->axis(QCPAxis::atLeft));
        graph->setName(PlotStyle::columnLabel(column.name, column.unit));
        graph->setPen(QPen(PlotStyle::seriesColor(c), 1.2));
        // We hand over at most ~2 points per pixel already; QCustomPlot's own sampling would
        // only cost time.
        graph->setAdaptiveSampling(false);
        if (lane.legend != plot_->legend) {
            graph->removeFromLegend(plot_->legend);
            graph->addToLegend(lane.legend);
        }
        graphLane_.push_back(lanes.laneOf[g]);
    }
    plot_->legend->setVisible(!visible_.empty());
    // A lane's one unit labels its axis; mixed units are in the legend only.
    plot_->yAxis->setLabel(lanes.count() > 0 ? PlotStyle::unitSuffix(lanes.unit.front()).trimmed() : QString());
    applyTimeAxis();
    PlotStyle::applyPalette(plot_, plot_->palette());
    emit lanesChanged();
}

void TimeSeriesPanel::setClockTime(bool on) {
    clockTime_ = on;
    if (clockBox_->isChecked() != on) clockBox_->setChecked(on);
    applyTimeAxis();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void TimeSeriesPanel::applyTimeAxis() {
    const bool clock = clockTime_ && t0_.has_value();
    // One ticker for every lane, so the grid lines line up; labelled once, under the bottom lane.
    const QSharedPointer<QCPAxisTicker> ticker = clock ? QSharedPointer<QCPAxisTicker>(new ClockTimeTicker(*t0_))
                                                       : QSharedPointer<QCPAxisTicker>(new QCPAxisTicker);
    const QString label = !clock ? tr("t [s]") : t0IsTimeOfDay_ ? tr("time of day") : tr("time of day (UTC)");
    for (std::size_t l = 0; l < lanes_.size(); ++l) {
        QCPAxis* x = lanes_[l].rect->axis(QCPAxis::atBottom);
        const bool bottom = l + 1 == lanes_.size();
        x->setTicker(ticker);
        x->setTickLabels(bottom);
        x->setLabel(bottom ? label : QString());
    }
}

void TimeSeriesPanel::addLane(const QString& unit) {
    auto* rect = new QCPAxisRect(plot_);
    plot_->plotLayout()->addElement(int(lanes_.size()), 0, rect);
    rect->setMarginGroup(QCP::msLeft | QCP::msRight, marginGroup_);
    for (QCPAxis* axis : rect->axes()) axis->grid()->setSubGridVisible(false);
    rect->axis(QCPAxis::atLeft)->setLabel(PlotStyle::unitSuffix(unit).trimmed());
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    x->setRange(plot_->xAxis->range());
    // Dragging or zooming any lane moves the main time axis, which the other lanes follow.
    connect(x, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this](const QCPRange& range) {
        if (!syncingX_) plot_->xAxis->setRange(range);
    });
    auto* legend = new QCPLegend;
    rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
    legend->setLayer(QStringLiteral("legend"));
    legend->setFont(plot_->legend->font());
    auto* cursor = new QCPItemStraightLine(plot_);
    cursor->setPen(cursorLine_->pen());
    cursor->setSelectable(false);
    cursor->setLayer(QStringLiteral("overlay"));
    cursor->setClipAxisRect(rect);
    for (QCPItemPosition* p : {cursor->point1, cursor->point2}) p->setAxes(x, rect->axis(QCPAxis::atLeft));
    cursor->point1->setCoords(cursorLine_->point1->coords());
    cursor->point2->setCoords(cursorLine_->point2->coords());
    cursor->setVisible(cursorLine_->visible());
    lanes_.push_back({rect, legend, cursor});
    applyRangeInteractions();
}

void TimeSeriesPanel::removeExtraLanes() {
    while (lanes_.size() > 1) {
        const Lane lane = lanes_.back();
        lanes_.pop_back();
        plot_->removeItem(lane.cursor);
        plot_->plotLayout()->remove(lane.rect);  // deletes the rect, its axes and its legend
    }
    plot_->plotLayout()->simplify();
    plot_->xAxis->setTickLabels(true);
    plot_->xAxis->setLabel(tr("t [s]"));
}

void TimeSeriesPanel::applyRangeInteractions() {
    // With auto-fit the y range belongs to the panel; without it the user may drag it too.
    const Qt::Orientations orientations = autoFitY_ ? Qt::Horizontal : Qt::Horizontal | Qt::Vertical;
    for (const Lane& lane : lanes_) {
        lane.rect->setRangeDrag(orientations);
        lane.rect->setRangeZoom(orientations);
    }
}

void TimeSeriesPanel::updateHeader() {
    QString text = title_;
    if (stream_ && !error_.isEmpty()) {
        text = tr("%1 — could not load: %2").arg(title_, error_);
        titleLabel_->setStyleSheet(QStringLiteral("color: #b00020;"));
    } else {
        titleLabel_->setStyleSheet({});
        if (stream_ && isLoading())
            text = tr("%1 — loading…").arg(title_);
        else if (stream_ && loaded_)
            text = tr("%1 — %2 samples").arg(title_, QLocale().toString(qlonglong(loaded_->data->rows())));
        else if (!stream_)
            text = tr("Select a stream in the project tree to plot it.");
    }
    titleLabel_->setText(text);
}

void TimeSeriesPanel::showFullRange() {
    if (!loaded_ || loaded_->data->rows() == 0) return;
    const StreamData& data = *loaded_->data;
    double t0 = data.t.front(), t1 = data.t.back();
    if (t1 <= t0) {
        t0 -= 0.5;
        t1 += 0.5;
    }
    plot_->xAxis->setRange(t0, t1);
    redecimate();  // also when the range did not change (no rangeChanged then)
    if (!autoFitY_) {
        std::vector<Extremes> all(lanes_.size());
        for (std::size_t g = 0; g < visible_.size() && g < graphLane_.size(); ++g) {
            Extremes& lane = all[std::size_t(graphLane_[g])];
            lane = Extremes::combine(lane, loaded_->pyramids[std::size_t(visible_[g])].rangeExtremes(0, data.rows()));
        }
        fitAllY(all);
    }
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

int TimeSeriesPanel::plotWidthPixels() const {
    const int width = plot_->axisRect()->width();
    // Before the first layout the axis rect has no size yet; guess from the widget.
    return width > 10 ? width : std::max(100, plot_->width() - 80);
}

void TimeSeriesPanel::redecimate() {
    if (!loaded_ || decimating_) return;
    decimating_ = true;
    const QCPRange range = plot_->xAxis->range();
    const int pixels = plotWidthPixels();
    decimatedWidth_ = pixels;
    std::vector<Extremes> visible(lanes_.size());
    for (int g = 0; g < plot_->graphCount() && g < int(visible_.size()); ++g) {
        const MinMaxPyramid& pyramid = loaded_->pyramids[std::size_t(visible_[std::size_t(g)])];
        const DecimatedSeries series = pyramid.decimate(range.lower, range.upper, pixels);
        QCPGraph* graph = plot_->graph(g);
        graph->setData(series.keys, series.values, true);
        const bool markers =
            series.raw && series.visibleSamples > 0 && pixels / double(series.visibleSamples) >= kMarkerSpacingPixels;
        graph->setScatterStyle(markers ? QCPScatterStyle(QCPScatterStyle::ssDisc, 4) : QCPScatterStyle());
        Extremes& lane = visible[std::size_t(graphLane_[std::size_t(g)])];
        lane = Extremes::combine(lane, series.visible);
    }
    if (autoFitY_) fitAllY(visible);
    decimating_ = false;
}

void TimeSeriesPanel::fitAllY(const std::vector<Extremes>& perLane) {
    for (std::size_t l = 0; l < perLane.size() && l < lanes_.size(); ++l)
        fitY(lanes_[l].rect->axis(QCPAxis::atLeft), perLane[l]);
}

void TimeSeriesPanel::fitY(QCPAxis* axis, const Extremes& extremes) {
    if (extremes.isEmpty() || !std::isfinite(extremes.min) || !std::isfinite(extremes.max)) return;
    double lo = extremes.min, hi = extremes.max;
    const double span = hi - lo;
    // A constant signal still gets a visible band around it.
    const double pad = span > 0 ? 0.05 * span : std::max(0.05 * std::abs(hi), 0.5);
    axis->setRange(lo - pad, hi + pad);
}

void TimeSeriesPanel::onXRangeChanged(const QCPRange& range) {
    syncingX_ = true;
    for (std::size_t l = 1; l < lanes_.size(); ++l) lanes_[l].rect->axis(QCPAxis::atBottom)->setRange(range);
    syncingX_ = false;
    redecimate();
    if (controller_ && !followingController_) controller_->setVisibleRange(range.lower, range.upper);
    if (controller_) readoutTimer_->start();
    // Drag and wheel replot on their own; programmatic changes need the request. Queued
    // replots coalesce, so asking twice costs nothing.
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void TimeSeriesPanel::onAfterLayout() {
    // A resize changes the number of pixel columns; the data drawn right after this signal
    // must match the new width.
    if (loaded_ && plot_->axisRect()->width() != decimatedWidth_) {
        redecimate();
        plot_->replot(QCustomPlot::rpQueuedReplot);
    }
}

long long TimeSeriesPanel::plottedPointCount() const {
    long long n = 0;
    for (int g = 0; g < plot_->graphCount(); ++g) n += plot_->graph(g)->dataCount();
    return n;
}

// --- time cursor ------------------------------------------------------------------------------

void TimeSeriesPanel::setTimeController(TimeController* controller) {
    if (controller_) disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    for (const Lane& lane : lanes_) lane.cursor->setVisible(controller_ != nullptr);
    readout_->setVisible(controller_ != nullptr && loaded_);
    if (!controller_) return;
    connect(controller_, &TimeController::cursorChanged, this, &TimeSeriesPanel::onCursorChanged);
    connect(controller_, &TimeController::visibleRangeChanged, this, &TimeSeriesPanel::onControllerRange);
    connect(controller_, &QObject::destroyed, this, [this] { controller_ = nullptr; });
    onCursorChanged(controller_->cursor());
}

void TimeSeriesPanel::onCursorChanged(double t) {
    for (const Lane& lane : lanes_) {
        lane.cursor->point1->setCoords(t, 0);
        lane.cursor->point2->setCoords(t, 1);
    }
    // Only the cursor line changes: the overlay layer repaints without redrawing the graphs.
    // Its paint buffer exists only after the first full replot.
    if (replotted_)
        plot_->layer(QStringLiteral("overlay"))->replot();
    else
        plot_->replot(QCustomPlot::rpQueuedReplot);
    updateReadout();
}

void TimeSeriesPanel::onControllerRange(double begin, double end) {
    const QCPRange current = plot_->xAxis->range();
    if (current.lower == begin && current.upper == end) return;
    followingController_ = true;
    plot_->xAxis->setRange(begin, end);
    followingController_ = false;
}

void TimeSeriesPanel::onPlotClicked(QMouseEvent* event) {
    // A click (not the end of a drag) puts the cursor there.
    if (!controller_ || event->button() != Qt::LeftButton || event->modifiers() != Qt::NoModifier) return;
    if ((event->pos() - pressPos_).manhattanLength() > 3) return;
    const bool inLane = std::any_of(lanes_.begin(), lanes_.end(),
                                    [&](const Lane& lane) { return lane.rect->rect().contains(event->pos()); });
    if (!inLane) return;
    controller_->setCursor(plot_->xAxis->pixelToCoord(event->pos().x()));
}

void TimeSeriesPanel::keyPressEvent(QKeyEvent* event) {
    if (controller_ && controller_->handleKey(event)) return;
    QWidget::keyPressEvent(event);
}

const StreamData* TimeSeriesPanel::data() const { return loaded_ ? loaded_->data.get() : nullptr; }

QString TimeSeriesPanel::readoutText() const { return readout_->text(); }

void TimeSeriesPanel::updateReadout() {
    readoutTimer_->stop();
    if (!controller_ || !loaded_ || visible_.empty()) {
        readout_->setVisible(false);
        return;
    }
    const StreamData& data = *loaded_->data;
    const QCPRange range = plot_->xAxis->range();
    const double t = controller_->cursor();
    const QLocale locale;
    auto number = [&](double v) { return std::isfinite(v) ? locale.toString(v, 'g', 5) : QStringLiteral("–"); };
    QString html = QStringLiteral(
                       "<table cellspacing=0 cellpadding=1><tr><th align=left>%1</th>"
                       "<th align=right>&nbsp;%2&nbsp;</th><th align=right>&nbsp;%3&nbsp;</th>"
                       "<th align=right>&nbsp;%4&nbsp;</th><th align=right>&nbsp;%5&nbsp;</th>"
                       "<th align=right>&nbsp;%6</th></tr>")
                       .arg(tr("t = %1 s").arg(number(t)), tr("at cursor"), tr("mean"), tr("SD"), tr("min"), tr("max"));
    const Columns& cols = stream_->info().columns;
    for (int c : visible_) {
        const Column& column = cols[std::size_t(c)];
        const RangeStatistics stats = RangeStatistics::compute(data, c, range.lower, range.upper);
        html +=
            QStringLiteral(
                "<tr><td><font color='%1'>&#9632;</font> %2</td><td align=right>%3</td>"
                "<td align=right>%4</td><td align=right>%5</td><td align=right>%6</td>"
                "<td align=right>%7</td></tr>")
                .arg(PlotStyle::seriesColor(c).name(), PlotStyle::columnLabel(column.name, column.unit).toHtmlEscaped(),
                     number(RangeStatistics::valueAt(data, c, t)),
                     stats.count ? number(stats.mean) : QStringLiteral("–"),
                     stats.count ? number(stats.sd) : QStringLiteral("–"),
                     stats.count ? number(stats.min) : QStringLiteral("–"),
                     stats.count ? number(stats.max) : QStringLiteral("–"));
    }
    html += QStringLiteral("</table>");
    readout_->setText(html);
    readout_->setVisible(true);
}

}  // namespace athlos::ui
