#include "ui/wizards/FunctionalCalibrationWizard.h"

#include "core/model/Project.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/wizards/WizardPages.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace athlos::ui {

namespace {

const QString kProcessor = QStringLiteral("functional-calibration");

QTableWidget* resultTable(const QString& objectName, QWidget* parent) {
    auto* table = new QTableWidget(parent);
    table->setObjectName(objectName);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->setVisible(false);
    table->horizontalHeader()->setStretchLastSection(true);
    return table;
}

QString degrees(double radians) {
    return std::isfinite(radians) ? QString::number(radians * 180.0 / std::numbers::pi, 'f', 2) : QStringLiteral("–");
}

}  // namespace

FunctionalCalibrationWizard::FunctionalCalibrationWizard(Workspace& workspace, QWidget* parent)
    : QWizard(parent), workspace_(workspace) {
    setWindowTitle(tr("Functional calibration"));
    setPage(SensorPage, createSensorPage());
    setPage(ResultPage, createResultPage());
    fillStreams();
}

QStringList FunctionalCalibrationWizard::segments() {
    // The lower body and trunk first (their order is the wizard's since the beginning), then the upper body.
    return {QStringLiteral("sacrum"),         QStringLiteral("sternum"),         QStringLiteral("right-thigh"),
            QStringLiteral("right-shank"),    QStringLiteral("right-foot"),      QStringLiteral("left-thigh"),
            QStringLiteral("left-shank"),     QStringLiteral("left-foot"),       QStringLiteral("upper-back"),
            QStringLiteral("head"),           QStringLiteral("right-upper-arm"), QStringLiteral("right-forearm"),
            QStringLiteral("left-upper-arm"), QStringLiteral("left-forearm")};
}

QWizardPage* FunctionalCalibrationWizard::createSensorPage() {
    auto* page = wizardPage(
        tr("Recording and sensors"),
        tr("The recording of the protocol: standing upright still (10 s) with the arms hanging, 3 squats, 3 trunk "
           "rotations, 3 hip ab/adductions per leg and, for arm sensors, 3 arm swings holding a pole horizontally, "
           "standing still for a moment between movements. Choose the IMU of each segment (leave out those without a "
           "sensor). Next finds the movements and calibrates."));
    auto* layout = new QFormLayout(page);
    recordingCombo_ = new QComboBox(page);
    recordingCombo_->setObjectName(QStringLiteral("recordingCombo"));
    if (const Project* project = workspace_.project())
        for (const auto& [name, recording] : project->recordings())
            for (const auto& [streamName, stream] : recording.streams)
                if (stream.kind() == QLatin1String("imu")) {
                    recordingCombo_->addItem(name);
                    break;
                }
    layout->addRow(tr("Recording:"), recordingCombo_);
    for (const QString& segment : segments()) {
        auto* combo = new QComboBox(page);
        combo->setObjectName(segment + QStringLiteral("Combo"));
        segmentCombos_.append(combo);
        layout->addRow(segment + QLatin1Char(':'), combo);
    }
    outputEdit_ = new QLineEdit(page);
    outputEdit_->setObjectName(QStringLiteral("outputEdit"));
    layout->addRow(tr("Output (rec/table):"), outputEdit_);
    errorLabel_ = errorLabel(QStringLiteral("errorLabel"), page);
    layout->addRow(errorLabel_);
    if (recordingCombo_->count() == 0)
        layout->addRow(new QLabel(tr("This project has no IMU stream; import the recording first."), page));
    connect(recordingCombo_, &QComboBox::currentTextChanged, this, &FunctionalCalibrationWizard::fillStreams);
    return page;
}

QWizardPage* FunctionalCalibrationWizard::createResultPage() {
    auto* page = wizardPage(tr("Movements and quality"),
                            tr("The movements found and, per segment, the dispersion χ of the functional axis between "
                               "repetitions, its angle to the horizontal plane, the angle between axes that should "
                               "be orthogonal and the CMC of the repetitions. Finish keeps the calibration; Back "
                               "discards it."));
    page->setFinalPage(true);
    movements_ = resultTable(QStringLiteral("movementTable"), page);
    quality_ = resultTable(QStringLiteral("qualityTable"), page);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(new QLabel(tr("Movements:"), page));
    layout->addWidget(movements_, 1);
    layout->addWidget(new QLabel(tr("Quality per segment:"), page));
    layout->addWidget(quality_, 1);
    return page;
}

