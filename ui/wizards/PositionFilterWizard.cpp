#include "ui/wizards/PositionFilterWizard.h"

#include "core/model/Project.h"
#include "ui/ParameterForm.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/venue/EqualAspectFrame.h"
#include "ui/venue/TrackOverlay.h"
#include "ui/views/TrackTrajectoryView.h"
#include "ui/wizards/WizardPages.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <qcustomplot.h>
#include <cmath>
#include <numbers>

namespace athlos::ui {

namespace {

const QString kProcessor = QStringLiteral("position-filter");

// Manual noise settings: the processor's q_* (process), r_* (measurement) and gate parameters.
bool isNoiseParameter(const QString& name) {
    return name.startsWith(QLatin1String("q_")) || name.startsWith(QLatin1String("r_")) ||
           name == QLatin1String("gate");
}

const ParameterSpec* findSpec(const ParameterSpecs& specs, const QString& name) {
    for (const ParameterSpec& spec : specs)
        if (spec.name == name) return &spec;
    return nullptr;
}

QComboBox* choiceCombo(const ParameterSpecs& specs, const QString& name, const QStringList& fallback, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setObjectName(name + QStringLiteral("Combo"));
    const ParameterSpec* spec = findSpec(specs, name);
    combo->addItems(spec ? spec->choices : fallback);
    if (spec) {
        combo->setCurrentText(spec->defaultValue.toString());
        combo->setToolTip(spec->help);
    }
    return combo;
}

QDoubleSpinBox* spinBox(const QString& objectName, double min, double max, double value, int decimals,
                        const QString& suffix, QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(objectName);
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

}  // namespace

PositionFilterWizard::PositionFilterWizard(Workspace& workspace, QWidget* parent, ParameterSpecs specs)
    : QWizard(parent),
      workspace_(workspace),
      specs_(specs.isEmpty() ? registeredParameters(kProcessor) : std::move(specs)) {
    setWindowTitle(tr("Filter positions"));
    setPage(InputPage, createInputPage());
    setPage(TrackPage, createTrackPage());
    setPage(FilterPage, createFilterPage());
    setPage(OutputPage, createOutputPage());
    setPage(ResultPage, createResultPage());
    updateEnabled();
}

PositionFilterWizard::~PositionFilterWizard() = default;

QWizardPage* PositionFilterWizard::createInputPage() {
    auto* page = wizardPage(tr("Position stream"), tr("The LPS fixes (kind lps-position, columns x and y) to filter."));
    streamCombo_ =
        streamCombo(workspace_.project(), QStringLiteral("lps-position"), QStringLiteral("streamCombo"), page);
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Stream:"), streamCombo_);
    if (streamCombo_->count() == 0)
        layout->addRow(new QLabel(tr("This project has no lps-position stream; import one first."), page));
    connect(streamCombo_, &QComboBox::currentTextChanged, this, [this] {
        loadRawPositions();
        outputEdit_->setText(streamCombo_->currentText() + QStringLiteral("-filtered"));
    });
    return page;
}

QWizardPage* PositionFilterWizard::createTrackPage() {
    auto* page = wizardPage(tr("Track and pose"),
                            tr("Place the track over the raw positions: the track models follow its lanes."));
    trackCombo_ = trackCombo(workspace_.project(), page);
    trackX_ = spinBox(QStringLiteral("trackX"), -1e5, 1e5, 0.0, 2, QStringLiteral(" m"), page);
    trackY_ = spinBox(QStringLiteral("trackY"), -1e5, 1e5, 0.0, 2, QStringLiteral(" m"), page);
    trackRotation_ = spinBox(QStringLiteral("trackRotation"), -180.0, 180.0, 0.0, 2, QStringLiteral(" °"), page);
    trackRotation_->setWrapping(true);
    auto* fit = new QPushButton(tr("Fit pose"), page);
    fit->setObjectName(QStringLiteral("fitPoseButton"));
    fit->setToolTip(tr("Centre the track on the positions and turn it along their longest extent."));

    posePlot_ = new QCustomPlot(page);
    posePlot_->setObjectName(QStringLiteral("posePlot"));
    PlotStyle::apply(posePlot_);
    posePlot_->setMinimumSize(420, 300);
    posePlot_->legend->setVisible(false);  // grey dots and lane lines explain themselves
    posePlot_->xAxis->setLabel(tr("x [m]"));
    posePlot_->yAxis->setLabel(tr("y [m]"));
    rawCurve_ = new QCPCurve(posePlot_->xAxis, posePlot_->yAxis);
    rawCurve_->setLineStyle(QCPCurve::lsNone);
    rawCurve_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(150, 150, 150), 3));
    overlay_ = std::make_unique<TrackOverlay>(posePlot_);
    aspect_ = new EqualAspectFrame(posePlot_);
    posePlot_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);

    auto* form = new QFormLayout;
    form->addRow(tr("Track:"), trackCombo_);
    form->addRow(tr("Origin x:"), trackX_);
    form->addRow(tr("Origin y:"), trackY_);
    form->addRow(tr("Rotation:"), trackRotation_);
    form->addRow(fit);
    auto* layout = new QHBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(posePlot_, 1);

    connect(trackCombo_, &QComboBox::currentTextChanged, this, &PositionFilterWizard::onTrackChosen);
    for (QDoubleSpinBox* box : {trackX_, trackY_, trackRotation_})
        connect(box, &QDoubleSpinBox::valueChanged, this, &PositionFilterWizard::updateOverlay);
    connect(fit, &QPushButton::clicked, this, &PositionFilterWizard::fitPose);
    return page;
}

