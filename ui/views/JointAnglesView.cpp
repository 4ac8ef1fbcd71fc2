#include "ui/views/JointAnglesView.h"

#include "core/math/Angles.h"
#include "core/model/Project.h"
#include "ui/PlotStyle.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos::ui {

namespace {

constexpr std::size_t kMaxPoints = 200000;  // per graph; thinned by a stride beyond
const char* const kColumns[3] = {"flexion", "abduction", "rotation"};

bool isJointAngles(const Stream& s) {
    if (s.kind() != QLatin1String("joint-angles")) return false;
    for (const char* c : kColumns)
        if (s.info().columnIndex(QLatin1String(c)) < 0) return false;
    return true;
}

bool isReference(const Stream& s) { return s.info().attributes.value(QStringLiteral("reference")).toBool(); }

struct Angles {
    std::vector<double> t;
    std::array<std::vector<double>, 3> deg;
};

Angles readAngles(const Stream& stream) {
    Angles out;
    auto data = stream.data();
    if (!data) return out;
    const StreamData& d = **data;
    out.t = d.t;
    for (int i = 0; i < 3; ++i) {
        const int c = stream.info().columnIndex(QLatin1String(kColumns[i]));
        out.deg[i].resize(d.rows());
        for (std::size_t k = 0; k < d.rows(); ++k) out.deg[i][k] = d.at(k, c) / math::kDeg;
    }
    return out;
}

// Linear interpolation of v(t) at x; NaN outside [t.front(), t.back()].
double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
    if (t.empty() || x < t.front() || x > t.back()) return std::numeric_limits<double>::quiet_NaN();
    const auto it = std::lower_bound(t.begin(), t.end(), x);
    const std::size_t j = std::size_t(it - t.begin());
    if (*it == x || j == 0) return v[j];
    const double f = (x - t[j - 1]) / (t[j] - t[j - 1]);
    return v[j - 1] + f * (v[j] - v[j - 1]);
}

QVector<double> thinned(const std::vector<double>& v, std::size_t stride) {
    QVector<double> out;
    out.reserve(int(v.size() / stride + 1));
    for (std::size_t k = 0; k < v.size(); k += stride) out.append(v[k]);
    return out;
}

}  // namespace

JointAnglesView::JointAnglesView(const Project* project, QWidget* parent) : QWidget(parent), project_(project) {
    streamCombo_ = new QComboBox(this);
    streamCombo_->setObjectName(QStringLiteral("streamCombo"));
    if (project_) streamCombo_->addItems(jointAngleStreams(*project_));
    readout_ = new QLabel(this);
    readout_->setObjectName(QStringLiteral("readout"));
    readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    note_ = new QLabel(this);
    note_->setWordWrap(true);

    const QStringList titles{tr("flexion [°]"), tr("abduction [°]"), tr("internal rotation [°]")};
    auto* layout = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Stream:"), this));
    controls->addWidget(streamCombo_, 1);
    otherSideBox_ = new QCheckBox(tr("Other side"), this);
    otherSideBox_->setObjectName(QStringLiteral("otherSideBox"));
    otherSideBox_->setToolTip(tr("Overlay the same joint of the other side (left/right comparison)"));
    otherSideBox_->setChecked(true);
    controls->addWidget(otherSideBox_);
    layout->addLayout(controls);
    for (int i = 0; i < 3; ++i) {
        auto* plot = new QCustomPlot(this);
        plot->setObjectName(QStringLiteral("%1Plot").arg(QLatin1String(kColumns[i])));
        PlotStyle::apply(plot);
        plot->legend->setVisible(true);
        plot->yAxis->setLabel(titles[i]);
        plot->xAxis->setLabel(i == 2 ? tr("t [s]") : QString());
        plot->setMinimumHeight(110);
        plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        plot->axisRect()->setRangeZoom(Qt::Horizontal);
        plot->axisRect()->setRangeDrag(Qt::Horizontal);
        auto* cursor = new QCPItemStraightLine(plot);
        cursor->setPen(QPen(QColor(0xd5, 0x5e, 0x00), 1.5));
        cursor->setSelectable(false);
        cursor->setVisible(false);
        plots_[std::size_t(i)] = plot;
        cursors_[std::size_t(i)] = cursor;
        layout->addWidget(plot, 1);
        connect(plot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this, i] { onPlotRange(i); });
        connect(plot, &QCustomPlot::mousePress, this, [this](QMouseEvent* event) { pressPos_ = event->pos(); });
        connect(plot, &QCustomPlot::mouseRelease, this, [this, i](QMouseEvent* event) { onPlotReleased(i, event); });
    }
    layout->addWidget(readout_);
    layout->addWidget(note_);
    connect(streamCombo_, &QComboBox::currentTextChanged, this, &JointAnglesView::refresh);
    connect(otherSideBox_, &QCheckBox::toggled, this, &JointAnglesView::refresh);
    refresh();
}

