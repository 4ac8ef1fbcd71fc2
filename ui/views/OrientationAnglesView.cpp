#include "ui/views/OrientationAnglesView.h"

#include "core/math/Angles.h"
#include "core/math/EulerAngles.h"
#include "core/model/Project.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos::ui {

namespace {

constexpr std::size_t kMaxPoints = 200000;  // per graph; thinned by a stride beyond

struct Quats {
    std::vector<double> t;
    std::vector<math::Quat> q;
};

bool hasQuaternion(const StreamInfo& info) {
    for (const char* c : {"qw", "qx", "qy", "qz"})
        if (info.columnIndex(QLatin1String(c)) < 0) return false;
    return true;
}

Quats readQuats(const Stream& stream) {
    Quats out;
    const StreamInfo& info = stream.info();
    const int w = info.columnIndex(QStringLiteral("qw")), x = info.columnIndex(QStringLiteral("qx")),
              y = info.columnIndex(QStringLiteral("qy")), z = info.columnIndex(QStringLiteral("qz"));
    auto data = stream.data();
    if (!data || w < 0) return out;
    const StreamData& d = **data;
    out.t = d.t;
    out.q.reserve(d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k)
        out.q.push_back(math::Quat(d.at(k, w), d.at(k, x), d.at(k, y), d.at(k, z)));
    return out;
}

// The reference at the estimate's time stamps: SLERP between neighbours; outside its span or across
// a non-finite sample (optical dropout) NaN, which the RMS skips.
std::vector<math::Quat> referenceAt(const Quats& ref, const std::vector<double>& t) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<math::Quat> out(t.size(), math::Quat(nan, nan, nan, nan));
    for (std::size_t k = 0; k < t.size(); ++k) {
        const auto it = std::lower_bound(ref.t.begin(), ref.t.end(), t[k]);
        if (it == ref.t.end()) continue;
        const std::size_t j = std::size_t(it - ref.t.begin());
        if (*it == t[k]) {
            out[k] = ref.q[j];
        } else if (j > 0) {
            const double f = (t[k] - ref.t[j - 1]) / (ref.t[j] - ref.t[j - 1]);
            const math::Quat& a = ref.q[j - 1];
            const math::Quat& b = ref.q[j];
            if (a.coeffs().allFinite() && b.coeffs().allFinite())
                out[k] = math::slerp(a.normalized(), b.normalized(), f);
        }
    }
    return out;
}

void addGraph(QCustomPlot* plot, int index, const QString& name, const QVector<double>& t, const QVector<double>& v) {
    QCPGraph* graph = plot->addGraph();
    graph->setName(name);
    graph->setPen(QPen(PlotStyle::seriesColor(index), 1.2));
    graph->setData(t, v, true);
}

}  // namespace

