#include "ui/views/ActionsView.h"

#include "core/model/Project.h"
#include "ui/AnnotationEditor.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"
#include "ui/views/ActionTimeline.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace athlos::ui {

ActionsView::ActionsView(const Project* project, TimeController* time, QWidget* parent)
    : QWidget(parent), project_(project), time_(time) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Recording:"), this));
    recordingCombo_ = new QComboBox(this);
    if (project_) recordingCombo_->addItems(annotatedRecordings(*project_));
    top->addWidget(recordingCombo_);
    auto* refreshButton = new QPushButton(tr("Refresh"), this);
    refreshButton->setToolTip(tr("Read the annotations again (after a processor run)."));
    top->addWidget(refreshButton);
    summary_ = new QLabel(this);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    top->addWidget(summary_, 1);
    layout->addLayout(top);

    auto* body = new QHBoxLayout;
    timeline_ = new ActionTimeline(time, this);
    timeline_->setToolTip(
        tr("Solid: manual annotations. Hatched: predicted by a processor, more opaque with "
           "higher confidence. Click to move the time cursor."));
    body->addWidget(timeline_, 1);
    table_ = new QTableWidget(0, 5, this);
    table_->setHorizontalHeaderLabels({tr("Class"), tr("Count"), tr("Predicted"), tr("Mean (s)"), tr("Confidence")});
    table_->horizontalHeaderItem(3)->setToolTip(tr("Mean duration of the intervals"));
    table_->horizontalHeaderItem(4)->setToolTip(tr("Mean confidence of the predicted ones"));
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    body->addWidget(table_);
    layout->addLayout(body, 1);

    auto* review = new QHBoxLayout;
    auto* previous = new QPushButton(tr("◀ Previous"), this);
    auto* next = new QPushButton(tr("Next ▶"), this);
    auto* accept = new QPushButton(tr("Accept"), this);
    auto* reject = new QPushButton(tr("Reject"), this);
    previous->setToolTip(tr("Previous predicted action"));
    next->setToolTip(tr("Next predicted action"));
    accept->setToolTip(tr("Keep the predicted action as a reviewed manual annotation (undoable)."));
    reject->setToolTip(tr("Delete the predicted action (undoable)."));
    acceptButton_ = accept;
    rejectButton_ = reject;
    reviewLabel_ = new QLabel(this);
    review->addWidget(new QLabel(tr("Review:"), this));
    for (QPushButton* b : {previous, next, accept, reject}) review->addWidget(b);
    review->addWidget(reviewLabel_, 1);
    layout->addLayout(review);
    connect(previous, &QPushButton::clicked, this, [this] { reviewPrevious(); });
    connect(next, &QPushButton::clicked, this, [this] { reviewNext(); });
    connect(accept, &QPushButton::clicked, this, [this] {
        if (Status s = acceptCurrent(); !s) reviewLabel_->setText(s.message());
    });
    connect(reject, &QPushButton::clicked, this, [this] {
        if (Status s = rejectCurrent(); !s) reviewLabel_->setText(s.message());
    });

    connect(recordingCombo_, &QComboBox::currentTextChanged, this, &ActionsView::refresh);
    connect(refreshButton, &QPushButton::clicked, this, &ActionsView::refresh);
    refresh();
}

QStringList ActionsView::annotatedRecordings(const Project& project) {
    QStringList names;
    for (const auto& [name, recording] : project.recordings())
        if (!recording.annotations.empty()) names << name;
    return names;
}

QString ActionsView::sourceStream(const Project& project, const QString& name) {
    const Recording* rec = project.recording(name);
    if (!rec) return {};
    const QJsonObject sources = rec->metadata.value(QStringLiteral("annotation_provenance")).toObject();
    for (const Annotation& a : rec->annotations) {
        if (a.source == QLatin1String("manual")) continue;
        const QJsonArray inputs = sources.value(a.annotator).toObject().value(QStringLiteral("inputs")).toArray();
        for (const auto& input : inputs) {
            const QString path = input.toObject().value(QStringLiteral("name")).toString();
            if (project.stream(path)) return path;
        }
    }
    return rec->streams.empty() ? QString() : name + QLatin1Char('/') + rec->streams.begin()->first;
}

Status ActionsView::setRecording(const QString& name) {
    if (!project_ || !project_->recording(name)) return makeError(tr("no recording '%1' in this project").arg(name));
    if (recordingCombo_->findText(name) < 0) recordingCombo_->addItem(name);
    if (recordingCombo_->currentText() != name)
        recordingCombo_->setCurrentText(name);  // refreshes
    else
        refresh();
    return {};
}

QString ActionsView::recording() const { return recordingCombo_->currentText(); }