QStringList JointAnglesView::jointAngleStreams(const Project& project) {
    QStringList list;
    for (const QString& path : project.streamPaths()) {
        const Stream* s = project.stream(path);
        if (isJointAngles(*s) && !isReference(*s)) list << path;
    }
    return list;
}

QString JointAnglesView::referenceFor(const Project& project, const QString& path) {
    const Stream* stream = project.stream(path);
    const ItemPath item = ItemPath::parse(path);
    const Recording* recording = project.recording(item.recording);
    if (!stream || !recording) return {};
    const QJsonObject& a = stream->info().attributes;
    for (const auto& [name, candidate] : recording->streams) {
        const QJsonObject& b = candidate.info().attributes;
        if (isJointAngles(candidate) && isReference(candidate) &&
            b.value(QStringLiteral("joint")) == a.value(QStringLiteral("joint")) &&
            b.value(QStringLiteral("side")) == a.value(QStringLiteral("side")))
            return item.recording + QLatin1Char('/') + name;
    }
    return {};
}

QString JointAnglesView::otherSideFor(const Project& project, const QString& path) {
    const Stream* stream = project.stream(path);
    const ItemPath item = ItemPath::parse(path);
    const Recording* recording = project.recording(item.recording);
    if (!stream || !recording) return {};
    const QJsonObject& a = stream->info().attributes;
    const QString side = a.value(QStringLiteral("side")).toString();
    const QString other = side == QLatin1String("left")    ? QStringLiteral("right")
                          : side == QLatin1String("right") ? QStringLiteral("left")
                                                           : QString();
    if (other.isEmpty()) return {};
    for (const auto& [name, candidate] : recording->streams) {
        const QJsonObject& b = candidate.info().attributes;
        if (isJointAngles(candidate) && !isReference(candidate) &&
            b.value(QStringLiteral("joint")) == a.value(QStringLiteral("joint")) &&
            b.value(QStringLiteral("side")).toString() == other)
            return item.recording + QLatin1Char('/') + name;
    }
    return {};
}

void JointAnglesView::setOtherSideShown(bool shown) { otherSideBox_->setChecked(shown); }

Status JointAnglesView::setStream(const QString& path) {
    if (streamCombo_->findText(path) < 0)
        return makeError(tr("'%1' is not a joint-angles stream (flexion, abduction, rotation)").arg(path));
    streamCombo_->setCurrentText(path);
    return {};
}

QString JointAnglesView::stream() const { return streamCombo_->currentText(); }

void JointAnglesView::setTimeController(TimeController* controller) {
    if (controller_) disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    for (auto* cursor : cursors_) cursor->setVisible(controller_ != nullptr);
    if (!controller_) return;
    connect(controller_, &TimeController::cursorChanged, this, &JointAnglesView::onCursorChanged);
    connect(controller_, &TimeController::visibleRangeChanged, this, &JointAnglesView::onRangeChanged);
    connect(controller_, &QObject::destroyed, this, [this] { controller_ = nullptr; });
    onRangeChanged(controller_->visibleBegin(), controller_->visibleEnd());
    onCursorChanged(controller_->cursor());
}

std::array<double, 3> JointAnglesView::valuesAt(double t) const {
    return {interpolate(t_, deg_[0], t), interpolate(t_, deg_[1], t), interpolate(t_, deg_[2], t)};
}

QString JointAnglesView::readoutText() const { return readout_->text(); }

