#include "ui/wizards/LpsCalibrationWizard.h"

#include "core/geometry/TrackGeometry.h"
#include "core/io/Importer.h"
#include "core/model/Project.h"
#include "ui/ParameterForm.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/venue/VenuePlot.h"
#include "ui/wizards/WizardPages.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <qcustomplot.h>

namespace athlos::ui {

namespace {

const QString kCalibration = QStringLiteral("lps-calibration");
const QString kPositioning = QStringLiteral("lps-positioning");
const QString kAlign = QStringLiteral("lps-align");
const QColor kInitialColor(150, 150, 150);
const QColor kCalibratedColor(0, 114, 178);

QString recordingOf(const QString& path) { return ItemPath::parse(path).recording; }

}  // namespace

LpsCalibrationWizard::LpsCalibrationWizard(Workspace& workspace, QWidget* parent, ParameterSpecs calibrationSpecs,
                                           ParameterSpecs alignSpecs)
    : QWizard(parent),
      workspace_(workspace),
      calibrationSpecs_(calibrationSpecs.isEmpty() ? registeredParameters(kCalibration) : std::move(calibrationSpecs)),
      alignSpecs_(alignSpecs.isEmpty() ? registeredParameters(kAlign) : std::move(alignSpecs)) {
    setWindowTitle(tr("Calibrate LPS"));
    setPage(BeaconsPage, createBeaconsPage());
    setPage(WalkPage, createWalkPage());
    setPage(ResultPage, createResultPage());
    setPage(SavePage, createSavePage());
}

LpsCalibrationWizard::~LpsCalibrationWizard() = default;

QWizardPage* LpsCalibrationWizard::createBeaconsPage() {
    auto* page =
        wizardPage(tr("Initial beacon positions"),
                   tr("Rough positions (a few metres are fine) from the project or a CSV file (id, x, y, z)."));
    beaconCombo_ = new QComboBox(page);
    beaconCombo_->setObjectName(QStringLiteral("beaconCombo"));
    auto* import = new QPushButton(tr("Import CSV…"), page);
    import->setObjectName(QStringLiteral("importButton"));
    trackCombo_ = trackCombo(workspace_.project(), page);
    beaconView_ = new VenuePlot(page);
    beaconView_->setMinimumSize(420, 300);
    fillBeaconCombo();

    auto* row = new QHBoxLayout;
    row->addWidget(beaconCombo_, 1);
    row->addWidget(import);
    auto* form = new QFormLayout;
    form->addRow(tr("Beacon table:"), row);
    form->addRow(tr("Venue drawing:"), trackCombo_);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(beaconView_, 1);

    connect(beaconCombo_, &QComboBox::currentTextChanged, this, &LpsCalibrationWizard::showInitialBeacons);
    connect(trackCombo_, &QComboBox::currentTextChanged, this, &LpsCalibrationWizard::showInitialBeacons);
    connect(import, &QPushButton::clicked, this, [this] {
        const QString file =
            QFileDialog::getOpenFileName(this, tr("Import beacon table"), {}, tr("CSV files (*.csv *.txt)"));
        if (file.isEmpty()) return;
        const QString rec =
            tdoaCombo_->currentText().isEmpty() ? QStringLiteral("venue") : recordingOf(tdoaCombo_->currentText());
        importBeacons(file, rec + QStringLiteral("/") + QFileInfo(file).completeBaseName());
    });
    return page;
}

void LpsCalibrationWizard::fillBeaconCombo() {
    const QSignalBlocker blocker(beaconCombo_);
    const QString current = beaconCombo_->currentText();
    beaconCombo_->clear();
    if (const Project* project = workspace_.project())
        for (const QString& path : project->tablePaths())
            if (project->table(path)->kind == QLatin1String("beacons")) beaconCombo_->addItem(path);
    if (!current.isEmpty()) beaconCombo_->setCurrentText(current);
}

bool LpsCalibrationWizard::importBeacons(const QString& file, const QString& target) {
    Project* project = workspace_.project();
    if (!project) return false;
    ImportOptions options;
    options.format = QStringLiteral("csv");
    options.kind = QStringLiteral("beacons");
    options.target = target;
    auto imported = importFile(file, options);
    Status applied = imported ? applyImport(*project, std::move(*imported), false) : Status(imported.error());
    if (!applied) {
        error_ = applied.message();
        return false;
    }
    workspace_.projectModified();
    fillBeaconCombo();
    beaconCombo_->setCurrentText(target);
    showInitialBeacons();
    return true;
}

void LpsCalibrationWizard::showInitialBeacons() {
    const Project* project = workspace_.project();
    if (!project) return;
    auto track = TrackGeometry::resolve(project->geometry(), trackCombo_->currentText());
    if (track) beaconView_->setTrack(*track);
    // The drawn venue is the track the calibration's gauge fit uses, unless the user edits it there.
    if (calibrationForm_ && calibrationForm_->editor(QStringLiteral("track")))
        calibrationForm_->setValue(QStringLiteral("track"), trackCombo_->currentText());
    if (const Table* table = project->table(beaconCombo_->currentText()))
        beaconView_->setBeacons(tr("initial"), *table, kInitialColor);
    else
        beaconView_->removeBeacons(tr("initial"));
    beaconView_->refit();
}

QWizardPage* LpsCalibrationWizard::createWalkPage() {
    auto* page =
        wizardPage(tr("Calibration walk"),
                   tr("The TDoA recording of the walk and the calibration settings. Next runs the calibration."));
    tdoaCombo_ = streamCombo(workspace_.project(), QStringLiteral("lps-tdoa"), QStringLiteral("tdoaCombo"), page);
    calibrationForm_ = new ParameterForm(calibrationSpecs_, ParameterForm::NumberStyle::Text, page);
    calibrationForm_->setObjectName(QStringLiteral("calibrationForm"));
    walkCheck_ = new QCheckBox(tr("Show the walk positions (runs lps-positioning with the calibrated beacons)"), page);
    walkCheck_->setObjectName(QStringLiteral("walkCheck"));
    walkCheck_->setChecked(true);
    outputEdit_ = new QLineEdit(page);
    outputEdit_->setObjectName(QStringLiteral("outputEdit"));
    auto setDefaultOutput = [this] {
        outputEdit_->setText(recordingOf(tdoaCombo_->currentText()) + QStringLiteral("/beacons-calibrated"));
    };
    setDefaultOutput();
    walkError_ = errorLabel(QStringLiteral("walkError"), page);

    auto* scroll = new QScrollArea(page);
    scroll->setWidget(calibrationForm_);
    scroll->setWidgetResizable(true);
    auto* form = new QFormLayout;
    form->addRow(tr("TDoA stream:"), tdoaCombo_);
    form->addRow(tr("Output (rec/table):"), outputEdit_);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(scroll, 1);
    layout->addWidget(walkCheck_);
    layout->addWidget(walkError_);
    if (calibrationSpecs_.isEmpty())
        layout->addWidget(
            new QLabel(tr("The lps-calibration processor was not found; check the plugin folder."), page));
    connect(tdoaCombo_, &QComboBox::currentTextChanged, this, setDefaultOutput);
    return page;
}

QWizardPage* LpsCalibrationWizard::createResultPage() {
    auto* page = wizardPage(tr("Calibration result"),
                            tr("Next keeps the result; Retry discards it so you can change the settings."));
    summary_ = new QLabel(page);
    summary_->setObjectName(QStringLiteral("summaryLabel"));
    summary_->setWordWrap(true);
    residualPlot_ = new QCustomPlot(page);
    residualPlot_->setObjectName(QStringLiteral("residualPlot"));
    PlotStyle::apply(residualPlot_);
    residualPlot_->setMinimumSize(300, 220);
    residualPlot_->yAxis->setLabel(tr("RMS residual [m]"));
    residualPlot_->legend->setVisible(true);
    resultView_ = new VenuePlot(page);
    resultView_->setMinimumSize(300, 220);
    auto* retryButton = new QPushButton(tr("Retry with other settings"), page);
    retryButton->setObjectName(QStringLiteral("retryButton"));
    auto* plots = new QHBoxLayout;
    plots->addWidget(residualPlot_, 1);
    plots->addWidget(resultView_, 1);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(summary_);
    layout->addLayout(plots, 1);
    layout->addWidget(retryButton, 0, Qt::AlignLeft);
    connect(retryButton, &QPushButton::clicked, this, &LpsCalibrationWizard::retry);
    return page;
}

QWizardPage* LpsCalibrationWizard::createSavePage() {
    auto* page =
        wizardPage(tr("Align and save"),
                   tr("Optionally move the beacons so that surveyed venue marks land on their known coordinates."));
    page->setFinalPage(true);
    alignCheck_ = new QCheckBox(tr("Align to venue marks (lps-align)"), page);
    alignCheck_->setObjectName(QStringLiteral("alignCheck"));
    marksEdit_ = new QLineEdit(page);
    marksEdit_->setObjectName(QStringLiteral("marksEdit"));
    marksEdit_->setPlaceholderText(QStringLiteral("x,y,z>X,Y,Z; x,y,z>X,Y,Z"));
    modeCombo_ = new QComboBox(page);
    modeCombo_->setObjectName(QStringLiteral("modeCombo"));
    for (const ParameterSpec& spec : alignSpecs_) {
        if (spec.name == QLatin1String("marks")) marksEdit_->setToolTip(spec.help);
        if (spec.name == QLatin1String("mode")) {
            modeCombo_->addItems(spec.choices);
            modeCombo_->setCurrentText(spec.defaultValue.toString());
            modeCombo_->setToolTip(spec.help);
        }
    }
    if (modeCombo_->count() == 0) modeCombo_->addItems({QStringLiteral("yaw"), QStringLiteral("full")});
    saveEdit_ = new QLineEdit(page);
    saveEdit_->setObjectName(QStringLiteral("saveEdit"));
    saveError_ = errorLabel(QStringLiteral("saveError"), page);
    auto* layout = new QFormLayout(page);
    layout->addRow(alignCheck_);
    layout->addRow(tr("Marks:"), marksEdit_);
    layout->addRow(tr("Mode:"), modeCombo_);
    layout->addRow(tr("Save as (rec/table):"), saveEdit_);
    layout->addRow(saveError_);
    auto enable = [this] {
        marksEdit_->setEnabled(alignCheck_->isChecked());
        modeCombo_->setEnabled(alignCheck_->isChecked());
    };
    connect(alignCheck_, &QCheckBox::toggled, this, enable);
    enable();
    return page;
}

void LpsCalibrationWizard::initializePage(int id) {
    if (id == BeaconsPage) showInitialBeacons();
    if (id == SavePage && saveEdit_->text().isEmpty()) saveEdit_->setText(calibrated_);
    QWizard::initializePage(id);
}

RunRequest LpsCalibrationWizard::calibrationRequest() const {
    return RunRequest{kCalibration,
                      {tdoaCombo_->currentText(), beaconCombo_->currentText()},
                      outputEdit_->text().trimmed(),
                      calibrationForm_->values()};
}

QString LpsCalibrationWizard::reportPath() const {
    for (const QString& path : written_)
        if (path.endsWith(QLatin1String("-report"))) return path;
    return {};
}

bool LpsCalibrationWizard::validateCurrentPage() {
    switch (currentId()) {
        case BeaconsPage:
            return !beaconCombo_->currentText().isEmpty();
        case WalkPage:
            return runCalibration();
        case SavePage:
            return save();
        default:
            return QWizard::validateCurrentPage();
    }
}

void LpsCalibrationWizard::discardResult() {
    Project* project = workspace_.project();
    if (written_.isEmpty() || !project) return;
    for (const QString& path : std::as_const(written_)) project->removeItem(path);
    written_.clear();
    calibrated_.clear();
    workspace_.projectModified();
}

void LpsCalibrationWizard::retry() {
    discardResult();
    if (currentId() == ResultPage) back();
}

void LpsCalibrationWizard::reject() {
    // Leaving without accepting keeps the project as it was before the wizard ran anything.
    if (!saved_) discardResult();
    QWizard::reject();
}

bool LpsCalibrationWizard::runCalibration() {
    // Coming back with Back instead of Retry: the earlier result is replaced, not stacked.
    discardResult();
    error_.clear();
    const RunRequest request = calibrationRequest();
    const Project* project = workspace_.project();
    if (tdoaCombo_->currentText().isEmpty())
        error_ = tr("Choose the TDoA stream of the calibration walk.");
    else if (!ItemPath::parse(request.output).isValid())
        error_ = tr("The output must be named rec/table.");
    else if (project && (project->table(request.output) || project->stream(request.output)))
        error_ = tr("'%1' already exists; choose another name.").arg(request.output);
    else if (!calibrationForm_->errors().isEmpty())
        error_ = calibrationForm_->errors().join(QLatin1Char('\n'));
    if (error_.isEmpty()) {
        auto outcome = workspace_.runProcessor(request);
        if (!outcome) {
            error_ = outcome.message();
        } else {
            written_ = outcome->written;
            calibrated_ = request.output;
            if (walkCheck_->isChecked()) {
                const RunRequest walk{kPositioning,
                                      {request.inputs.front(), request.output},
                                      request.output + QStringLiteral("-walk"),
                                      {}};
                auto positioned = workspace_.runProcessor(walk);
                // The walk is a view aid: its failure does not invalidate the calibration.
                if (positioned)
                    written_ += positioned->written;
                else
                    summary_->setToolTip(positioned.message());
            }
        }
    }
    walkError_->setText(error_);
    if (error_.isEmpty()) showResult();
    return error_.isEmpty();
}

void LpsCalibrationWizard::showResult() {
    const Project* project = workspace_.project();
    if (!project) return;
    const Table* initial = project->table(beaconCombo_->currentText());
    const Table* calibrated = project->table(calibrated_);
    const Table* report = project->table(reportPath());

    auto track = TrackGeometry::resolve(project->geometry(), trackCombo_->currentText());
    if (track) resultView_->setTrack(*track);
    if (initial) resultView_->setBeacons(tr("initial"), *initial, kInitialColor);
    if (calibrated) resultView_->setBeacons(tr("calibrated"), *calibrated, kCalibratedColor);
    QVector<double> wx, wy;
    for (const QString& path : std::as_const(written_))
        if (const Stream* stream = project->stream(path); stream && stream->kind() == QLatin1String("lps-position"))
            appendPlanarPositions(*stream, wx, wy);
    resultView_->setWalk(wx, wy);

    // Residual bars: every residual column of the report (before/after when the report has both).
    residualPlot_->clearPlottables();
    QString text;
    if (report) {
        const TableColumn* ids = report->column(QStringLiteral("id"));
        QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
        QVector<double> keys;
        for (int i = 0; i < report->rows(); ++i) {
            keys.append(i + 1);
            ticker->addTick(i + 1, ids && ids->isText ? ids->texts.value(i) : QString::number(i + 1));
        }
        residualPlot_->xAxis->setTicker(ticker);
        QList<const TableColumn*> residuals;
        for (const TableColumn& column : report->columns)
            if (!column.isText && column.name.contains(QLatin1String("residual"))) residuals.append(&column);
        auto* group = new QCPBarsGroup(residualPlot_);
        for (int c = 0; c < residuals.size(); ++c) {
            auto* bars = new QCPBars(residualPlot_->xAxis, residualPlot_->yAxis);
            bars->setName(residuals[c]->name);
            bars->setWidth(0.8 / std::max<qsizetype>(1, residuals.size()));
            const QColor color = residuals.size() > 1 && c == 0 ? kInitialColor : kCalibratedColor;
            bars->setPen(QPen(color.darker(130)));
            bars->setBrush(color);
            bars->setData(keys, QVector<double>(residuals[c]->numbers.begin(), residuals[c]->numbers.end()));
            bars->setBarsGroup(group);
        }
        residualPlot_->rescaleAxes();
        residualPlot_->xAxis->setRange(0.3, report->rows() + 0.7);
        residualPlot_->yAxis->setRangeLower(0.0);
        const QJsonObject a = report->attributes;
        text = tr("nRMSR before: %1 m, after: %2 m; %3 fixes used, %4 removed; converged: %5")
                   .arg(a.value(QStringLiteral("nrmsr_initial")).toDouble(), 0, 'f', 3)
                   .arg(a.value(QStringLiteral("nrmsr_calibrated")).toDouble(), 0, 'f', 3)
                   .arg(a.value(QStringLiteral("fixes_used")).toInt())
                   .arg(a.value(QStringLiteral("fixes_removed")).toInt())
                   .arg(a.value(QStringLiteral("converged")).toBool() ? tr("yes") : tr("no"));
    }
    residualPlot_->replot();
    summary_->setText(text);
}

bool LpsCalibrationWizard::save() {
    error_.clear();
    Project* project = workspace_.project();
    const QString target = saveEdit_->text().trimmed();
    if (!project || calibrated_.isEmpty())
        error_ = tr("There is no calibration result to save.");
    else if (!ItemPath::parse(target).isValid())
        error_ = tr("The name must be rec/table.");
    else if (target != calibrated_ && (project->table(target) || project->stream(target)))
        error_ = tr("'%1' already exists; choose another name.").arg(target);
    else if (alignCheck_->isChecked()) {
        if (target == calibrated_)
            error_ = tr("The aligned table needs a name of its own.");
        else {
            const RunRequest align{kAlign,
                                   {calibrated_},
                                   target,
                                   {{QStringLiteral("marks"), marksEdit_->text().trimmed()},
                                    {QStringLiteral("mode"), modeCombo_->currentText()}}};
            auto outcome = workspace_.runProcessor(align);
            if (!outcome) error_ = outcome.message();
        }
    } else if (target != calibrated_) {
        // Renaming keeps the table's provenance: it is the same calibration under another name.
        Table table = *project->table(calibrated_);
        project->putTable(target, std::move(table));
        project->removeItem(calibrated_);
        workspace_.projectModified();
    }
    saveError_->setText(error_);
    if (error_.isEmpty()) saved_ = true;
    return error_.isEmpty();
}

namespace {

void launchLpsCalibrationWizard(Workspace& workspace) {
    auto* wizard = new LpsCalibrationWizard(workspace, workspace.window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->open();
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("lps-calibration-wizard"), QT_TRANSLATE_NOOP("Tools", "Calibrate LPS…"),
                      QT_TRANSLATE_NOOP("Tools", "Positioning"), launchLpsCalibrationWizard});

}  // namespace athlos::ui