QWizardPage* PositionFilterWizard::createFilterPage() {
    auto* page = wizardPage(tr("Filter and noise"), tr("Kalman filter variant, motion model and noise settings."));
    filterCombo_ = choiceCombo(specs_, QStringLiteral("filter"), {"ekf", "ukf", "srukf"}, page);
    modelCombo_ = choiceCombo(specs_, QStringLiteral("model"), {"unconstrained", "pseudo", "augmented"}, page);
    noiseCombo_ = choiceCombo(specs_, QStringLiteral("noise"), {"auto", "manual"}, page);
    ParameterSpecs noiseSpecs;
    for (const ParameterSpec& spec : specs_)
        if (isNoiseParameter(spec.name)) noiseSpecs.append(spec);
    noiseForm_ = new ParameterForm(noiseSpecs, ParameterForm::NumberStyle::Text, page);
    noiseForm_->setObjectName(QStringLiteral("noiseForm"));
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Filter:"), filterCombo_);
    layout->addRow(tr("Motion model:"), modelCombo_);
    layout->addRow(tr("Noise:"), noiseCombo_);
    layout->addRow(noiseForm_);
    if (specs_.isEmpty())
        layout->addRow(new QLabel(tr("The position-filter processor was not found; check the plugin folder."), page));
    connect(noiseCombo_, &QComboBox::currentTextChanged, this, &PositionFilterWizard::updateEnabled);
    return page;
}

QWizardPage* PositionFilterWizard::createOutputPage() {
    auto* page = wizardPage(tr("Smoothing and output"), tr("Next runs the filter."));
    smootherCombo_ = choiceCombo(specs_, QStringLiteral("smoother"), {"none", "rts", "fixed-lag"}, page);
    const ParameterSpec* lagSpec = findSpec(specs_, QStringLiteral("lag"));
    lag_ = spinBox(QStringLiteral("lagSpin"), 0.01, 60.0, lagSpec ? lagSpec->defaultValue.toDouble() : 0.5, 2,
                   QStringLiteral(" s"), page);
    rateCheck_ = new QCheckBox(tr("Resample to a uniform rate"), page);
    rateCheck_->setObjectName(QStringLiteral("rateCheck"));
    rate_ = spinBox(QStringLiteral("rateSpin"), 0.1, 1000.0, 10.0, 1, QStringLiteral(" Hz"), page);
    outputEdit_ = new QLineEdit(page);
    outputEdit_->setObjectName(QStringLiteral("outputEdit"));
    outputEdit_->setText(streamCombo_->currentText() + QStringLiteral("-filtered"));
    errorLabel_ = errorLabel(QStringLiteral("errorLabel"), page);
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Smoother:"), smootherCombo_);
    layout->addRow(tr("Lag:"), lag_);
    layout->addRow(rateCheck_, rate_);
    layout->addRow(tr("Output (rec/stream):"), outputEdit_);
    layout->addRow(errorLabel_);
    connect(smootherCombo_, &QComboBox::currentTextChanged, this, &PositionFilterWizard::updateEnabled);
    connect(rateCheck_, &QCheckBox::toggled, this, &PositionFilterWizard::updateEnabled);
    return page;
}

QWizardPage* PositionFilterWizard::createResultPage() {
    auto* page = wizardPage(tr("Result"));
    page->setFinalPage(true);
    resultView_ = new TrackTrajectoryView(page);
    resultView_->setMinimumSize(420, 320);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(resultView_);
    return page;
}

void PositionFilterWizard::initializePage(int id) {
    if (id == TrackPage) {
        if (rawX_.isEmpty()) loadRawPositions();
        if (overlay_->curves().isEmpty()) onTrackChosen();
    }
    QWizard::initializePage(id);
}

void PositionFilterWizard::loadRawPositions() {
    rawX_.clear();
    rawY_.clear();
    const Project* project = workspace_.project();
    // A preview: 20 k dots show the shape of any recording.
    if (const Stream* stream = project ? project->stream(streamCombo_->currentText()) : nullptr)
        appendPlanarPositions(*stream, rawX_, rawY_, 20000);
    rawCurve_->setData(rawX_, rawY_);
    updateOverlay();
}

void PositionFilterWizard::onTrackChosen() {
    auto track = resolveTrack(workspace_.project(), trackCombo_->currentText());
    if (track) {
        // The geometry's own pose is the starting point; the user adjusts from there.
        const QSignalBlocker bx(trackX_), by(trackY_), br(trackRotation_);
        trackX_->setValue(track->pose().x);
        trackY_->setValue(track->pose().y);
        trackRotation_->setValue(track->pose().rotation * 180.0 / std::numbers::pi);
    }
    updateOverlay();
}

