#include "ui/views/TrackTrajectoryView.h"

#include "core/model/Project.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/venue/EqualAspectFrame.h"
#include "ui/venue/TrackOverlay.h"

#include <QCoreApplication>
#include <QLabel>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <cmath>

namespace athlos::ui {

namespace {

constexpr int kMaxDots = 50000;  // thinned by a stride beyond this: dots overlap long before
constexpr int kSpeedBins = 8;
constexpr int kMaxSpeedRuns = 2000;  // a noisy speed would make thousands of tiny curves; draw one colour then

struct Xy {
    QVector<double> t, x, y;
};

Xy readXy(const Stream& stream, int maxPoints = 0) {
    Xy out;
    const int cx = stream.info().columnIndex(QStringLiteral("x")), cy = stream.info().columnIndex(QStringLiteral("y"));
    auto data = stream.data();
    if (cx < 0 || cy < 0 || !data) return out;
    const StreamData& d = **data;
    const std::size_t stride = maxPoints > 0 ? std::max<std::size_t>(1, d.rows() / std::size_t(maxPoints) + 1) : 1;
    for (std::size_t k = 0; k < d.rows(); k += stride) {
        if (!std::isfinite(d.at(k, cx)) || !std::isfinite(d.at(k, cy))) continue;
        out.t.append(d.t[k]);
        out.x.append(d.at(k, cx));
        out.y.append(d.at(k, cy));
    }
    return out;
}

QCPCurve* makeDots(QCustomPlot* plot, const QColor& color, double size, const QString& name) {
    auto* curve = new QCPCurve(plot->xAxis, plot->yAxis);
    curve->setLineStyle(QCPCurve::lsNone);
    curve->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, color, color, size));
    curve->setName(name);
    return curve;
}

}  // namespace

TrackTrajectoryView::TrackTrajectoryView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    plot_ = new QCustomPlot(this);
    PlotStyle::apply(plot_);
    plot_->xAxis->setLabel(tr("x [m]"));
    plot_->yAxis->setLabel(tr("y [m]"));
    plot_->legend->setVisible(true);
    summaryLabel_ = new QLabel(this);
    summaryLabel_->setWordWrap(true);
    layout->addWidget(plot_, 1);
    layout->addWidget(summaryLabel_);
    overlay_ = std::make_unique<TrackOverlay>(plot_);
    aspect_ = new EqualAspectFrame(plot_);

    raw_ = makeDots(plot_, QColor(160, 160, 160), 3, tr("Raw positions"));
    trajectory_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
    trajectory_->setPen(QPen(QColor(40, 40, 40), 1.0));
    trajectory_->setName(tr("Filtered trajectory"));
    outliers_ = makeDots(plot_, QColor(213, 0, 0), 5, tr("Outliers"));
    // Rejected fixes stay visible above the speed-coloured segments added later.
    plot_->addLayer(QStringLiteral("outliers"), plot_->layer(QStringLiteral("main")), QCustomPlot::limAbove);
    outliers_->setLayer(QStringLiteral("outliers"));

    colorScale_ = new QCPColorScale(plot_);
    colorScale_->setType(QCPAxis::atRight);
    colorScale_->setGradient(QCPColorGradient(QCPColorGradient::gpJet));
    colorScale_->axis()->setLabel(tr("speed [m/s]"));
    colorScale_->setVisible(false);
    plot_->plotLayout()->addElement(0, 1, colorScale_);
}

TrackTrajectoryView::~TrackTrajectoryView() = default;

QString TrackTrajectoryView::findResult(const Project& project) {
    for (const QString& path : project.streamPaths()) {
        const Stream* stream = project.stream(path);
        if (stream && stream->info().provenance.processorId == QLatin1String("position-filter") &&
            stream->kind() == QLatin1String("trajectory"))
            return path;
    }
    return {};
}

TrackGeometry TrackTrajectoryView::trackOf(const Project& project, const QString& trajectoryPath) {
    const Stream* stream = project.stream(trajectoryPath);
    const QJsonObject params = stream ? stream->info().provenance.parameters : QJsonObject();
    auto track = TrackGeometry::resolve(project.geometry(),
                                        params.value(QStringLiteral("track")).toString(QStringLiteral("iaaf-400m")));
    TrackGeometry geometry = track ? *track : TrackGeometry::iaaf400m();
    TrackPose pose = geometry.pose();
    pose.x = params.value(QStringLiteral("track_x")).toDouble(pose.x);
    pose.y = params.value(QStringLiteral("track_y")).toDouble(pose.y);
    pose.rotation = params.value(QStringLiteral("track_rotation")).toDouble(pose.rotation);
    geometry.setPose(pose);
    return geometry;
}