OrientationAnglesView::OrientationAnglesView(const Project* project, QWidget* parent)
    : QWidget(parent), project_(project) {
    streamCombo_ = new QComboBox(this);
    streamCombo_->setObjectName(QStringLiteral("streamCombo"));
    if (project_) streamCombo_->addItems(orientationStreams(*project_));
    sequenceCombo_ = new QComboBox(this);
    sequenceCombo_->setObjectName(QStringLiteral("sequenceCombo"));
    // Cardan sequences first (aerospace yaw/pitch/roll = ZYX), then proper Euler, then extrinsic.
    sequenceCombo_->addItems(
        {"ZYX", "XYZ", "YXZ", "ZXY", "XZY", "YZX", "ZXZ", "ZYZ", "XYX", "XZX", "YXY", "YZY", "zyx", "xyz"});
    note_ = new QLabel(this);
    note_->setWordWrap(true);
    anglePlot_ = new QCustomPlot(this);
    anglePlot_->setObjectName(QStringLiteral("anglePlot"));
    errorPlot_ = new QCustomPlot(this);
    errorPlot_->setObjectName(QStringLiteral("errorPlot"));
    for (QCustomPlot* plot : {anglePlot_, errorPlot_}) {
        PlotStyle::apply(plot);
        plot->legend->setVisible(true);
        plot->xAxis->setLabel(tr("t [s]"));
        plot->setMinimumHeight(160);
    }
    anglePlot_->yAxis->setLabel(tr("angle [°]"));
    errorPlot_->yAxis->setLabel(tr("error [°]"));

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Stream:"), this));
    controls->addWidget(streamCombo_, 1);
    controls->addWidget(new QLabel(tr("Sequence:"), this));
    controls->addWidget(sequenceCombo_);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(anglePlot_);
    splitter->addWidget(errorPlot_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(splitter, 1);
    layout->addWidget(note_);

    connect(streamCombo_, &QComboBox::currentTextChanged, this, &OrientationAnglesView::refresh);
    connect(sequenceCombo_, &QComboBox::currentTextChanged, this, &OrientationAnglesView::refresh);
    refresh();
}

QStringList OrientationAnglesView::orientationStreams(const Project& project) {
    QStringList list;
    for (const QString& path : project.streamPaths()) {
        const Stream* s = project.stream(path);
        if (s->kind() == QLatin1String("orientation") && hasQuaternion(s->info())) list << path;
    }
    return list;
}

QString OrientationAnglesView::referenceFor(const Project& project, const QString& path) {
    const Recording* recording = project.recording(ItemPath::parse(path).recording);
    if (!recording) return {};
    for (const auto& [name, stream] : recording->streams)
        if (stream.kind() == QLatin1String("reference") && hasQuaternion(stream.info()))
            return ItemPath::parse(path).recording + QLatin1Char('/') + name;
    return {};
}

Status OrientationAnglesView::setStream(const QString& path) {
    if (streamCombo_->findText(path) < 0)
        return makeError(tr("'%1' is not an orientation stream (qw, qx, qy, qz)").arg(path));
    streamCombo_->setCurrentText(path);
    return {};
}

void OrientationAnglesView::setSequence(const QString& sequence) {
    if (sequenceCombo_->findText(sequence) < 0) sequenceCombo_->addItem(sequence);
    sequenceCombo_->setCurrentText(sequence);
}

QString OrientationAnglesView::stream() const { return streamCombo_->currentText(); }
QString OrientationAnglesView::sequence() const { return sequenceCombo_->currentText(); }

void OrientationAnglesView::refresh() {
    anglePlot_->clearGraphs();
    errorPlot_->clearGraphs();
    rms_ = {};
    note_->clear();
    const Stream* stream = project_ ? project_->stream(streamCombo_->currentText()) : nullptr;
    auto sequence = math::EulerSequence::parse(sequenceCombo_->currentText());
    if (stream && sequence) {
        const Quats est = readQuats(*stream);
        const std::size_t stride = est.t.size() / kMaxPoints + 1;
        QVector<double> t;
        std::array<QVector<double>, 3> angles;
        for (std::size_t k = 0; k < est.t.size(); k += stride) {
            const math::Vec3 a = math::eulerFromQuaternion(est.q[k].normalized(), *sequence) / math::kDeg;
            // A wrap from +180° to −180° is a gap, not a vertical line across the plot.
            bool wrapped = false;
            for (int i = 0; i < 3 && !t.isEmpty(); ++i) wrapped |= std::abs(a[i] - angles[i].back()) > 180.0;
            if (wrapped) {
                t.append(0.5 * (t.back() + est.t[k]));
                for (int i = 0; i < 3; ++i) angles[i].append(std::numeric_limits<double>::quiet_NaN());
            }
            t.append(est.t[k]);
            for (int i = 0; i < 3; ++i) angles[i].append(a[i]);
        }
        const QString axes = sequence->name();
        const bool yawPitchRoll = axes == QLatin1String("ZYX");
        const QStringList names = yawPitchRoll
                                      ? QStringList{tr("yaw (Z)"), tr("pitch (Y)"), tr("roll (X)")}
                                      : QStringList{tr("angle 1 (%1)").arg(axes[0]), tr("angle 2 (%1)").arg(axes[1]),
                                                    tr("angle 3 (%1)").arg(axes[2])};
        for (int i = 0; i < 3; ++i) addGraph(anglePlot_, i, names[i], t, angles[i]);

        const QString refPath = referenceFor(*project_, streamCombo_->currentText());
        const Stream* refStream = refPath.isEmpty() ? nullptr : project_->stream(refPath);
        if (refStream) {
            const std::vector<math::Quat> ref = referenceAt(readQuats(*refStream), est.t);
            rms_ = math::orientationErrorRms(est.q, ref);
            std::array<QVector<double>, 3> err;
            QVector<double> te;
            for (std::size_t k = 0; k < est.t.size(); k += stride) {
                if (!ref[k].coeffs().allFinite() || !est.q[k].coeffs().allFinite()) continue;
                const math::OrientationErrors e = math::orientationError(est.q[k], ref[k]);
                te.append(est.t[k]);
                err[0].append(e.total / math::kDeg);
                err[1].append(e.heading / math::kDeg);
                err[2].append(e.inclination / math::kDeg);
            }
            addGraph(errorPlot_, 0, tr("total (RMS %1°)").arg(rms_.total, 0, 'f', 2), te, err[0]);
            addGraph(errorPlot_, 1, tr("heading (RMS %1°)").arg(rms_.heading, 0, 'f', 2), te, err[1]);
            addGraph(errorPlot_, 2, tr("inclination (RMS %1°)").arg(rms_.inclination, 0, 'f', 2), te, err[2]);
            note_->setText(tr("Error against %1 (%2 samples).").arg(refPath).arg(rms_.count));
        } else {
            note_->setText(tr("No reference orientation (kind reference with qw..qz) in this recording."));
        }
    } else if (!sequence) {
        note_->setText(sequence.message());
    }
    errorPlot_->setVisible(errorPlot_->graphCount() > 0);
    for (QCustomPlot* plot : {anglePlot_, errorPlot_}) {
        plot->rescaleAxes();
        plot->replot();
    }
}

namespace {

void launchOrientationAngles(Workspace& workspace) {
    if (!workspace.project()) return;
    auto* window = new QWidget(workspace.window(), Qt::Window);
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setWindowTitle(QCoreApplication::translate("athlos::ui::OrientationAnglesView", "Orientation angles"));
    auto* layout = new QVBoxLayout(window);
    layout->addWidget(new OrientationAnglesView(workspace.project(), window));
    // The view reads the project it was opened on: close it when the main window swaps projects.
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, window, &QWidget::close);
    window->resize(900, 600);
    window->show();
}

Status prepareOrientationView(Workspace& workspace) {
    Project* project = workspace.project();
    const QStringList streams = project ? OrientationAnglesView::orientationStreams(*project) : QStringList();
    if (streams.isEmpty())
        return makeError(
            QCoreApplication::translate("athlos::ui::OrientationAnglesView",
                                        "no orientation stream (kind orientation with qw, qx, qy, qz) in this "
                                        "project; run orientation first"));
    auto* view = new OrientationAnglesView(project);
    if (Status status = view->setStream(streams.front()); !status) {
        delete view;
        return status;
    }
    workspace.addView(view, QCoreApplication::translate("athlos::ui::OrientationAnglesView", "Orientation"));
    QCoreApplication::processEvents();
    view->anglePlot()->replot();
    view->errorPlot()->replot();
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("orientation-angles"), QT_TRANSLATE_NOOP("Tools", "Orientation angles…"),
                      QT_TRANSLATE_NOOP("Tools", "Inertial"), launchOrientationAngles});
ATHLOS_REGISTER_VIEW({QStringLiteral("orientation"), prepareOrientationView});

}  // namespace athlos::ui