TrackGeometry PositionFilterWizard::currentTrack() const {
    auto track = resolveTrack(workspace_.project(), trackCombo_->currentText());
    TrackGeometry geometry = track ? *track : TrackGeometry::iaaf400m();
    geometry.setPose({trackX_->value(), trackY_->value(), trackRotation_->value() * std::numbers::pi / 180.0});
    return geometry;
}

void PositionFilterWizard::updateOverlay() {
    overlay_->setTrack(currentTrack());
    if (aspect_->isFraming())
        aspect_->frameAll();
    else
        posePlot_->replot();
}

void PositionFilterWizard::fitPose() {
    if (rawX_.size() < 2) return;
    const auto [xMin, xMax] = std::minmax_element(rawX_.cbegin(), rawX_.cend());
    const auto [yMin, yMax] = std::minmax_element(rawY_.cbegin(), rawY_.cend());
    const double cx = 0.5 * (*xMin + *xMax), cy = 0.5 * (*yMin + *yMax);
    double sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < rawX_.size(); ++i) {
        const double dx = rawX_[i] - cx, dy = rawY_[i] - cy;
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    // Principal axis of the fixes = direction of the straights (up to 180°, which the oval does not see).
    double angle = 0.5 * std::atan2(2 * sxy, sxx - syy) * 180.0 / std::numbers::pi;
    const QSignalBlocker bx(trackX_), by(trackY_), br(trackRotation_);
    trackX_->setValue(cx);
    trackY_->setValue(cy);
    trackRotation_->setValue(angle);
    updateOverlay();
}

void PositionFilterWizard::updateEnabled() {
    noiseForm_->setVisible(noiseCombo_->currentText() == QLatin1String("manual"));
    lag_->setEnabled(smootherCombo_->currentText() == QLatin1String("fixed-lag"));
    rate_->setEnabled(rateCheck_->isChecked());
}

RunRequest PositionFilterWizard::request() const {
    RunRequest r;
    r.processorId = kProcessor;
    r.inputs = {streamCombo_->currentText()};
    r.output = outputEdit_->text().trimmed();
    QVariantMap& p = r.parameters;
    p.insert(QStringLiteral("filter"), filterCombo_->currentText());
    p.insert(QStringLiteral("model"), modelCombo_->currentText());
    p.insert(QStringLiteral("track"), trackCombo_->currentText());
    p.insert(QStringLiteral("track_x"), trackX_->value());
    p.insert(QStringLiteral("track_y"), trackY_->value());
    p.insert(QStringLiteral("track_rotation"), trackRotation_->value() * std::numbers::pi / 180.0);
    p.insert(QStringLiteral("noise"), noiseCombo_->currentText());
    if (noiseCombo_->currentText() == QLatin1String("manual")) p.insert(noiseForm_->values());
    p.insert(QStringLiteral("smoother"), smootherCombo_->currentText());
    if (smootherCombo_->currentText() == QLatin1String("fixed-lag")) p.insert(QStringLiteral("lag"), lag_->value());
    if (rateCheck_->isChecked()) p.insert(QStringLiteral("output_rate"), rate_->value());
    return r;
}

bool PositionFilterWizard::validateCurrentPage() {
    if (currentId() == InputPage && streamCombo_->currentText().isEmpty()) return false;
    if (currentId() == OutputPage) return runFilter();
    return QWizard::validateCurrentPage();
}

bool PositionFilterWizard::runFilter() {
    error_.clear();
    const RunRequest r = request();
    const Project* project = workspace_.project();
    if (!ItemPath::parse(r.output).isValid())
        error_ = tr("The output must be named rec/stream.");
    else if (project && (project->stream(r.output) || project->table(r.output)))
        error_ = tr("'%1' already exists; choose another name.").arg(r.output);
    else if (noiseCombo_->currentText() == QLatin1String("manual") && !noiseForm_->errors().isEmpty())
        error_ = noiseForm_->errors().join(QLatin1Char('\n'));
    if (error_.isEmpty()) {
        auto outcome = workspace_.runProcessor(r);
        if (!outcome)
            error_ = outcome.message();
        else if (Project* current = workspace_.project()) {
            if (Status shown = resultView_->setResult(*current, r.output); !shown) error_ = shown.message();
        }
    }
    errorLabel_->setText(error_);
    return error_.isEmpty();
}

namespace {

void launchPositionFilterWizard(Workspace& workspace) {
    auto* wizard = new PositionFilterWizard(workspace, workspace.window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(wizard, &QWizard::accepted, wizard, [wizard, &workspace] {
        const QString output = wizard->request().output;
        if (workspace.project() && workspace.project()->stream(output)) workspace.showItem(output);
    });
    wizard->open();
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("position-filter-wizard"), QT_TRANSLATE_NOOP("Tools", "Filter positions…"),
                      QT_TRANSLATE_NOOP("Tools", "Positioning"), launchPositionFilterWizard});

}  // namespace athlos::ui
