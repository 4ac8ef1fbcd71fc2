#pragma once
// An action timeline: one lane per annotation class, each annotation a bar on the window's time
// axis (manual ones solid, predicted ones hatched and as opaque as their confidence), with the
// cursor and the visible range of the window's TimeController. A click moves the cursor. The
// label column shows per class the count and the mean duration ("stride left  42 · 1.09 s").
#include "core/model/Annotation.h"

#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>

namespace athlos {
class Project;
}

namespace athlos::ui {

class TimeController;

class ActionTimeline : public QWidget {
    Q_OBJECT

public:
    struct ClassStats {
        QString label;
        int count = 0;
        int predicted = 0;          // source other than "manual"
        double meanDuration = 0.0;  // s, over intervals (instants excluded); 0 if none
        double meanConfidence = 0.0;
    };

    explicit ActionTimeline(TimeController* time, QWidget* parent = nullptr);

    // The annotations to draw; project (may be null) supplies the class order and colours the
    // annotation layer uses, so a class has the same colour in both.
    void setAnnotations(const Annotations& annotations, const Project* project = nullptr);
    const Annotations& annotations() const { return annotations_; }

    // Lanes in display order: the project's classes first (in their order), then other labels
    // alphabetically.
    const QStringList& lanes() const { return lanes_; }
    const std::vector<ClassStats>& classStats() const { return stats_; }
    const ClassStats* statsFor(const QString& label) const;
    // Outlines annotation `index` (position in annotations()), e.g. the one under review; -1: none.
    void setHighlighted(int index);
    int highlighted() const { return highlighted_; }

    // Geometry, for painting and tests: the time area's x for t, the time at x, a lane's rectangle.
    int xAt(double t) const;
    double timeAt(int x) const;
    QRect laneRect(int lane) const;
    QRect timeArea() const;
    static QColor colorFor(const Project* project, const QString& label);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    void rebuild(const Project* project);
    double visibleBegin() const;
    double visibleEnd() const;

    QPointer<TimeController> time_;
    Annotations annotations_;
    QStringList lanes_;
    std::vector<ClassStats> stats_;
    std::vector<QColor> colors_;
    int highlighted_ = -1;
};

}  // namespace athlos::ui
