#pragma once
// Joint angles (kind "joint-angles": flexion, abduction, rotation in rad, from the joint-angles
// processor) as three plots in degrees, with the reference overlaid when the recording has one (a
// joint-angles stream with attributes reference = true and the same joint and side, e.g. from
// simulate-limb) and the RMSE per angle, and the same joint of the other side overlaid (left/right
// comparison; "Other side" toggles it) when the recording has one. The x axes follow the window's TimeController both ways
// (visible range, cursor line, click sets the cursor) and a read-out shows the angles at the cursor.
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>
#include <array>
#include <vector>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QCPItemStraightLine;
class QLabel;
class QMouseEvent;

namespace athlos {
class Project;
}

namespace athlos::ui {

class TimeController;

class JointAnglesView : public QWidget {
    Q_OBJECT

public:
    explicit JointAnglesView(const Project* project, QWidget* parent = nullptr);

    // Computed joint-angle streams (kind joint-angles with flexion, abduction, rotation; references excluded).
    static QStringList jointAngleStreams(const Project& project);
    // The reference for a computed stream: same recording, reference = true, same joint and side; or empty.
    static QString referenceFor(const Project& project, const QString& path);
    // The same joint of the other side (attributes side left ↔ right) in the same recording, not a
    // reference; or empty.
    static QString otherSideFor(const Project& project, const QString& path);

    Status setStream(const QString& path);
    QString stream() const;
    QString reference() const { return reference_; }
    QString otherSide() const { return otherSide_; }  // overlaid stream, empty when none or switched off
    void setOtherSideShown(bool shown);
    void setTimeController(TimeController* controller);

    QCustomPlot* plot(int angle) const { return plots_.at(static_cast<std::size_t>(angle)); }
    QCPItemStraightLine* cursorLine(int angle) const { return cursors_.at(static_cast<std::size_t>(angle)); }
    // Root mean square of estimate − reference per angle (deg); empty without a reference.
    const std::vector<double>& rmse() const { return rmse_; }
    // Angles (deg) at the cursor, interpolated; NaN outside the stream.
    std::array<double, 3> valuesAt(double t) const;
    QString readoutText() const;

private:
    void refresh();
    void onCursorChanged(double t);
    void onRangeChanged(double begin, double end);
    void onPlotRange(int angle);
    void onPlotReleased(int angle, QMouseEvent* event);

    const Project* project_;
    TimeController* controller_ = nullptr;
    QComboBox* streamCombo_ = nullptr;
    QCheckBox* otherSideBox_ = nullptr;
    QLabel* readout_ = nullptr;
    QLabel* note_ = nullptr;
    std::array<QCustomPlot*, 3> plots_{};
    std::array<QCPItemStraightLine*, 3> cursors_{};
    QString reference_, otherSide_;
    std::vector<double> t_;
    std::array<std::vector<double>, 3> deg_;  // estimate in degrees
    std::vector<double> rmse_;
    bool syncing_ = false;
    QPoint pressPos_;
};

}  // namespace athlos::ui
