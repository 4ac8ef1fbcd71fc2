#include "ui/AnnotationPanel.h"

#include "core/model/Project.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/PlotStyle.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace athlos::ui {

AnnotationPanel::AnnotationPanel(AnnotationEditor* editor, AnnotationLayer* layer, QWidget* parent)
    : QWidget(parent), editor_(editor), layer_(layer) {
    classes_ = new QListWidget(this);
    classes_->setToolTip(tr("Class of new intervals (keys 1–9 on the plot)"));
    classes_->setMaximumHeight(110);
    connect(classes_, &QListWidget::currentTextChanged, this, [this](const QString& text) {
        if (!refreshing_ && !text.isEmpty()) editor_->setCurrentClass(text.section(QLatin1Char(' '), 1));
    });
    auto* addClass = new QPushButton(tr("Add Class…"), this);
    connect(addClass, &QPushButton::clicked, this, &AnnotationPanel::addClassDialog);

    table_ = new QTableWidget(0, 4, this);
    table_->setHorizontalHeaderLabels({tr("Class"), tr("Start [s]"), tr("End [s]"), tr("Source")});
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->setVisible(false);
    table_->horizontalHeader()->setStretchLastSection(true);
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        if (!refreshing_ && layer_) layer_->setSelected(selectedRow());
    });

    auto* next = new QPushButton(tr("Next to Review"), this);
    next->setToolTip(tr("Select the next annotation made by a processor"));
    connect(next, &QPushButton::clicked, this, [this] { reviewNext(); });
    auto* accept = new QPushButton(tr("Accept"), this);
    connect(accept, &QPushButton::clicked, this, &AnnotationPanel::acceptSelected);
    auto* reject = new QPushButton(tr("Reject"), this);
    connect(reject, &QPushButton::clicked, this, &AnnotationPanel::rejectSelected);
    status_ = new QLabel(this);
    status_->setWordWrap(true);

    auto* classRow = new QHBoxLayout;
    classRow->addWidget(new QLabel(tr("Classes:"), this), 1);
    classRow->addWidget(addClass);
    auto* reviewRow = new QHBoxLayout;
    reviewRow->addWidget(next);
    reviewRow->addWidget(accept);
    reviewRow->addWidget(reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(classRow);
    layout->addWidget(classes_);
    layout->addWidget(table_, 1);
    layout->addLayout(reviewRow);
    layout->addWidget(status_);

    connect(editor_, &AnnotationEditor::classesChanged, this, &AnnotationPanel::refresh);
    connect(editor_, &AnnotationEditor::currentClassChanged, this, &AnnotationPanel::refresh);
    connect(editor_, &AnnotationEditor::annotationsChanged, this, &AnnotationPanel::refresh);
    refresh();
}

void AnnotationPanel::refresh() {
    refreshing_ = true;
    const Project* project = editor_->project();
    classes_->clear();
    const QStringList classes = project ? project->annotationClasses() : QStringList();
    for (int i = 0; i < classes.size(); ++i) {
        auto* item = new QListWidgetItem(
            QStringLiteral("%1 %2").arg(i < 9 ? QString::number(i + 1) : QStringLiteral("·"), classes[i]), classes_);
        QPixmap swatch(12, 12);
        swatch.fill(PlotStyle::seriesColor(i));
        item->setIcon(QIcon(swatch));
        if (classes[i] == editor_->currentClass()) classes_->setCurrentItem(item);
    }
    const QString recording = layer_ ? layer_->recording() : QString();
    const Recording* rec = project ? project->recording(recording) : nullptr;
    table_->setRowCount(rec ? int(rec->annotations.size()) : 0);
    int toReview = 0;
    if (rec) {
        for (int row = 0; row < int(rec->annotations.size()); ++row) {
            const Annotation& a = rec->annotations[std::size_t(row)];
            const bool manual = a.source == QLatin1String("manual");
            toReview += manual ? 0 : 1;
            const QString source = manual ? tr("manual (%1)").arg(a.annotator)
                                          : tr("%1, %2% confident").arg(a.source).arg(std::lround(a.confidence * 100));
            const QStringList cells{a.label, QLocale().toString(a.tStart, 'f', 3), QLocale().toString(a.tEnd, 'f', 3),
                                    source};
            for (int c = 0; c < cells.size(); ++c) table_->setItem(row, c, new QTableWidgetItem(cells[c]));
        }
    }
    if (layer_ && layer_->selected() >= 0 && layer_->selected() < table_->rowCount())
        table_->selectRow(layer_->selected());
    if (!rec)
        status_->setText(tr("Select a stream to annotate its recording."));
    else if (rec->annotations.empty())
        status_->setText(
            tr("No annotations on %1 yet. Shift+drag on the plot (or use annotate mode) to add one.").arg(recording));
    else
        status_->setText(tr("Annotations to review: %1").arg(toReview));
    refreshing_ = false;
}

int AnnotationPanel::selectedRow() const {
    const QList<QTableWidgetItem*> items = table_->selectedItems();
    return items.isEmpty() ? -1 : items.front()->row();
}

bool AnnotationPanel::reviewNext() {
    const Project* project = editor_->project();
    const Recording* rec = project && layer_ ? project->recording(layer_->recording()) : nullptr;
    if (!rec) return false;
    const int n = int(rec->annotations.size());
    const int from = selectedRow();
    for (int k = 1; k <= n; ++k) {
        const int row = (from + k + n) % n;
        if (rec->annotations[std::size_t(row)].source != QLatin1String("manual")) {
            layer_->setSelected(row);
            table_->selectRow(row);
            return true;
        }
    }
    status_->setText(tr("Nothing left to review."));
    return false;
}

void AnnotationPanel::acceptSelected() {
    const int row = selectedRow();
    if (row < 0 || !layer_) return;
    if (Status s = editor_->accept(layer_->recording(), row); !s)
        status_->setText(s.message());
    else
        reviewNext();
}

void AnnotationPanel::rejectSelected() {
    const int row = selectedRow();
    if (row < 0 || !layer_) return;
    if (Status s = editor_->remove(layer_->recording(), row); !s)
        status_->setText(s.message());
    else
        reviewNext();
}

void AnnotationPanel::addClassDialog() {
    bool ok = false;
    const QString name =
        QInputDialog::getText(this, tr("Add Annotation Class"), tr("Class name:"), QLineEdit::Normal, {}, &ok);
    if (!ok) return;
    if (Status s = editor_->addClass(name); !s) status_->setText(s.message());
}

}  // namespace athlos::ui