void JointAnglesView::refresh() {
    rmse_.clear();
    reference_.clear();
    otherSide_.clear();
    t_.clear();
    for (auto& d : deg_) d.clear();
    for (QCustomPlot* plot : plots_) plot->clearGraphs();
    note_->clear();
    const Stream* stream = project_ ? project_->stream(streamCombo_->currentText()) : nullptr;
    if (stream) {
        Angles est = readAngles(*stream);
        t_ = est.t;
        deg_ = est.deg;
        const std::size_t stride = t_.size() / kMaxPoints + 1;
        const QVector<double> t = thinned(t_, stride);
        reference_ = referenceFor(*project_, streamCombo_->currentText());
        Angles ref;
        if (const Stream* r = reference_.isEmpty() ? nullptr : project_->stream(reference_)) ref = readAngles(*r);
        const QJsonObject a = stream->info().attributes;
        const QString label =
            tr("%1 %2").arg(a.value(QStringLiteral("side")).toString(), a.value(QStringLiteral("joint")).toString());
        for (int i = 0; i < 3; ++i) {
            QCustomPlot* plot = plots_[std::size_t(i)];
            QCPGraph* graph = plot->addGraph();
            graph->setName(label.trimmed().isEmpty() ? tr("estimate") : label.trimmed());
            graph->setPen(QPen(PlotStyle::seriesColor(0), 1.4));
            graph->setData(t, thinned(deg_[std::size_t(i)], stride), true);
            if (ref.t.empty()) continue;
            // RMSE at the estimate's samples, reference interpolated; samples outside it are skipped.
            double sum = 0.0;
            long long n = 0;
            for (std::size_t k = 0; k < t_.size(); ++k) {
                const double r = interpolate(ref.t, ref.deg[std::size_t(i)], t_[k]);
                const double e = deg_[std::size_t(i)][k];
                if (!std::isfinite(r) || !std::isfinite(e)) continue;
                sum += (e - r) * (e - r);
                ++n;
            }
            rmse_.push_back(n > 0 ? std::sqrt(sum / double(n)) : std::numeric_limits<double>::quiet_NaN());
            const std::size_t rs = ref.t.size() / kMaxPoints + 1;
            QCPGraph* refGraph = plot->addGraph();
            refGraph->setName(tr("reference (RMSE %1°)").arg(rmse_.back(), 0, 'f', 2));
            QPen pen(PlotStyle::seriesColor(1), 1.2, Qt::DashLine);
            refGraph->setPen(pen);
            refGraph->setData(thinned(ref.t, rs), thinned(ref.deg[std::size_t(i)], rs), true);
        }
        if (otherSideBox_->isChecked()) otherSide_ = otherSideFor(*project_, streamCombo_->currentText());
        if (const Stream* o = otherSide_.isEmpty() ? nullptr : project_->stream(otherSide_)) {
            const Angles other = readAngles(*o);
            const QJsonObject b = o->info().attributes;
            const std::size_t os = other.t.size() / kMaxPoints + 1;
            for (int i = 0; i < 3; ++i) {
                QCPGraph* graph = plots_[std::size_t(i)]->addGraph();
                graph->setName(tr("%1 %2").arg(b.value(QStringLiteral("side")).toString(),
                                               b.value(QStringLiteral("joint")).toString()));
                graph->setPen(QPen(PlotStyle::seriesColor(2), 1.2));
                graph->setData(thinned(other.t, os), thinned(other.deg[std::size_t(i)], os), true);
            }
        }
        note_->setText(reference_.isEmpty() ? tr("No reference angles for this joint in the recording.")
                                            : tr("Reference: %1").arg(reference_));
    } else {
        note_->setText(tr("No joint-angles stream in this project; run joint-angles first."));
    }
    for (QCustomPlot* plot : plots_) {
        plot->rescaleAxes();
        plot->yAxis->scaleRange(1.1);
    }
    if (controller_) onRangeChanged(controller_->visibleBegin(), controller_->visibleEnd());
    for (QCustomPlot* plot : plots_) plot->replot();
    if (controller_) onCursorChanged(controller_->cursor());
}

void JointAnglesView::onCursorChanged(double t) {
    for (std::size_t i = 0; i < 3; ++i) {
        cursors_[i]->point1->setCoords(t, 0);
        cursors_[i]->point2->setCoords(t, 1);
        plots_[i]->replot(QCustomPlot::rpQueuedReplot);
    }
    const std::array<double, 3> v = valuesAt(t);
    const auto number = [](double x) { return std::isfinite(x) ? QString::number(x, 'f', 1) : QStringLiteral("–"); };
    readout_->setText(tr("t = %1 s: flexion %2°, abduction %3°, rotation %4°")
                          .arg(QString::number(t, 'f', 2), number(v[0]), number(v[1]), number(v[2])));
}

