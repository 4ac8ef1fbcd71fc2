#include "ui/wizards/TrainClassifierWizard.h"

#include "core/model/Project.h"
#include "plugins/activity/ActivityTraining.h"
#include "ui/PlotStyle.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/wizards/WizardPages.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QPointer>
#include <QRegularExpression>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent>
#include <qcustomplot.h>
#include <cmath>
#include <limits>
#include <set>

namespace athlos::ui {

using namespace activity;

struct TrainClassifierWizard::Result {
    QString error;  // empty: success
    QString text;   // summary and metrics, as `athlos train` prints them
    std::optional<Evaluation> evaluation;
    std::optional<ActivityModel> model;
};

namespace {

QStringList checkedItems(const QListWidget* list) {
    QStringList out;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->checkState() == Qt::Checked) out << list->item(i)->text();
    return out;
}

void addCheckable(QListWidget* list, const QString& text) {
    auto* item = new QListWidgetItem(text, list);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
}

bool isTrainable(const Annotation& a) { return activity::isGroundTruth(a) && a.tEnd > a.tStart; }

// The streams of a recording that the stream field names: a name, or a wildcard pattern (sim-imu-*).
bool matchesStream(const Recording& rec, const QString& stream) {
    if (!stream.contains(QLatin1Char('*')) && !stream.contains(QLatin1Char('?'))) return rec.streams.count(stream);
    const QRegularExpression glob(QRegularExpression::wildcardToRegularExpression(stream));
    for (const auto& [name, s] : rec.streams)
        if (glob.match(name).hasMatch()) return true;
    return false;
}

// The whole training as `athlos train` runs it, on the worker: dataset, cross-validation, final model.
std::shared_ptr<TrainClassifierWizard::Result> train(std::vector<TrainingSource> sources, TrainingOptions options,
                                                     Progress progress) {
    auto r = std::make_shared<TrainClassifierWizard::Result>();
    auto dataset = buildDataset(sources, options, progress.sub(0.0, 0.2));
    if (!dataset) {
        r->error = dataset.message();
        return r;
    }
    r->text = QCoreApplication::translate("athlos::ui::TrainClassifierWizard",
                                          "%1 windows from %2 recordings, %3 features, classes: %4\n")
                  .arg(dataset->labels.size())
                  .arg(sources.size())
                  .arg(dataset->features.size())
                  .arg(dataset->classes.join(QStringLiteral(", ")));
    if (dataset->segmentation.detectionTree) r->text += dataset->segmentation.detectionTree->summary();
    if (options.validation != QLatin1String("none")) {
        auto groups = foldGroups(*dataset, sources, options);
        if (!groups) {
            r->error = groups.message();
            return r;
        }
        auto evaluation = crossValidate(*dataset, *groups, options, progress.sub(0.2, 0.85));
        if (!evaluation) {
            r->error = evaluation.message();
            return r;
        }
        r->text += QStringLiteral("cross-validation (%1, %2):\n%3")
                       .arg(options.validation, options.classifier.kind, evaluation->toText());
        r->evaluation = std::move(*evaluation);
    }
    if (progress.isCancelled()) {
        r->error = QStringLiteral("cancelled");
        return r;
    }
    auto model = trainModel(*dataset, options, progress.sub(0.85, 1.0));
    if (!model) {
        r->error = model.message();
        return r;
    }
    if (model->selection)
        r->text += QCoreApplication::translate("athlos::ui::TrainClassifierWizard",
                                               "the %1 features of highest mutual information with the class:\n")
                       .arg(model->selection->size()) +
                   model->selection->toText(20);
    else
        r->text += QCoreApplication::translate("athlos::ui::TrainClassifierWizard",
                                               "features of highest mutual information with the class:\n") +
                   rankFeatures(*dataset, options).toText(10);
    QJsonArray training;
    for (const TrainingSource& s : sources)
        training.append(QJsonObject{{QStringLiteral("recording"), s.recording},
                                    {QStringLiteral("stream"), s.info.name},
                                    {QStringLiteral("athlete"), s.athlete},
                                    {QStringLiteral("content_hash"), QString::fromLatin1(s.data->contentHash())}});
    model->provenance[QStringLiteral("parameters")] = trainingParameters(options);
    model->provenance[QStringLiteral("training")] = training;
    if (options.interaction) model->provenance[QStringLiteral("interaction_streams")] = interactionStreams(sources);
    model->provenance[QStringLiteral("windows")] = double(dataset->labels.size());
    model->provenance[QStringLiteral("cross_validation")] =
        r->evaluation ? r->evaluation->toJson() : QJsonObject{{QStringLiteral("scheme"), QStringLiteral("none")}};
    model->provenance[QStringLiteral("created")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    model->provenance[QStringLiteral("trained_in")] = QStringLiteral("gui");
    r->model = std::move(*model);
    progress.report(1.0);
    return r;
}

}  // namespace

TrainClassifierWizard::TrainClassifierWizard(Workspace& workspace, QWidget* parent)
    : QWizard(parent), workspace_(workspace) {
    setWindowTitle(tr("Train classifier"));
    setPage(DataPage, createDataPage());
    setPage(SettingsPage, createSettingsPage());
    setPage(EvaluationPage, createEvaluationPage());
    setPage(SavePage, createSavePage());
    connect(&watcher_, &QFutureWatcher<std::shared_ptr<Result>>::finished, this, &TrainClassifierWizard::onFinished);
}

TrainClassifierWizard::~TrainClassifierWizard() {
    cancel_.cancel();
    watcher_.waitForFinished();
}

QWizardPage* TrainClassifierWizard::createDataPage() {
    auto* page = wizardPage(tr("Recordings and classes"),
                            tr("Recordings with the stream and ground-truth annotations (manual or imported) to "
                               "learn from, and the labels to learn."));
    streamCombo_ = new QComboBox(page);
    streamCombo_->setObjectName(QStringLiteral("streamCombo"));
    // Every IMU stream name, and for a team session (several IMU streams with an athlete attribute in
    // one recording, as simulate-rugby writes) the pattern of their common prefix: one source per player.
    std::set<QString> names;
    if (const Project* project = workspace_.project())
        for (const auto& [name, rec] : project->recordings()) {
            QStringList athletes;
            for (const auto& [stream, s] : rec.streams) {
                if (s.info().kind != QLatin1String("imu")) continue;
                names.insert(stream);
                if (s.info().attributes.contains(QStringLiteral("athlete"))) athletes << stream;
            }
            if (athletes.size() < 2) continue;
            QString prefix = athletes.front();
            for (const QString& a : athletes)
                while (!a.startsWith(prefix)) prefix.chop(1);
            if (!prefix.isEmpty()) names.insert(prefix + QLatin1Char('*'));
        }
    for (const QString& n : names) streamCombo_->addItem(n);
    streamCombo_->setEditable(true);
    streamCombo_->setToolTip(
        tr("A stream name, or a pattern such as sim-imu-* (every matching stream of a "
           "recording is trained on: one per player of a team session)."));
    recordingList_ = new QListWidget(page);
    recordingList_->setObjectName(QStringLiteral("recordingList"));
    classList_ = new QListWidget(page);
    classList_->setObjectName(QStringLiteral("classList"));
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Stream:"), streamCombo_);
    layout->addRow(tr("Recordings:"), recordingList_);
    layout->addRow(tr("Classes:"), classList_);
    connect(streamCombo_, &QComboBox::currentTextChanged, this, &TrainClassifierWizard::fillRecordings);
    fillRecordings();
    return page;
}

void TrainClassifierWizard::fillRecordings() {
    recordingList_->clear();
    classList_->clear();
    const Project* project = workspace_.project();
    if (!project) return;
    std::set<QString> labels;
    for (const auto& [name, rec] : project->recordings()) {
        if (!matchesStream(rec, streamCombo_->currentText())) continue;
        bool annotated = false;
        for (const Annotation& a : rec.annotations)
            if (isTrainable(a)) {
                labels.insert(a.label);
                annotated = true;
            }
        if (annotated) addCheckable(recordingList_, name);
    }
    for (const QString& l : labels) addCheckable(classList_, l);
}

QWizardPage* TrainClassifierWizard::createSettingsPage() {
    auto* page = wizardPage(tr("Windows and classifier"),
                            tr("Sliding windows for continuous activities, or windows around detected events for "
                               "discrete actions; the classifier and how it is cross-validated."));
    window_ = new QDoubleSpinBox(page);
    window_->setObjectName(QStringLiteral("windowSpin"));
    window_->setRange(0.1, 3600.0);
    window_->setValue(3.0);
    window_->setSuffix(QStringLiteral(" s"));
    step_ = new QDoubleSpinBox(page);
    step_->setObjectName(QStringLiteral("stepSpin"));
    step_->setRange(0.05, 3600.0);
    step_->setValue(1.5);
    step_->setSuffix(QStringLiteral(" s"));
    segmentationCombo_ = new QComboBox(page);
    segmentationCombo_->setObjectName(QStringLiteral("segmentationCombo"));
    segmentationCombo_->addItems(Segmentation::kinds());
    classifierCombo_ = new QComboBox(page);
    classifierCombo_->setObjectName(QStringLiteral("classifierCombo"));
    classifierCombo_->addItems(Classifier::kinds());
    validationCombo_ = new QComboBox(page);
    validationCombo_->setObjectName(QStringLiteral("validationCombo"));
    validationCombo_->addItems({QStringLiteral("leave-one-athlete-out"), QStringLiteral("leave-one-recording-out"),
                                QStringLiteral("k-fold"), QStringLiteral("none")});
    // As `athlos train --balance`: the values are the CLI's, the labels explain them.
    balanceCombo_ = new QComboBox(page);
    balanceCombo_->setObjectName(QStringLiteral("balanceCombo"));
    balanceCombo_->addItem(tr("Oversample smaller classes"), QStringLiteral("oversample"));
    balanceCombo_->addItem(tr("SMOTE (synthetic windows)"), QStringLiteral("smote"));
    balanceCombo_->addItem(tr("None"), QStringLiteral("none"));
    balanceCombo_->setToolTip(tr("Class balancing of the training windows (athlos train --balance)."));
    selectFeatures_ = new QSpinBox(page);
    selectFeatures_->setObjectName(QStringLiteral("selectFeaturesSpin"));
    selectFeatures_->setRange(0, 10000);
    selectFeatures_->setValue(0);
    selectFeatures_->setSpecialValueText(tr("all"));
    selectFeatures_->setToolTip(
        tr("Keep the K features of highest mutual information with the class, ranked "
           "inside each cross-validation fold (athlos train --select-features K)."));
    interaction_ = new QSpinBox(page);
    interaction_->setObjectName(QStringLiteral("interactionSpin"));
    interaction_->setRange(0, 20);
    interaction_->setValue(0);
    interaction_->setSpecialValueText(tr("none"));
    interaction_->setEnabled(false);
    interaction_->setToolTip(
        tr("Multi-athlete interaction features of detected events (athlos train --interaction k=K): the player's "
           "torso pitch and speed and the distance, speed and torso pitch of the K nearest opponents, from the "
           "other athletes' IMU and positions streams of the recording (athlete and team attributes)."));
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Window:"), window_);
    layout->addRow(tr("Step:"), step_);
    layout->addRow(tr("Segmentation:"), segmentationCombo_);
    layout->addRow(tr("Classifier:"), classifierCombo_);
    layout->addRow(tr("Cross-validation:"), validationCombo_);
    layout->addRow(tr("Class balancing:"), balanceCombo_);
    layout->addRow(tr("Features (mutual information):"), selectFeatures_);
    layout->addRow(tr("Nearest opponents (interaction features):"), interaction_);
    connect(segmentationCombo_, &QComboBox::currentTextChanged, this, [this](const QString& kind) {
        step_->setEnabled(kind == QLatin1String("sliding"));
        interaction_->setEnabled(kind != QLatin1String("sliding"));
    });
    return page;
}

QWizardPage* TrainClassifierWizard::createEvaluationPage() {
    auto* page = wizardPage(tr("Cross-validation"),
                            tr("Trained on a worker; the confusion matrix shows the share of each annotated class "
                               "(rows) predicted as each class (columns)."));
    progressBar_ = new QProgressBar(page);
    progressBar_->setObjectName(QStringLiteral("progressBar"));
    progressBar_->setRange(0, 1000);
    cancelButton_ = new QPushButton(tr("Cancel training"), page);
    cancelButton_->setObjectName(QStringLiteral("cancelTrainingButton"));
    metrics_ = new QPlainTextEdit(page);
    metrics_->setObjectName(QStringLiteral("metricsText"));
    metrics_->setReadOnly(true);
    metrics_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    confusionPlot_ = new QCustomPlot(page);
    confusionPlot_->setObjectName(QStringLiteral("confusionPlot"));
    PlotStyle::apply(confusionPlot_);
    confusionPlot_->setMinimumSize(360, 300);
    auto* bar = new QHBoxLayout;
    bar->addWidget(progressBar_, 1);
    bar->addWidget(cancelButton_);
    auto* body = new QHBoxLayout;
    body->addWidget(metrics_, 1);
    body->addWidget(confusionPlot_, 1);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(bar);
    layout->addLayout(body, 1);
    connect(cancelButton_, &QPushButton::clicked, this, &TrainClassifierWizard::cancelTraining);
    return page;
}

QWizardPage* TrainClassifierWizard::createSavePage() {
    auto* page = wizardPage(tr("Save"), tr("The model trained on every window is stored in the project; classify "
                                           "with Processing → Classify actions."));
    page->setFinalPage(true);
    nameEdit_ = new QLineEdit(QStringLiteral("activities"), page);
    nameEdit_->setObjectName(QStringLiteral("nameEdit"));
    saveError_ = errorLabel(QStringLiteral("saveError"), page);
    auto* layout = new QFormLayout(page);
    layout->addRow(tr("Model name:"), nameEdit_);
    layout->addRow(saveError_);
    return page;
}

void TrainClassifierWizard::initializePage(int id) {
    if (id == EvaluationPage) startTraining();
    QWizard::initializePage(id);
}

bool TrainClassifierWizard::validateCurrentPage() {
    // One class is enough with event segmentation (chosen on the next page): the detector's other events are
    // the null class; a sliding-window training with one class is refused with its reason by the training.
    if (currentId() == DataPage) return !checkedItems(recordingList_).isEmpty() && !checkedItems(classList_).isEmpty();
    if (currentId() == EvaluationPage) return !watcher_.isRunning() && result_ && result_->model;
    if (currentId() == SavePage) return saveModel();
    return QWizard::validateCurrentPage();
}

void TrainClassifierWizard::startTraining() {
    if (watcher_.isRunning()) return;
    result_.reset();
    metrics_->clear();
    confusionPlot_->clearPlottables();
    confusionPlot_->replot();
    const Project* project = workspace_.project();
    if (!project) return;
    auto sources = trainingSources(*project, streamCombo_->currentText(), checkedItems(recordingList_));
    if (!sources) {
        metrics_->setPlainText(sources.message());
        emit evaluationFinished(false);
        return;
    }
    TrainingOptions options;
    options.window = window_->value();
    options.step = step_->value();
    options.classes = checkedItems(classList_);
    options.classifier.kind = classifierCombo_->currentText();
    options.validation = validationCombo_->currentText();
    const QString balance = balanceCombo_->currentData().toString();
    options.classifier.balance = balance != QLatin1String("none");
    options.classifier.smote = balance == QLatin1String("smote");
    options.selectFeatures = selectFeatures_->value();
    auto segmentation = Segmentation::parse(segmentationCombo_->currentText());
    if (segmentation) options.segmentation = *segmentation;
    if (options.segmentation.events() && !options.classes.contains(options.segmentation.nullLabel))
        options.classes << options.segmentation.nullLabel;
    if (options.segmentation.events() && interaction_->value() > 0) {
        InteractionOptions interaction;
        interaction.neighbours = interaction_->value();
        options.interaction = interaction;
        // The other athletes' streams, gathered here as classify-actions gathers them (once per recording).
        if (Status s = attachInteraction(*project, *sources, interaction); !s) {
            metrics_->setPlainText(s.message());
            emit evaluationFinished(false);
            return;
        }
    }
    cancel_ = CancelToken();
    QPointer<QProgressBar> bar = progressBar_;
    Progress progress(
        [bar](double f, const QString&) {
            QMetaObject::invokeMethod(
                bar,
                [bar, f] {
                    if (bar) bar->setValue(int(1000 * f));
                },
                Qt::QueuedConnection);
        },
        cancel_);
    progressBar_->setValue(0);
    cancelButton_->setEnabled(true);
    metrics_->setPlainText(tr("Training…"));
    watcher_.setFuture(QtConcurrent::run(train, std::move(*sources), options, progress));
}

void TrainClassifierWizard::cancelTraining() { cancel_.cancel(); }

void TrainClassifierWizard::onFinished() {
    result_ = watcher_.result();
    cancelButton_->setEnabled(false);
    const bool ok = result_ && result_->error.isEmpty() && result_->model;
    if (!ok) {
        const QString error = result_ ? result_->error : QString();
        metrics_->setPlainText(error == QLatin1String("cancelled") ? tr("Cancelled.") : error);
    } else {
        progressBar_->setValue(1000);
        metrics_->setPlainText(result_->text);
        showConfusion();
    }
    emit evaluationFinished(ok);
}

void TrainClassifierWizard::showConfusion() {
    confusionPlot_->clearPlottables();
    if (!result_ || !result_->evaluation) {
        confusionPlot_->replot();
        return;
    }
    const Evaluation& e = *result_->evaluation;
    const int k = int(e.classes.size());
    auto* map = new QCPColorMap(confusionPlot_->xAxis, confusionPlot_->yAxis);
    map->data()->setSize(k, k);
    map->data()->setRange(QCPRange(0, k - 1), QCPRange(0, k - 1));
    for (int truth = 0; truth < k; ++truth) {
        long long row = 0;
        for (long long v : e.confusion[std::size_t(truth)]) row += v;
        for (int predicted = 0; predicted < k; ++predicted)
            // Rows from the top: class 0 first, as the printed matrix.
            map->data()->setCell(
                predicted, k - 1 - truth,
                row ? double(e.confusion[std::size_t(truth)][std::size_t(predicted)]) / double(row) : 0.0);
    }
    map->setGradient(QCPColorGradient::gpHot);
    map->setDataRange(QCPRange(0, 1));
    map->setInterpolate(false);
    QSharedPointer<QCPAxisTickerText> xTicks(new QCPAxisTickerText), yTicks(new QCPAxisTickerText);
    for (int c = 0; c < k; ++c) {
        xTicks->addTick(c, e.classes[c]);
        yTicks->addTick(k - 1 - c, e.classes[c]);
    }
    confusionPlot_->xAxis->setTicker(xTicks);
    confusionPlot_->yAxis->setTicker(yTicks);
    confusionPlot_->xAxis->setTickLabelRotation(60);
    confusionPlot_->xAxis->setLabel(tr("predicted"));
    confusionPlot_->yAxis->setLabel(tr("annotated"));
    confusionPlot_->xAxis->setRange(-0.5, k - 0.5);
    confusionPlot_->yAxis->setRange(-0.5, k - 0.5);
    confusionPlot_->replot();
}

bool TrainClassifierWizard::saveModel() {
    Project* project = workspace_.project();
    const QString name = nameEdit_->text().trimmed();
    QString error;
    if (!project || !result_ || !result_->model)
        error = tr("There is no trained model to save.");
    else if (name.isEmpty() || name.contains(QLatin1Char('/')) || name == QLatin1String(".") ||
             name == QLatin1String(".."))
        error = tr("Give the model a name without '/'.");
    if (error.isEmpty()) {
        result_->model->provenance[QStringLiteral("input")] = streamCombo_->currentText();
        auto stored = result_->model->toStored(name);
        if (!stored) {
            error = stored.message();
        } else {
            project->models()[name] = std::move(*stored);
            project->setModified();
            workspace_.projectModified();
        }
    }
    saveError_->setText(error);
    return error.isEmpty();
}

QString TrainClassifierWizard::metricsText() const { return metrics_->toPlainText(); }

double TrainClassifierWizard::balancedAccuracy() const {
    return result_ && result_->evaluation ? result_->evaluation->balancedAccuracy
                                          : std::numeric_limits<double>::quiet_NaN();
}

bool TrainClassifierWizard::hasModel() const { return result_ && result_->model.has_value(); }

namespace {

void launchTrainClassifierWizard(Workspace& workspace) {
    auto* wizard = new TrainClassifierWizard(workspace, workspace.window());
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->open();
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("train-classifier-wizard"), QT_TRANSLATE_NOOP("Tools", "Train classifier…"),
                      QT_TRANSLATE_NOOP("Tools", "Processing"), launchTrainClassifierWizard});

}  // namespace athlos::ui
