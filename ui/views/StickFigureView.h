#pragma once
// 3D stick figure of a body-com result (issue #18 item 7): the joint centres (kind joint-centres, relative to the
// lumbar joint centre in ENU axes) drawn as bones in an orthographic projection that the mouse rotates (drag:
// azimuth and elevation), the centre of mass as a dot with its trajectory over ±1 s around the cursor, synced to
// the window's TimeController. By default the view turns with the pelvis' heading (from the hip joints), so the
// athlete is seen from the side whatever the direction of travel.
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>
#include <array>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;

namespace athlos {
class Project;
}

namespace athlos::ui {

class TimeController;

class StickFigureCanvas;

class StickFigureView : public QWidget {
    Q_OBJECT

public:
    explicit StickFigureView(const Project* project, QWidget* parent = nullptr);

    // body-com joint streams (kind joint-centres whose attribute origin is the lumbar joint centre).
    static QStringList jointStreams(const Project& project);
    Status setStream(const QString& path);
    QString stream() const;
    void setTimeController(TimeController* controller);

    // The sample shown (the last at or before the cursor), -1 without data.
    long long currentSample() const { return current_; }
    std::size_t sampleCount() const { return t_.size(); }
    // The view: azimuth (rad, about the vertical, added to the pelvis heading when following it) and elevation.
    void setViewAngles(double azimuth, double elevation);
    double azimuth() const { return azimuth_; }
    double elevation() const { return elevation_; }
    void setFollowHeading(bool follow);
    // Screen coordinates (before scaling: m to the right and up) of a point given relative to the lumbar joint.
    QPointF project(const math::Vec3& p) const;
    math::Vec3 joint(int j) const;  // of the current sample
    math::Vec3 com() const;         // of the current sample (NaN without a CoM stream)
    QString readoutText() const;
    QWidget* canvas() const;

private:
    friend class StickFigureCanvas;
    void refresh();
    void onCursorChanged(double t);
    double heading() const;  // pelvis heading of the current sample (rad), 0 when not following

    const Project* project_;
    TimeController* controller_ = nullptr;
    QComboBox* streamCombo_ = nullptr;
    QCheckBox* follow_ = nullptr;
    QLabel* readout_ = nullptr;
    StickFigureCanvas* canvas_ = nullptr;
    std::vector<double> t_;
    std::vector<std::array<math::Vec3, 15>> joints_;
    std::vector<math::Vec3> com_;
    std::vector<double> foreAft_;
    long long current_ = -1;
    double azimuth_ = 0.0, elevation_ = 0.2;
    bool followHeading_ = true;
};

}  // namespace athlos::ui