void ActionsView::refresh() {
    const Recording* rec = project_ ? project_->recording(recording()) : nullptr;
    timeline_->setAnnotations(rec ? rec->annotations : Annotations(), project_);
    const auto& stats = timeline_->classStats();
    table_->setRowCount(int(stats.size()));
    int total = 0, predicted = 0;
    for (int row = 0; row < int(stats.size()); ++row) {
        const auto& s = stats[std::size_t(row)];
        total += s.count;
        predicted += s.predicted;
        auto* label = new QTableWidgetItem(s.label);
        label->setForeground(ActionTimeline::colorFor(project_, s.label).darker(140));
        table_->setItem(row, 0, label);
        const QStringList cells{QString::number(s.count), QString::number(s.predicted),
                                s.meanDuration > 0 ? QString::number(s.meanDuration, 'f', 3) : QStringLiteral("–"),
                                s.predicted ? QString::number(s.meanConfidence, 'f', 2) : QStringLiteral("–")};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, c + 1, item);
        }
    }
    // The table is as wide as its columns: the timeline gets the rest.
    table_->resizeColumnsToContents();
    int width = 2 * table_->frameWidth() + 2;
    for (int c = 0; c < table_->columnCount(); ++c) width += table_->columnWidth(c);
    table_->setFixedWidth(width);
    summary_->setText(tr("%n annotation(s)", nullptr, total) + QStringLiteral(", ") +
                      tr("%n predicted", nullptr, predicted));
    if (rec && (current_ >= int(rec->annotations.size()) ||
                (current_ >= 0 && rec->annotations[std::size_t(current_)].source == QLatin1String("manual"))))
        current_ = -1;
    if (!rec) current_ = -1;
    updateReview();
}

void ActionsView::setEditor(AnnotationEditor* editor) {
    if (editor_) disconnect(editor_, nullptr, this, nullptr);
    editor_ = editor;
    if (editor_)
        connect(editor_, &AnnotationEditor::annotationsChanged, this, [this](const QString& rec) {
            if (rec == recording()) refresh();
        });
    updateReview();
}

std::vector<int> ActionsView::predictedOrder() const {
    std::vector<int> order;
    const Recording* rec = project_ ? project_->recording(recording()) : nullptr;
    if (!rec) return order;
    for (int k = 0; k < int(rec->annotations.size()); ++k)
        if (rec->annotations[std::size_t(k)].source != QLatin1String("manual")) order.push_back(k);
    std::stable_sort(order.begin(), order.end(), [rec](int a, int b) {
        return rec->annotations[std::size_t(a)].tStart < rec->annotations[std::size_t(b)].tStart;
    });
    return order;
}

void ActionsView::goTo(int index) {
    current_ = index;
    const Recording* rec = project_ ? project_->recording(recording()) : nullptr;
    if (rec && index >= 0 && time_) {
        const Annotation& a = rec->annotations[std::size_t(index)];
        const double mid = 0.5 * (a.tStart + a.tEnd);
        const double span = time_->visibleEnd() - time_->visibleBegin();
        if (a.tStart < time_->visibleBegin() || a.tEnd > time_->visibleEnd())
            time_->setVisibleRange(mid - 0.5 * span, mid + 0.5 * span);
        time_->setCursor(mid);
    }
    updateReview();
}

bool ActionsView::reviewNext() {
    const auto order = predictedOrder();
    if (order.empty()) return false;
    auto it = std::find(order.begin(), order.end(), current_);
    if (it == order.end())
        goTo(order.front());
    else if (it + 1 != order.end())
        goTo(*(it + 1));
    else
        return false;
    return true;
}

bool ActionsView::reviewPrevious() {
    const auto order = predictedOrder();
    auto it = std::find(order.begin(), order.end(), current_);
    if (it == order.end() || it == order.begin()) return false;
    goTo(*(it - 1));
    return true;
}

// The first predicted annotation starting at or after t (after an accept or reject).
void ActionsView::advanceFrom(double t) {
    const Recording* rec = project_ ? project_->recording(recording()) : nullptr;
    current_ = -1;
    if (rec)
        for (int k : predictedOrder())
            if (rec->annotations[std::size_t(k)].tStart >= t) {
                goTo(k);
                return;
            }
    updateReview();
}

Status ActionsView::acceptCurrent() {
    if (!editor_) return makeError(tr("Reviewing needs the annotation editor of the main window."));
    if (current_ < 0) return makeError(tr("No predicted action selected; use Next."));
    const double t = project_->recording(recording())->annotations[std::size_t(current_)].tStart;
    if (Status s = editor_->accept(recording(), current_); !s) return s;
    refresh();
    advanceFrom(t);
    return {};
}

Status ActionsView::rejectCurrent() {
    if (!editor_) return makeError(tr("Reviewing needs the annotation editor of the main window."));
    if (current_ < 0) return makeError(tr("No predicted action selected; use Next."));
    const double t = project_->recording(recording())->annotations[std::size_t(current_)].tStart;
    if (Status s = editor_->remove(recording(), current_); !s) return s;
    current_ = -1;
    refresh();
    advanceFrom(t);
    return {};
}

