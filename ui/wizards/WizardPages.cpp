#include "ui/wizards/WizardPages.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRegistry.h"

#include <QComboBox>
#include <QLabel>
#include <QWizardPage>
#include <cmath>

namespace athlos::ui {

QWizardPage* wizardPage(const QString& title, const QString& subTitle) {
    auto* page = new QWizardPage;
    page->setTitle(title);
    if (!subTitle.isEmpty()) page->setSubTitle(subTitle);
    return page;
}

QComboBox* streamCombo(const Project* project, const QString& kind, const QString& objectName, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(objectName);
    if (project)
        for (const QString& path : project->streamPaths())
            if (project->stream(path)->kind() == kind) combo->addItem(path);
    return combo;
}

QComboBox* trackCombo(const Project* project, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("trackCombo"));
    combo->addItems(TrackGeometry::builtinNames());
    if (project)
        for (const auto& [name, json] : project->geometry())
            if (json.value(QStringLiteral("type")).toString().startsWith(QLatin1String("track-"))) combo->addItem(name);
    return combo;
}

Expected<TrackGeometry> resolveTrack(const Project* project, const QString& name) {
    return project ? TrackGeometry::resolve(project->geometry(), name) : TrackGeometry::builtin(name);
}

QLabel* errorLabel(const QString& objectName, QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #b00020"));
    return label;
}

ParameterSpecs registeredParameters(const QString& id) {
    auto processor = ProcessorRegistry::instance().find(id);
    return processor ? processor->parameters() : ParameterSpecs{};
}

void appendPlanarPositions(const Stream& stream, QVector<double>& x, QVector<double>& y, std::size_t maxRows) {
    const int cx = stream.info().columnIndex(QStringLiteral("x")), cy = stream.info().columnIndex(QStringLiteral("y"));
    auto data = stream.data();
    if (cx < 0 || cy < 0 || !data) return;
    const StreamData& d = **data;
    const std::size_t stride = maxRows > 0 ? d.rows() / maxRows + 1 : 1;
    for (std::size_t k = 0; k < d.rows(); k += stride) {
        if (!std::isfinite(d.at(k, cx)) || !std::isfinite(d.at(k, cy))) continue;
        x.append(d.at(k, cx));
        y.append(d.at(k, cy));
    }
}

}  // namespace athlos::ui