void FunctionalCalibrationWizard::fillStreams() {
    const QString rec = recordingCombo_->currentText();
    outputEdit_->setText(rec.isEmpty() ? QString() : rec + QStringLiteral("/functional-calibration"));
    QStringList streams;
    const Project* project = workspace_.project();
    if (project && project->recordings().count(rec))
        for (const auto& [name, stream] : project->recordings().at(rec).streams)
            if (stream.kind() == QLatin1String("imu")) streams << name;
    const QStringList names = segments();
    for (int i = 0; i < segmentCombos_.size(); ++i) {
        QComboBox* combo = segmentCombos_[i];
        combo->clear();
        combo->addItem(tr("(none)"), QString());
        for (const QString& s : streams) combo->addItem(s, s);
        // Streams named after the segment ("imu-right-thigh", "right-thigh"); the sacrum also takes
        // "pelvis" or a lone "imu" (simulate-body's naming).
        int match = 0;
        for (int k = 0; k < streams.size() && match == 0; ++k) {
            const QString& s = streams[k];
            if (s == names[i] || s.endsWith(QLatin1Char('-') + names[i])) match = k + 1;
            if (names[i] == QLatin1String("sacrum") &&
                (s == QLatin1String("pelvis") || s.endsWith(QLatin1String("-pelvis"))))
                match = k + 1;
        }
        if (match == 0 && names[i] == QLatin1String("sacrum") && streams.contains(QStringLiteral("imu")))
            match = int(streams.indexOf(QStringLiteral("imu"))) + 1;
        combo->setCurrentIndex(match);
    }
}

RunRequest FunctionalCalibrationWizard::request() const {
    RunRequest r;
    r.processorId = kProcessor;
    const QString rec = recordingCombo_->currentText();
    QStringList names;
    const QStringList all = segments();
    for (int i = 0; i < segmentCombos_.size(); ++i) {
        const QString stream = segmentCombos_[i]->currentData().toString();
        if (stream.isEmpty()) continue;
        r.inputs << rec + QLatin1Char('/') + stream;
        names << all[i];
    }
    r.output = outputEdit_->text().trimmed();
    r.parameters.insert(QStringLiteral("segments"), names.join(QLatin1Char(',')));
    return r;
}

bool FunctionalCalibrationWizard::validateCurrentPage() {
    if (currentId() == SensorPage) return runCalibration();
    return QWizard::validateCurrentPage();
}

void FunctionalCalibrationWizard::cleanupPage(int id) {
    // Back from the result: the calibration is discarded and run again on Next.
    if (id == ResultPage) discardResult();
    QWizard::cleanupPage(id);
}

void FunctionalCalibrationWizard::reject() {
    discardResult();
    QWizard::reject();
}

void FunctionalCalibrationWizard::discardResult() {
    Project* project = workspace_.project();
    if (written_.isEmpty() || !project) return;
    for (const QString& path : std::as_const(written_)) project->removeItem(path);
    written_.clear();
    workspace_.projectModified();
}

bool FunctionalCalibrationWizard::runCalibration() {
    discardResult();
    error_.clear();
    const RunRequest r = request();
    const Project* project = workspace_.project();
    if (r.inputs.isEmpty())
        error_ = tr("Choose the IMU stream of at least one segment.");
    else if (!ItemPath::parse(r.output).isValid())
        error_ = tr("The output must be named rec/table.");
    else if (project && (project->table(r.output) || project->stream(r.output)))
        error_ = tr("'%1' already exists; choose another name.").arg(r.output);
    if (error_.isEmpty()) {
        auto outcome = workspace_.runProcessor(r);
        if (!outcome)
            error_ = outcome.message();
        else {
            written_ = outcome->written;
            showResult();
        }
    }
    errorLabel_->setText(error_);
    return error_.isEmpty();
}

