#include "ui/AnnotationLayer.h"

#include "core/model/Project.h"
#include "ui/AnnotationEditor.h"
#include "ui/PlotStyle.h"
#include "ui/TimeSeriesPanel.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <qcustomplot.h>

#include <cmath>

namespace athlos::ui {

namespace {
const QString kLayerName = QStringLiteral("annotations");
constexpr int kEdgePixels = 5;  // how close to a span's edge a press grabs the edge

QColor classColor(const Project* project, const QString& label) {
    const int index = project ? int(project->annotationClasses().indexOf(label)) : -1;
    // Unknown labels (e.g. from a processor) still get a stable colour.
    return PlotStyle::seriesColor(index >= 0 ? index : 8 + int(qHash(label) % 8));
}
}  // namespace

AnnotationLayer::AnnotationLayer(TimeSeriesPanel* panel, AnnotationEditor* editor)
    : QObject(panel), panel_(panel), editor_(editor) {
    QCustomPlot* p = plot();
    if (!p->layer(kLayerName)) p->addLayer(kLayerName, p->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    connect(p, &QCustomPlot::mousePress, this, &AnnotationLayer::onPress);
    connect(p, &QCustomPlot::mouseMove, this, &AnnotationLayer::onMove);
    connect(p, &QCustomPlot::mouseRelease, this, &AnnotationLayer::onRelease);
    connect(editor_, &AnnotationEditor::annotationsChanged, this, [this](const QString& rec) {
        if (rec == recording_) rebuild();
    });
    connect(editor_, &AnnotationEditor::classesChanged, this, &AnnotationLayer::rebuild);
    connect(panel, &TimeSeriesPanel::lanesChanged, this, &AnnotationLayer::rebuild);
    panel->installEventFilter(this);
}

QCustomPlot* AnnotationLayer::plot() const { return panel_->plot(); }

bool AnnotationLayer::inAnyLane(const QPoint& pos) const {
    for (int lane = 0; lane < plot()->axisRectCount(); ++lane)
        if (plot()->axisRect(lane)->rect().contains(pos)) return true;
    return false;
}

void AnnotationLayer::setRecording(const QString& recording) {
    recording_ = recording;
    selected_ = -1;
    rebuild();
}

void AnnotationLayer::clearSpans() {
    for (const Span& span : spans_) {
        plot()->removeItem(span.rect);
        plot()->removeItem(span.label);
        for (QCPItemRect* shade : span.shades) plot()->removeItem(shade);
    }
    spans_.clear();
}

void AnnotationLayer::rebuild() {
    clearSpans();
    const Project* project = editor_->project();
    const Recording* rec = project ? project->recording(recording_) : nullptr;
    if (rec) {
        for (std::size_t i = 0; i < rec->annotations.size(); ++i) {
            const Annotation& a = rec->annotations[i];
            QColor color = classColor(project, a.label);
            Span span;
            span.rect = new QCPItemRect(plot());
            span.rect->setLayer(kLayerName);
            span.rect->setSelectable(false);
            span.rect->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
            span.rect->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
            span.rect->topLeft->setCoords(a.tStart, 0.0);
            span.rect->bottomRight->setCoords(a.tEnd, 1.0);
            const bool selected = int(i) == selected_;
            // Processor annotations are paler until reviewed.
            color.setAlpha(a.source == QLatin1String("manual") ? 70 : 35);
            span.rect->setBrush(color);
            span.rect->setPen(QPen(color.darker(selected ? 200 : 130), selected ? 2.5 : 1.0));

            span.label = new QCPItemText(plot());
            span.label->setLayer(kLayerName);
            span.label->setSelectable(false);
            span.label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
            span.label->position->setCoords(a.tStart, 0.0);
            span.label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
            span.label->setClipToAxisRect(true);
            QString text = a.label;
            if (a.source != QLatin1String("manual"))
                text += QStringLiteral(" (%1%)").arg(std::lround(a.confidence * 100));
            span.label->setText(text);
            span.label->setColor(color.darker(220));
            // The other lanes of a stacked panel shade the same interval (their time axis is the same).
            for (int lane = 1; lane < plot()->axisRectCount(); ++lane) {
                QCPAxisRect* axisRect = plot()->axisRect(lane);
                auto* shade = new QCPItemRect(plot());
                shade->setLayer(kLayerName);
                shade->setSelectable(false);
                shade->setClipAxisRect(axisRect);
                for (QCPItemPosition* p : {shade->topLeft, shade->bottomRight}) {
                    p->setAxes(axisRect->axis(QCPAxis::atBottom), axisRect->axis(QCPAxis::atLeft));
                    p->setAxisRect(axisRect);
                    p->setTypeY(QCPItemPosition::ptAxisRectRatio);
                }
                shade->topLeft->setCoords(a.tStart, 0.0);
                shade->bottomRight->setCoords(a.tEnd, 1.0);
                shade->setBrush(span.rect->brush());
                shade->setPen(span.rect->pen());
                span.shades.push_back(shade);
            }
            spans_.push_back(span);
        }
    }
    plot()->replot(QCustomPlot::rpQueuedReplot);
}

void AnnotationLayer::setSelected(int index) {
    selected_ = index >= 0 && index < spanCount() ? index : -1;
    rebuild();
}

int AnnotationLayer::spanAt(double pixelX, Drag* edge) const {
    const Project* project = editor_->project();
    const Recording* rec = project ? project->recording(recording_) : nullptr;
    if (!rec) return -1;
    const QCPAxis* x = plot()->xAxis;
    int inside = -1;
    for (std::size_t i = 0; i < rec->annotations.size(); ++i) {
        const double start = x->coordToPixel(rec->annotations[i].tStart);
        const double end = x->coordToPixel(rec->annotations[i].tEnd);
        if (edge && std::abs(pixelX - start) <= kEdgePixels) {
            *edge = Drag::MoveStart;
            return int(i);
        }
        if (edge && std::abs(pixelX - end) <= kEdgePixels) {
            *edge = Drag::MoveEnd;
            return int(i);
        }
        if (pixelX >= start && pixelX <= end) inside = int(i);
    }
    return inside;
}

void AnnotationLayer::onPress(QMouseEvent* event) {
    const bool annotating = annotateMode_ || (event->modifiers() & Qt::ShiftModifier);
    if (!annotating || event->button() != Qt::LeftButton || recording_.isEmpty()) return;
    if (!inAnyLane(event->pos())) return;
    Drag edge = Drag::None;
    const int index = spanAt(event->pos().x(), &edge);
    if (index >= 0 && edge != Drag::None) {
        drag_ = edge;
        dragIndex_ = index;
    } else {
        drag_ = Drag::Create;
        dragOrigin_ = plot()->xAxis->pixelToCoord(event->pos().x());
        preview_ = new QCPItemRect(plot());
        preview_->setLayer(kLayerName);
        preview_->topLeft->setTypeY(QCPItemPosition::ptAxisRectRatio);
        preview_->bottomRight->setTypeY(QCPItemPosition::ptAxisRectRatio);
        QColor color = classColor(editor_->project(), editor_->currentClass());
        color.setAlpha(60);
        preview_->setBrush(color);
        preview_->setPen(QPen(color.darker(150), 1, Qt::DashLine));
        preview_->topLeft->setCoords(dragOrigin_, 0.0);
        preview_->bottomRight->setCoords(dragOrigin_, 1.0);
    }
    // The drag is ours, not the axis rect's pan.
    savedRangeDrag_ = plot()->interactions().testFlag(QCP::iRangeDrag);
    plot()->setInteraction(QCP::iRangeDrag, false);
}

void AnnotationLayer::onMove(QMouseEvent* event) {
    if (drag_ == Drag::None) {
        // Hovering an edge in annotate mode shows that it can be dragged.
        Drag edge = Drag::None;
        const bool nearEdge = annotateMode_ && spanAt(event->pos().x(), &edge) >= 0 && edge != Drag::None;
        plot()->setCursor(nearEdge ? Qt::SizeHorCursor : Qt::ArrowCursor);
        return;
    }
    const double t = plot()->xAxis->pixelToCoord(event->pos().x());
    if (drag_ == Drag::Create && preview_) {
        preview_->topLeft->setCoords(std::min(t, dragOrigin_), 0.0);
        preview_->bottomRight->setCoords(std::max(t, dragOrigin_), 1.0);
    } else if (dragIndex_ >= 0 && dragIndex_ < spanCount()) {
        const Span& span = spans_[std::size_t(dragIndex_)];
        std::vector<QCPItemRect*> rects = span.shades;
        rects.push_back(span.rect);
        for (QCPItemRect* rect : rects)
            (drag_ == Drag::MoveStart ? rect->topLeft : rect->bottomRight)
                ->setCoords(t, drag_ == Drag::MoveStart ? 0.0 : 1.0);
    }
    plot()->replot(QCustomPlot::rpQueuedReplot);
}

void AnnotationLayer::onRelease(QMouseEvent* event) {
    const bool clickOnly = drag_ == Drag::None;
    if (!clickOnly) plot()->setInteraction(QCP::iRangeDrag, savedRangeDrag_);
    const double t = plot()->xAxis->pixelToCoord(event->pos().x());
    const Drag drag = drag_;
    drag_ = Drag::None;
    if (preview_) {
        plot()->removeItem(preview_);
        preview_ = nullptr;
    }
    Status status;
    if (drag == Drag::Create) {
        const double widthPixels = std::abs(plot()->xAxis->coordToPixel(t) - plot()->xAxis->coordToPixel(dragOrigin_));
        if (widthPixels < 3) {
            // A click in annotate mode selects the span under it.
            setSelected(spanAt(event->pos().x(), nullptr));
            return;
        }
        auto created = editor_->create(recording_, dragOrigin_, t);
        if (created)
            selected_ = *created;
        else
            status = created.error();
    } else if (drag == Drag::MoveStart || drag == Drag::MoveEnd) {
        const Recording* rec = editor_->project() ? editor_->project()->recording(recording_) : nullptr;
        if (rec && dragIndex_ < int(rec->annotations.size())) {
            Annotation a = rec->annotations[std::size_t(dragIndex_)];
            (drag == Drag::MoveStart ? a.tStart : a.tEnd) = t;
            if (a.tEnd < a.tStart) std::swap(a.tStart, a.tEnd);
            status = editor_->change(recording_, dragIndex_, a);
            selected_ = dragIndex_;
        }
    } else if (event->modifiers() & Qt::ShiftModifier || annotateMode_) {
        setSelected(spanAt(event->pos().x(), nullptr));
        return;
    }
    if (!status) emit editor_->errorOccurred(status.message());
    rebuild();
}

bool AnnotationLayer::eventFilter(QObject* watched, QEvent* event) {
    // The type first: while the panel is being destroyed it still sends events, and converting the
    // QPointer to a TimeSeriesPanel* then would be a bad downcast (UBSan vptr).
    if (event->type() == QEvent::KeyPress && watched == panel_.data()) {
        auto* key = static_cast<QKeyEvent*>(event);
        if ((key->key() == Qt::Key_Delete || key->key() == Qt::Key_Backspace) && selected_ >= 0) {
            const Status removed = editor_->remove(recording_, selected_);
            if (!removed) emit editor_->errorOccurred(removed.message());
            selected_ = -1;
            rebuild();
            return true;
        }
        if (key->key() >= Qt::Key_1 && key->key() <= Qt::Key_9 && key->modifiers() == Qt::NoModifier)
            return editor_->selectClassByNumber(key->key() - Qt::Key_1);
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace athlos::ui