void ActionsView::updateReview() {
    timeline_->setHighlighted(current_);
    const auto order = predictedOrder();
    const bool active = current_ >= 0 && editor_;
    acceptButton_->setEnabled(active);
    rejectButton_->setEnabled(active);
    if (current_ < 0) {
        reviewLabel_->setText(order.empty()
                                  ? tr("No predicted actions to review.")
                                  : tr("%n predicted action(s) to review; press Next.", nullptr, int(order.size())));
        return;
    }
    const Annotation& a = project_->recording(recording())->annotations[std::size_t(current_)];
    const int position = int(std::find(order.begin(), order.end(), current_) - order.begin()) + 1;
    reviewLabel_->setText(tr("%1 of %2: %3, %4–%5 s, confidence %6")
                              .arg(position)
                              .arg(order.size())
                              .arg(a.label)
                              .arg(a.tStart, 0, 'f', 2)
                              .arg(a.tEnd, 0, 'f', 2)
                              .arg(a.confidence, 0, 'f', 2));
}

namespace {

constexpr const char* kDockName = "actionTimelineDock";

QDockWidget* makeDock(QWidget* window, ActionsView* view) {
    auto* dock = new QDockWidget(QCoreApplication::translate("athlos::ui::ActionsView", "Action timeline"), window);
    dock->setObjectName(QLatin1String(kDockName));
    dock->setAttribute(Qt::WA_DeleteOnClose);
    dock->setWidget(view);
    return dock;
}

void launchActionTimeline(Workspace& workspace) {
    Project* project = workspace.project();
    if (!project) return;
    if (auto* existing = workspace.window()->findChild<QDockWidget*>(QLatin1String(kDockName))) {
        if (auto* view = qobject_cast<ActionsView*>(existing->widget())) view->refresh();
        existing->show();
        existing->raise();
        return;
    }
    auto* view = new ActionsView(project, workspace.timeController());
    auto* dock = makeDock(workspace.window(), view);
    // The view reads the project it was opened on: close with it, follow annotation edits and
    // review through the window's editor.
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, &QWidget::close);
    view->setEditor(workspace.annotationEditor());
    workspace.addDock(dock, Qt::BottomDockWidgetArea);
    dock->show();
}

// The foot IMU the predicted actions came from, with the annotations on its time series, and the
// action timeline docked below, over the first ~15 s that have annotations.
Status prepareActionsView(Workspace& workspace) {
    Project* project = workspace.project();
    const QStringList recordings = project ? ActionsView::annotatedRecordings(*project) : QStringList();
    if (recordings.isEmpty())
        return makeError(QCoreApplication::translate("athlos::ui::ActionsView",
                                                     "no annotations in this project; run an event detector (e.g. "
                                                     "gait-events) or annotate first"));
    // Prefer a recording with predicted actions.
    QString recording = recordings.front();
    for (const QString& name : recordings) {
        const auto& all = project->recording(name)->annotations;
        if (std::any_of(all.begin(), all.end(),
                        [](const Annotation& a) { return a.source != QLatin1String("manual"); })) {
            recording = name;
            break;
        }
    }
    const QString stream = ActionsView::sourceStream(*project, recording);
    if (stream.isEmpty())
        return makeError(QCoreApplication::translate("athlos::ui::ActionsView", "recording '%1' has no stream to plot")
                             .arg(recording));
    workspace.selectItem(stream);
    workspace.showTimeSeriesView();
    workspace.waitForPlots();

    auto* view = new ActionsView(project, workspace.timeController());
    view->setEditor(workspace.annotationEditor());
    if (Status s = view->setRecording(recording); !s) {
        delete view;
        return s;
    }
    auto* dock = makeDock(workspace.window(), view);
    workspace.addDock(dock, Qt::BottomDockWidgetArea);
    dock->show();
    workspace.resizeDock(dock, int(workspace.window()->height() * 0.36), Qt::Vertical);

    view->reviewNext();  // the first predicted action outlined, its review line filled in
    const auto& all = project->recording(recording)->annotations;
    double first = all.front().tStart;
    for (const Annotation& a : all) first = std::min(first, a.tStart);
    TimeController* time = workspace.timeController();
    const double begin = std::max(time->begin(), first - 1.0);
    time->setVisibleRange(begin, std::min(time->end(), begin + 15.0));
    time->setCursor(0.5 * (time->visibleBegin() + time->visibleEnd()));
    workspace.waitForPlots();
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("action-timeline"), QT_TRANSLATE_NOOP("Tools", "Action timeline…"),
                      QT_TRANSLATE_NOOP("Tools", "View"), launchActionTimeline});
ATHLOS_REGISTER_VIEW({QStringLiteral("actions"), prepareActionsView});

}  // namespace athlos::ui