void FunctionalCalibrationWizard::showResult() {
    const Project* project = workspace_.project();
    const QString out = outputEdit_->text().trimmed();
    const Table* moves = project ? project->table(out + QStringLiteral("-movements")) : nullptr;
    const Table* quality = project ? project->table(out + QStringLiteral("-quality")) : nullptr;
    movements_->clear();
    quality_->clear();
    if (moves) {
        const TableColumn* name = moves->column(QStringLiteral("movement"));
        const TableColumn* rep = moves->column(QStringLiteral("repetition"));
        const TableColumn* begin = moves->column(QStringLiteral("begin"));
        const TableColumn* end = moves->column(QStringLiteral("end"));
        const TableColumn* given = moves->column(QStringLiteral("given"));
        if (name && rep && begin && end && given) {
            movements_->setColumnCount(4);
            movements_->setHorizontalHeaderLabels({tr("Movement"), tr("Repetition"), tr("From [s]"), tr("To [s]")});
            movements_->setRowCount(int(name->size()));
            for (int i = 0; i < int(name->size()); ++i) {
                const auto k = std::size_t(i);
                const QString label = name->texts.at(i) + (given->numbers[k] > 0.5 ? tr(" (marked)") : QString());
                movements_->setItem(i, 0, new QTableWidgetItem(label));
                movements_->setItem(
                    i, 1, new QTableWidgetItem(rep->numbers[k] > 0.5 ? QString::number(rep->numbers[k]) : tr("all")));
                movements_->setItem(i, 2, new QTableWidgetItem(QString::number(begin->numbers[k], 'f', 2)));
                movements_->setItem(i, 3, new QTableWidgetItem(QString::number(end->numbers[k], 'f', 2)));
            }
        }
    }
    if (quality) {
        const QStringList columns{QStringLiteral("segment"),
                                  QStringLiteral("movement"),
                                  QStringLiteral("dispersion"),
                                  QStringLiteral("orthogonality"),
                                  QStringLiteral("cross_orthogonality"),
                                  QStringLiteral("cmc")};
        std::vector<const TableColumn*> cols;
        for (const QString& c : columns) cols.push_back(quality->column(c));
        if (std::all_of(cols.begin(), cols.end(), [](const TableColumn* c) { return c != nullptr; })) {
            quality_->setColumnCount(6);
            quality_->setHorizontalHeaderLabels({tr("Segment"), tr("Movement"), tr("χ [°]"), tr("Orthogonality [°]"),
                                                 tr("Second axis [°]"), tr("CMC")});
            const int rows = int(cols[0]->size());
            quality_->setRowCount(rows);
            for (int i = 0; i < rows; ++i) {
                const auto k = std::size_t(i);
                quality_->setItem(i, 0, new QTableWidgetItem(cols[0]->texts.at(i)));
                quality_->setItem(i, 1, new QTableWidgetItem(cols[1]->texts.at(i)));
                quality_->setItem(i, 2, new QTableWidgetItem(degrees(cols[2]->numbers[k])));
                quality_->setItem(i, 3, new QTableWidgetItem(degrees(cols[3]->numbers[k])));
                quality_->setItem(i, 4, new QTableWidgetItem(degrees(cols[4]->numbers[k])));
                quality_->setItem(i, 5, new QTableWidgetItem(QString::number(cols[5]->numbers[k], 'f', 3)));
            }
        }
    }
    movements_->resizeColumnsToContents();
    quality_->resizeColumnsToContents();
}

namespace {

void launchFunctionalCalibrationWizard(Workspace& workspace) {
    auto* wizard = new FunctionalCalibrationWizard(workspace, workspace.window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    QObject::connect(wizard, &QWizard::accepted, wizard, [wizard, &workspace] {
        const QString output = wizard->request().output;
        if (workspace.project() && workspace.project()->table(output)) workspace.showItem(output);
    });
    wizard->open();
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("functional-calibration-wizard"),
                      QT_TRANSLATE_NOOP("Tools", "Functional calibration…"), QT_TRANSLATE_NOOP("Tools", "Processing"),
                      launchFunctionalCalibrationWizard});

}  // namespace athlos::ui
