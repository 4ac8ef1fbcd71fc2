#pragma once
// Page set-up the wizards share (LpsCalibrationWizard, PositionFilterWizard): pages with their
// titles, the stream and track choosers, the error label, the parameters of a registered processor,
// and the planar positions of a stream for the venue plots. Callers pass translated texts, so every
// string keeps the translation context of the wizard that shows it.
#include "core/geometry/TrackGeometry.h"
#include "core/processing/ParameterSpec.h"

#include <QString>
#include <QVector>
#include <cstddef>

class QComboBox;
class QLabel;
class QWidget;
class QWizardPage;

namespace athlos {
class Project;
class Stream;
}  // namespace athlos

namespace athlos::ui {

// A new wizard page with its (translated) title and subtitle.
QWizardPage* wizardPage(const QString& title, const QString& subTitle = {});

// A combo box (named objectName) listing the project's streams of the given kind.
QComboBox* streamCombo(const Project* project, const QString& kind, const QString& objectName, QWidget* parent);

// A combo box named "trackCombo" listing the built-in tracks and the project's track-* geometries.
QComboBox* trackCombo(const Project* project, QWidget* parent);

// The track of that name: the project's geometry, or a built-in when there is no project.
Expected<TrackGeometry> resolveTrack(const Project* project, const QString& name);

// A word-wrapped red label for the messages that keep a page from finishing.
QLabel* errorLabel(const QString& objectName, QWidget* parent);

// The parameters of the registered processor `id`; empty when its plugin is not loaded.
ParameterSpecs registeredParameters(const QString& id);

// Appends the finite (x, y) of a stream with columns x and y: every row, or with maxRows > 0 every
// (rows / maxRows + 1)-th row (a preview). A stream without them (or unreadable) adds nothing.
void appendPlanarPositions(const Stream& stream, QVector<double>& x, QVector<double>& y, std::size_t maxRows = 0);

}  // namespace athlos::ui