void JointAnglesView::onRangeChanged(double begin, double end) {
    if (!(end > begin)) return;
    syncing_ = true;
    for (QCustomPlot* plot : plots_) {
        plot->xAxis->setRange(begin, end);
        plot->replot(QCustomPlot::rpQueuedReplot);
    }
    syncing_ = false;
}

void JointAnglesView::onPlotRange(int angle) {
    // A drag or wheel zoom in one plot moves the window's visible range; every panel follows.
    if (syncing_) return;
    const QCPRange r = plots_[std::size_t(angle)]->xAxis->range();
    if (controller_) {
        controller_->setVisibleRange(r.lower, r.upper);
    } else {
        syncing_ = true;
        for (QCustomPlot* plot : plots_)
            if (plot != plots_[std::size_t(angle)]) {
                plot->xAxis->setRange(r);
                plot->replot(QCustomPlot::rpQueuedReplot);
            }
        syncing_ = false;
    }
}

void JointAnglesView::onPlotReleased(int angle, QMouseEvent* event) {
    // A click (not the end of a drag) puts the cursor there.
    QCustomPlot* plot = plots_[std::size_t(angle)];
    if (!controller_ || event->button() != Qt::LeftButton || (event->pos() - pressPos_).manhattanLength() > 3) return;
    if (!plot->axisRect()->rect().contains(event->pos())) return;
    controller_->setCursor(plot->xAxis->pixelToCoord(event->pos().x()));
}

namespace {

QString trView(const char* text) { return QCoreApplication::translate("athlos::ui::JointAnglesView", text); }

QDockWidget* makeDock(const Project* project, TimeController* time, const QString& stream, QWidget* parent) {
    auto* dock = new QDockWidget(trView("Joint angles"), parent);
    dock->setObjectName(QStringLiteral("jointAnglesDock"));
    auto* view = new JointAnglesView(project, dock);
    if (!stream.isEmpty()) (void)view->setStream(stream);  // a name from jointAngleStreams(): cannot fail
    view->setTimeController(time);
    dock->setWidget(view);
    dock->setAttribute(Qt::WA_DeleteOnClose);
    return dock;
}

void launchJointAngles(Workspace& workspace) {
    if (!workspace.project()) return;
    QDockWidget* dock = makeDock(workspace.project(), workspace.timeController(), QString(), workspace.window());
    // The view reads the project it was opened on: close it when the main window swaps projects.
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, &QWidget::close);
    workspace.addDock(dock, Qt::RightDockWidgetArea);
}

Status prepareJointAnglesView(Workspace& workspace) {
    Project* project = workspace.project();
    QStringList streams = project ? JointAnglesView::jointAngleStreams(*project) : QStringList();
    // The knee first: it is the joint the demo and the validation are about.
    std::stable_partition(streams.begin(), streams.end(), [project](const QString& path) {
        return project->stream(path)->info().attributes.value(QStringLiteral("joint")).toString() ==
               QLatin1String("knee");
    });
    if (streams.isEmpty())
        return makeError(
            trView("no joint-angles stream (kind joint-angles with flexion, abduction, rotation) in this project; "
                   "run joint-angles first"));
    // The stream in the main time series too, so the shared cursor and range are visible in both.
    workspace.selectItem(streams.front());
    workspace.showTimeSeriesView();
    workspace.waitForPlots();
    TimeController* time = workspace.timeController();
    QDockWidget* dock = makeDock(project, time, streams.front(), workspace.window());
    workspace.addDock(dock, Qt::RightDockWidgetArea);
    workspace.resizeDock(dock, workspace.window()->width() * 11 / 20, Qt::Horizontal);
    // Show the last third (squats in the simulated demo) with the cursor in its middle.
    const double b = time->begin(), e = time->end();
    time->setVisibleRange(b + 0.55 * (e - b), e);
    time->setCursor(b + 0.8 * (e - b));
    QCoreApplication::processEvents();
    workspace.waitForPlots();
    if (auto* view = dock->findChild<JointAnglesView*>())
        for (int i = 0; i < 3; ++i) view->plot(i)->replot();
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("joint-angles-view"), QT_TRANSLATE_NOOP("Tools", "Joint angles…"),
                      QT_TRANSLATE_NOOP("Tools", "Inertial"), launchJointAngles});
ATHLOS_REGISTER_VIEW({QStringLiteral("joint-angles"), prepareJointAnglesView});

}  // namespace athlos::ui