Status TrackTrajectoryView::setResult(const Project& project, const QString& trajectoryPath) {
    const Stream* stream = project.stream(trajectoryPath);
    if (!stream) return makeError(tr("'%1' is not a stream of this project").arg(trajectoryPath));
    const Xy filtered = readXy(*stream);
    if (filtered.t.isEmpty()) return makeError(tr("'%1' has no x/y samples").arg(trajectoryPath));

    overlay_->setTrack(trackOf(project, trajectoryPath));

    // Raw fixes and rejected fixes come from the filter's input and its "-outliers" stream, whose
    // rows are the input's valid fixes in order (matched by time stamp).
    Xy raw;
    const auto& inputs = stream->info().provenance.inputs;
    const Stream* input = inputs.empty() ? nullptr : project.stream(inputs.front().name);
    if (input) raw = readXy(*input);
    QVector<double> ox, oy;
    if (const Stream* flags = project.stream(trajectoryPath + QStringLiteral("-outliers")); flags && !raw.t.isEmpty()) {
        const int c = flags->info().columnIndex(QStringLiteral("outlier"));
        auto data = flags->data();
        if (c >= 0 && data) {
            const StreamData& d = **data;
            for (std::size_t k = 0; k < d.rows(); ++k) {
                if (d.at(k, c) < 0.5) continue;
                const auto it = std::lower_bound(raw.t.cbegin(), raw.t.cend(), d.t[k]);
                if (it == raw.t.cend() || *it != d.t[k]) continue;
                const auto i = it - raw.t.cbegin();
                ox.append(raw.x[i]);
                oy.append(raw.y[i]);
            }
        }
    }
    if (raw.t.size() > kMaxDots) {
        Xy thin;
        const int stride = int(raw.t.size()) / kMaxDots + 1;
        for (int i = 0; i < raw.t.size(); i += stride) {
            thin.x.append(raw.x[i]);
            thin.y.append(raw.y[i]);
        }
        raw = thin;
    }
    raw_->setData(raw.x, raw.y);
    outliers_->setData(ox, oy);
    trajectory_->setData(filtered.x, filtered.y);

    QVector<double> speed;
    if (const int cs = stream->info().columnIndex(QStringLiteral("speed")); cs >= 0) {
        auto data = stream->data();
        const StreamData& d = **data;
        for (std::size_t k = 0; k < d.rows(); ++k)
            if (std::isfinite(d.at(k, 0)) && std::isfinite(d.at(k, 1))) speed.append(d.at(k, cs));
    }
    clearSpeedRuns();
    if (speed.size() == filtered.x.size()) addSpeedRuns(filtered.x, filtered.y, speed);

    summary_ = tr("%1: %2 filtered samples, %3 raw fixes, %4 rejected as outliers")
                   .arg(trajectoryPath)
                   .arg(filtered.t.size())
                   .arg(input ? QString::number(readXy(*input).t.size()) : tr("unknown"))
                   .arg(ox.size());
    summaryLabel_->setText(summary_);
    showFullRange();
    return {};
}

QString TrackTrajectoryView::summary() const { return summary_; }

void TrackTrajectoryView::clearSpeedRuns() {
    for (QCPCurve* curve : std::as_const(speedRuns_)) plot_->removePlottable(curve);
    speedRuns_.clear();
    colorScale_->setVisible(false);
}

void TrackTrajectoryView::addSpeedRuns(const QVector<double>& x, const QVector<double>& y,
                                       const QVector<double>& speed) {
    const auto [lo, hi] = std::minmax_element(speed.cbegin(), speed.cend());
    const double vMin = *lo, vMax = std::max(*hi, *lo + 1e-6);
    auto bin = [&](double v) { return std::clamp(int((v - vMin) / (vMax - vMin) * kSpeedBins), 0, kSpeedBins - 1); };
    // Runs of equal speed bin share one curve; neighbouring runs share their boundary point so the
    // line stays continuous.
    QList<std::pair<int, int>> runs;  // [begin, end] inclusive
    int begin = 0;
    for (int i = 1; i <= x.size(); ++i) {
        if (i == x.size() || bin(speed[i]) != bin(speed[begin])) {
            runs.append({begin, std::min(i, int(x.size()) - 1)});
            begin = i;
        }
    }
    if (runs.size() > kMaxSpeedRuns) return;
    QCPColorGradient gradient(QCPColorGradient::gpJet);  // color() is non-const (lookup table cache)
    for (const auto& [b, e] : runs) {
        auto* curve = new QCPCurve(plot_->xAxis, plot_->yAxis);
        curve->setData(x.mid(b, e - b + 1), y.mid(b, e - b + 1));
        const double mid = vMin + (bin(speed[b]) + 0.5) * (vMax - vMin) / kSpeedBins;
        curve->setPen(QPen(QColor::fromRgb(gradient.color(mid, QCPRange(vMin, vMax))), 2.5));
        curve->removeFromLegend();
        speedRuns_.append(curve);
    }
    colorScale_->setDataRange(QCPRange(vMin, vMax));
    colorScale_->setVisible(true);
}

void TrackTrajectoryView::showFullRange() { aspect_->frameAll(); }

namespace {

// Screenshot view "track": the first position-filter result on its track, shown as a tab next to
// the main window's panels.
Status prepareTrackView(Workspace& workspace) {
    Project* project = workspace.project();
    const QString path = project ? TrackTrajectoryView::findResult(*project) : QString();
    if (path.isEmpty())
        return makeError(QCoreApplication::translate("athlos::ui::TrackTrajectoryView",
                                                     "no position-filter result (kind trajectory) in this project; "
                                                     "run position-filter first"));
    auto* view = new TrackTrajectoryView;
    if (Status status = view->setResult(*project, path); !status) {
        delete view;
        return status;
    }
    workspace.addView(view, QCoreApplication::translate("athlos::ui::TrackTrajectoryView", "Track"));
    QCoreApplication::processEvents();
    view->showFullRange();
    return {};
}

}  // namespace

ATHLOS_REGISTER_VIEW({QStringLiteral("track"), prepareTrackView});

}  // namespace athlos::ui
