#pragma once
// An orientation stream (qw..qz) as Euler angles in degrees over time, in a chosen axis sequence
// (core/math's decomposition), and, when the recording has a reference (kind "reference" with
// qw..qz), the error against it (total, heading, inclination; core/math's OrientationError) with
// each RMS in the legend, so the numbers match what the evaluation tools report.
#include "core/math/OrientationError.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>

class QComboBox;
class QCustomPlot;
class QLabel;

namespace athlos {
class Project;
}

namespace athlos::ui {

class OrientationAnglesView : public QWidget {
    Q_OBJECT

public:
    explicit OrientationAnglesView(const Project* project, QWidget* parent = nullptr);

    // Streams with columns qw, qx, qy, qz and kind "orientation".
    static QStringList orientationStreams(const Project& project);
    // A stream of kind "reference" with qw..qz in the same recording, or empty.
    static QString referenceFor(const Project& project, const QString& path);

    Status setStream(const QString& path);
    void setSequence(const QString& sequence);  // "ZYX", "XYZ", "zyx", …
    QString stream() const;
    QString sequence() const;

    QCustomPlot* anglePlot() const { return anglePlot_; }
    QCustomPlot* errorPlot() const { return errorPlot_; }
    // RMS of the plotted error (count 0 without a reference).
    const math::ErrorRms& errorRms() const { return rms_; }

private:
    void refresh();

    const Project* project_;
    QComboBox* streamCombo_ = nullptr;
    QComboBox* sequenceCombo_ = nullptr;
    QLabel* note_ = nullptr;
    QCustomPlot* anglePlot_ = nullptr;
    QCustomPlot* errorPlot_ = nullptr;
    math::ErrorRms rms_;
};

}  // namespace athlos::ui
