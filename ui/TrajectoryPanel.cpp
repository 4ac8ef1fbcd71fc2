#include "ui/TrajectoryPanel.h"

#include "core/model/Stream.h"
#include "ui/PlotStyle.h"
#include "ui/TimeController.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::ui {

TrajectoryPanel::TrajectoryPanel(QWidget* parent) : QWidget(parent) {
    titleLabel_ = new QLabel(this);
    titleLabel_->setTextFormat(Qt::PlainText);
    QFont bold = titleLabel_->font();
    bold.setBold(true);
    titleLabel_->setFont(bold);

    plot_ = new QCustomPlot(this);
    PlotStyle::apply(plot_);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->xAxis->setLabel(tr("x [m]"));
    plot_->yAxis->setLabel(tr("y [m]"));

    curve_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
    curve_->setPen(QPen(PlotStyle::seriesColor(0), 1.5));
    curve_->setName(tr("Path"));

    startMarker_ = plot_->addGraph();
    startMarker_->setLineStyle(QCPGraph::lsNone);
    startMarker_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(0, 130, 60), 2), QColor(0, 158, 115), 11));
    startMarker_->setName(tr("Start"));
    endMarker_ = plot_->addGraph();
    endMarker_->setLineStyle(QCPGraph::lsNone);
    endMarker_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssSquare, QPen(QColor(150, 30, 20), 2), QColor(213, 94, 0), 10));
    endMarker_->setName(tr("End"));
    // After the start and end markers: graph(0) and graph(1) stay what they were.
    cursorMarker_ = plot_->addGraph();
    cursorMarker_->setLineStyle(QCPGraph::lsNone);
    cursorMarker_->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssDisc, QPen(QColor(0xd5, 0x5e, 0x00), 2), QColor(0xd5, 0x5e, 0x00), 12));
    cursorMarker_->setName(tr("Cursor"));
    cursorMarker_->removeFromLegend();
    plot_->legend->setVisible(false);

    connect(plot_, &QCustomPlot::afterLayout, this, [this] {
        const QSize size = plot_->axisRect()->rect().size();
        if (size == lastAxisRectSize_) return;
        lastAxisRectSize_ = size;
        if (!hasData_) return;
        if (userFramed_)
            keepEqualScale();
        else
            showFullRange();
    });
    connect(plot_, &QCustomPlot::mousePress, this, [this] { userFramed_ = true; });
    connect(plot_, &QCustomPlot::mouseWheel, this, [this] { userFramed_ = true; });
    connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { showFullRange(); });

    auto* header = new QHBoxLayout;
    header->setContentsMargins(6, 4, 6, 0);
    header->addWidget(titleLabel_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(header);
    layout->addWidget(plot_, 1);

    updateHeader();
}

TrajectoryPanel::~TrajectoryPanel() = default;

bool TrajectoryPanel::isPositionStream(const StreamInfo& info) {
    static const QStringList kinds = {QStringLiteral("lps-position"), QStringLiteral("trajectory"),
                                      QStringLiteral("gnss")};
    return kinds.contains(info.kind) && info.columnIndex(QStringLiteral("x")) >= 0 &&
           info.columnIndex(QStringLiteral("y")) >= 0;
}

std::shared_ptr<TrajectoryPanel::Loaded> TrajectoryPanel::load(const std::shared_ptr<const Stream>& stream) {
    auto result = std::make_shared<Loaded>();
    const int cx = stream->info().columnIndex(QStringLiteral("x"));
    const int cy = stream->info().columnIndex(QStringLiteral("y"));
    if (cx < 0 || cy < 0) {
        result->error = tr("stream %1 has no x and y columns").arg(stream->name());
        return result;
    }
    auto data = stream->data();
    if (!data) {
        result->error = data.message();
        return result;
    }
    const StreamData& d = *data.value();
    const std::size_t n = d.rows();
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxCurvePoints - 1) / kMaxCurvePoints);
    const auto keep = [&](std::size_t i) {
        result->t.append(d.t[i]);
        result->x.append(d.at(i, cx));
        result->y.append(d.at(i, cy));
    };
    for (std::size_t i = 0; i < n; i += stride) keep(i);
    if (n > 0 && (n - 1) % stride != 0) keep(n - 1);  // the end marker must sit on the last sample
    return result;
}

void TrajectoryPanel::setStream(std::shared_ptr<const Stream> stream, const QString& title) {
    clear();
    if (!stream) return;
    stream_ = std::move(stream);
    title_ = title.isEmpty() ? stream_->name() : title;
    const StreamInfo& info = stream_->info();
    const Column& xc = info.columns.at(std::size_t(std::max(0, info.columnIndex(QStringLiteral("x")))));
    const Column& yc = info.columns.at(std::size_t(std::max(0, info.columnIndex(QStringLiteral("y")))));
    plot_->xAxis->setLabel(PlotStyle::columnLabel(xc.name, xc.unit));
    plot_->yAxis->setLabel(PlotStyle::columnLabel(yc.name, yc.unit));
    loader_.start<std::shared_ptr<Loaded>>([stream = stream_] { return load(stream); },
                                           [this](std::shared_ptr<Loaded> result) { applyLoaded(std::move(result)); });
    updateHeader();
}

