#include "ui/views/CycleNormalisedView.h"

#include "core/model/Project.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <algorithm>
#include <cmath>
#include <map>

namespace athlos::ui {

NormalisedCurves CycleNormalisedView::normalise(const std::vector<double>& t, const std::vector<double>& v,
                                                const std::vector<std::pair<double, double>>& cycles, int points,
                                                double span) {
    NormalisedCurves out;
    if (points < 2 || t.size() < 2) return out;
    std::vector<double> sum(std::size_t(points), 0.0), sum2(std::size_t(points), 0.0);
    for (const auto& [a, b] : cycles) {
        if (a < t.front() || b > t.back() || b <= a) continue;
        ++out.cycles;
        for (int k = 0; k < points; ++k) {
            const double x = a + (b - a) * double(k) / double(points - 1);
            const auto it = std::upper_bound(t.begin(), t.end(), x);
            const std::size_t i = std::min(t.size() - 1, std::size_t(std::max<std::ptrdiff_t>(1, it - t.begin())));
            const double f = t[i] > t[i - 1] ? (x - t[i - 1]) / (t[i] - t[i - 1]) : 0.0;
            const double y = v[i - 1] + f * (v[i] - v[i - 1]);
            sum[std::size_t(k)] += y;
            sum2[std::size_t(k)] += y * y;
        }
    }
    if (out.cycles == 0) return out;
    const double n = double(out.cycles);
    for (int k = 0; k < points; ++k) {
        const double m = sum[std::size_t(k)] / n;
        out.percent.push_back(span * double(k) / double(points - 1));
        out.mean.push_back(m);
        out.sd.push_back(out.cycles > 1 ? std::sqrt(std::max(0.0, (sum2[std::size_t(k)] - n * m * m) / (n - 1.0)))
                                        : 0.0);
    }
    return out;
}

std::vector<std::pair<double, double>> CycleNormalisedView::cyclesOf(const Annotations& annotations,
                                                                     const QString& label) {
    std::vector<std::pair<double, double>> out;
    if (label == QLatin1String(kDoubleTurn)) {
        for (const Annotation& l : annotations) {
            if (l.label != QLatin1String("turn left")) continue;
            for (const Annotation& r : annotations)
                if (r.label == QLatin1String("turn right") && std::abs(r.tStart - l.tEnd) < 1e-6)
                    out.emplace_back(l.tStart, r.tEnd);
        }
    } else {
        for (const Annotation& a : annotations)
            if (a.label == label && a.tEnd > a.tStart) out.emplace_back(a.tStart, a.tEnd);
    }
    std::sort(out.begin(), out.end());
    return out;
}

QStringList CycleNormalisedView::cycleLabels(const Annotations& annotations) {
    std::map<QString, int> count;
    for (const Annotation& a : annotations)
        if (a.tEnd > a.tStart) ++count[a.label];
    QStringList out;
    for (const auto& [label, n] : count)
        if (n >= 2) out << label;
    if (count.count(QStringLiteral("turn left")) && count.count(QStringLiteral("turn right")))
        out.prepend(QLatin1String(kDoubleTurn));
    return out;
}

CycleNormalisedView::CycleNormalisedView(const Project* project, QWidget* parent) : QWidget(parent), project_(project) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    recording_ = new QComboBox(this);
    stream_ = new QComboBox(this);
    column_ = new QComboBox(this);
    label_ = new QComboBox(this);
    row->addWidget(new QLabel(tr("Recording"), this));
    row->addWidget(recording_);
    row->addWidget(new QLabel(tr("Signal"), this));
    row->addWidget(stream_);
    row->addWidget(column_);
    row->addWidget(new QLabel(tr("Cycles"), this));
    row->addWidget(label_, 1);
    layout->addLayout(row);
    note_ = new QLabel(this);
    layout->addWidget(note_);
    plot_ = new QCustomPlot(this);
    plot_->setMinimumHeight(200);
    layout->addWidget(plot_, 1);
    connect(recording_, &QComboBox::currentIndexChanged, this, [this] { fillChoices(); });
    connect(stream_, &QComboBox::currentIndexChanged, this, [this] {
        if (filling_) return;
        filling_ = true;
        column_->clear();
        const Stream* s = project_ ? project_->stream(stream_->currentText()) : nullptr;
        if (s) column_->addItems(s->info().columnNames());
        filling_ = false;
        refresh();
    });
    connect(column_, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    connect(label_, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    fillRecordings();
}

void CycleNormalisedView::fillRecordings() {
    if (!project_) return;
    for (const QString& name : project_->recordingNames())
        if (!cycleLabels(project_->recording(name)->annotations).isEmpty()) recording_->addItem(name);
}

void CycleNormalisedView::fillChoices() {
    const Recording* rec = project_ ? project_->recording(recording_->currentText()) : nullptr;
    filling_ = true;
    stream_->clear();
    column_->clear();
    label_->clear();
    if (rec) {
        for (const auto& [name, s] : rec->streams) stream_->addItem(rec->name + QLatin1Char('/') + name);
        label_->addItems(cycleLabels(rec->annotations));
        if (const Stream* s = project_->stream(stream_->currentText())) column_->addItems(s->info().columnNames());
    }
    filling_ = false;
    refresh();
}

Status CycleNormalisedView::show(const QString& recording, const QString& stream, const QString& column,
                                 const QString& label) {
    const int r = recording_->findText(recording);
    if (r < 0) return makeError(tr("recording '%1' has no cycle annotations").arg(recording));
    recording_->setCurrentIndex(r);
    fillChoices();
    const int s = stream_->findText(stream);
    if (s < 0) return makeError(tr("no stream '%1' in recording '%2'").arg(stream, recording));
    stream_->setCurrentIndex(s);
    const int c = column_->findText(column);
    if (c < 0) return makeError(tr("stream '%1' has no column '%2'").arg(stream, column));
    column_->setCurrentIndex(c);
    const int l = label_->findText(label);
    if (l < 0) return makeError(tr("no cycles labelled '%1' in recording '%2'").arg(label, recording));
    label_->setCurrentIndex(l);
    refresh();
    return {};
}

void CycleNormalisedView::refresh() {
    if (filling_) return;
    plot_->clearGraphs();
    curves_ = {};
    const Recording* rec = project_ ? project_->recording(recording_->currentText()) : nullptr;
    const Stream* s = project_ ? project_->stream(stream_->currentText()) : nullptr;
    const int col = s ? s->info().columnIndex(column_->currentText()) : -1;
    if (!rec || !s || col < 0 || label_->currentText().isEmpty()) {
        note_->setText(
            tr("Choose a recording with cycle annotations (e.g. from xc-skiing-cycles, alpine-turns or "
               "gait-events), a signal and the cycles."));
        plot_->replot();
        return;
    }
    auto data = s->data();
    if (!data) {
        note_->setText(data.message());
        plot_->replot();
        return;
    }
    const StreamData& d = **data;
    std::vector<double> v(d.rows());
    for (std::size_t i = 0; i < d.rows(); ++i) v[i] = d.at(i, col);
    const bool doubleTurn = label_->currentText() == QLatin1String(kDoubleTurn);
    curves_ = normalise(d.t, v, cyclesOf(rec->annotations, label_->currentText()), 101, doubleTurn ? 200.0 : 100.0);
    const QString unit = s->info().columns[std::size_t(col)].unit;
    note_->setText(tr("%n cycle(s), mean ± SD", nullptr, curves_.cycles));
    QVector<double> x(curves_.percent.begin(), curves_.percent.end()), lo, hi,
        mean(curves_.mean.begin(), curves_.mean.end());
    for (std::size_t k = 0; k < curves_.mean.size(); ++k) {
        lo << curves_.mean[k] - curves_.sd[k];
        hi << curves_.mean[k] + curves_.sd[k];
    }
    QCPGraph* upper = plot_->addGraph();
    upper->setData(x, hi);
    upper->setPen(Qt::NoPen);
    QCPGraph* lower = plot_->addGraph();
    lower->setData(x, lo);
    lower->setPen(Qt::NoPen);
    upper->setBrush(QColor(31, 119, 180, 60));
    upper->setChannelFillGraph(lower);
    QCPGraph* m = plot_->addGraph();
    m->setData(x, mean);
    m->setPen(QPen(QColor(31, 119, 180), 2));
    m->setName(column_->currentText());
    plot_->xAxis->setLabel(doubleTurn ? tr("double turn (%): left 0–100, right 100–200") : tr("cycle (%)"));
    plot_->yAxis->setLabel(unit.isEmpty() || unit == QLatin1String("1") ? column_->currentText()
                                                                        : column_->currentText() + " [" + unit + "]");
    plot_->xAxis->setRange(0.0, doubleTurn ? 200.0 : 100.0);
    plot_->rescaleAxes(true);
    plot_->xAxis->setRange(0.0, doubleTurn ? 200.0 : 100.0);
    plot_->replot();
}

namespace {

QString trView(const char* text) { return QCoreApplication::translate("athlos::ui::CycleNormalisedView", text); }

QDockWidget* makeDock(const Project* project, QWidget* parent) {
    auto* dock = new QDockWidget(trView("Cycle-normalised curves"), parent);
    dock->setObjectName(QStringLiteral("cycleNormalisedDock"));
    dock->setWidget(new CycleNormalisedView(project, dock));
    dock->setAttribute(Qt::WA_DeleteOnClose);
    return dock;
}

void launchCycleNormalised(Workspace& workspace) {
    if (!workspace.project()) return;
    QDockWidget* dock = makeDock(workspace.project(), workspace.window());
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, &QWidget::close);
    workspace.addDock(dock, Qt::RightDockWidgetArea);
}

// Screenshot: the first recording with cycle annotations, its first stream's first column, its first label.
Status prepareCycleNormalised(Workspace& workspace) {
    Project* project = workspace.project();
    if (!project) return makeError(trView("no project"));
    QDockWidget* dock = makeDock(project, workspace.window());
    auto* view = dock->findChild<CycleNormalisedView*>();
    for (const QString& name : project->recordingNames()) {
        const Recording* rec = project->recording(name);
        const QStringList labels = CycleNormalisedView::cycleLabels(rec->annotations);
        if (labels.isEmpty() || rec->streams.empty()) continue;
        const auto& [stream, s] = *rec->streams.begin();
        const QStringList columns = s.info().columnNames();
        if (columns.isEmpty()) continue;
        // The trunk's yaw rate (gyr_z) over double turns, else the ski's medio-lateral gyroscope (gyr_y).
        const QString preferred = labels.front() == QLatin1String(CycleNormalisedView::kDoubleTurn)
                                      ? QStringLiteral("gyr_z")
                                      : QStringLiteral("gyr_y");
        const QString column = columns.contains(preferred) ? preferred : columns.front();
        if (Status st = view->show(name, name + QLatin1Char('/') + stream, column, labels.front()); !st) {
            delete dock;
            return st;
        }
        workspace.addDock(dock, Qt::RightDockWidgetArea);
        workspace.resizeDock(dock, workspace.window()->width() / 2, Qt::Horizontal);
        return {};
    }
    delete dock;
    return makeError(
        trView("no recording with cycle annotations (run xc-skiing-cycles, alpine-turns or gait-events "
               "first)"));
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("cycle-normalised-view"), QT_TRANSLATE_NOOP("Tools", "Cycle-normalised curves…"),
                      QT_TRANSLATE_NOOP("Tools", "Inertial"), launchCycleNormalised});
ATHLOS_REGISTER_VIEW({QStringLiteral("cycle-normalised"), prepareCycleNormalised});

}  // namespace athlos::ui