void TrajectoryPanel::clear() {
    loader_.cancel();  // the result of a load still running is dropped when it arrives
    stream_.reset();
    title_.clear();
    error_.clear();
    note_.clear();
    hasData_ = false;
    userFramed_ = false;
    curve_->data()->clear();
    startMarker_->data()->clear();
    endMarker_->data()->clear();
    cursorMarker_->data()->clear();
    plot_->legend->setVisible(false);
    plot_->xAxis->setLabel(tr("x [m]"));
    plot_->yAxis->setLabel(tr("y [m]"));
    updateHeader();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void TrajectoryPanel::setNote(const QString& note) {
    note_ = note;
    updateHeader();
}

bool TrajectoryPanel::isLoading() const { return loader_.isLoading(); }

void TrajectoryPanel::waitForLoad() { loader_.waitForLoad(); }

void TrajectoryPanel::applyLoaded(std::shared_ptr<Loaded> result) {
    if (!result->error.isEmpty()) {
        error_ = result->error;
        updateHeader();
        emit loadFailed(error_);
        return;
    }
    // QCPCurve orders by its parameter t, so the path is drawn in time order.
    curve_->setData(result->t, result->x, result->y, true);
    minX_ = minY_ = std::numeric_limits<double>::infinity();
    maxX_ = maxY_ = -std::numeric_limits<double>::infinity();
    for (qsizetype i = 0; i < result->x.size(); ++i) {
        if (!std::isfinite(result->x[i]) || !std::isfinite(result->y[i])) continue;
        minX_ = std::min(minX_, result->x[i]);
        maxX_ = std::max(maxX_, result->x[i]);
        minY_ = std::min(minY_, result->y[i]);
        maxY_ = std::max(maxY_, result->y[i]);
    }
    hasData_ = minX_ <= maxX_;
    if (!result->x.isEmpty()) {
        updateCursorMarker();
        startMarker_->setData({result->x.front()}, {result->y.front()});
        endMarker_->setData({result->x.back()}, {result->y.back()});
    }
    plot_->legend->setVisible(hasData_);
    updateHeader();
    showFullRange();
    emit loaded();
}

void TrajectoryPanel::showFullRange() {
    userFramed_ = false;
    if (!hasData_) return;
    const QRect rect = plot_->axisRect()->rect();
    // Before the first layout the axis rect is empty; a rough guess is refined on afterLayout.
    const double w = rect.width() > 10 ? rect.width() : std::max(100, plot_->width() - 80);
    const double h = rect.height() > 10 ? rect.height() : std::max(100, plot_->height() - 60);
    const double spanX = std::max(maxX_ - minX_, 1e-6);
    const double spanY = std::max(maxY_ - minY_, 1e-6);
    const double unitsPerPixel = 1.08 * std::max(spanX / w, spanY / h);  // 4 % margin per side
    const double cx = 0.5 * (minX_ + maxX_), cy = 0.5 * (minY_ + maxY_);
    plot_->xAxis->setRange(cx, unitsPerPixel * w, Qt::AlignCenter);
    plot_->yAxis->setRange(cy, unitsPerPixel * h, Qt::AlignCenter);
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

void TrajectoryPanel::keepEqualScale() {
    plot_->yAxis->setScaleRatio(plot_->xAxis, 1.0);
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

int TrajectoryPanel::pointCount() const { return curve_->dataCount(); }

void TrajectoryPanel::updateHeader() {
    if (stream_ && !error_.isEmpty()) {
        titleLabel_->setStyleSheet(QStringLiteral("color: #b00020;"));
        titleLabel_->setText(tr("%1 — could not load: %2").arg(title_, error_));
        return;
    }
    titleLabel_->setStyleSheet({});
    if (!stream_)
        titleLabel_->setText(note_.isEmpty() ? tr("Select a position stream to show its path.") : note_);
    else if (isLoading())
        titleLabel_->setText(tr("%1 — loading…").arg(title_));
    else
        titleLabel_->setText(tr("%1 — %2 samples").arg(title_, QLocale().toString(qlonglong(stream_->info().rows))));
}

void TrajectoryPanel::setTimeController(TimeController* controller) {
    if (controller_) disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    if (!controller_) return;
    connect(controller_, &TimeController::cursorChanged, this, &TrajectoryPanel::updateCursorMarker);
    connect(controller_, &QObject::destroyed, this, [this] { controller_ = nullptr; });
    updateCursorMarker();
}

QPointF TrajectoryPanel::cursorPosition() const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!controller_ || curve_->data()->isEmpty()) return {nan, nan};
    const double t = controller_->cursor();
    const auto data = curve_->data();
    // The curve's sort key is the sample time.
    auto upper = data->findBegin(t, false);
    if (upper == data->constEnd() || t < data->constBegin()->t || t > (data->constEnd() - 1)->t) return {nan, nan};
    if (upper->t == t || upper == data->constBegin()) return {upper->key, upper->value};
    auto lower = upper - 1;
    const double f = (t - lower->t) / (upper->t - lower->t);
    return {lower->key + f * (upper->key - lower->key), lower->value + f * (upper->value - lower->value)};
}

void TrajectoryPanel::updateCursorMarker() {
    const QPointF p = cursorPosition();
    if (std::isnan(p.x()))
        cursorMarker_->data()->clear();
    else
        cursorMarker_->setData({p.x()}, {p.y()});
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace athlos::ui
