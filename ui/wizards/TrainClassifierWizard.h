#pragma once
// "Train classifier…": the GUI face of `athlos train` (same library calls, plugins/activity):
// recordings and classes from the project's annotations, window and segmentation, classifier, class
// balancing (oversample / SMOTE / none), mutual-information feature selection (K) and the multi-athlete
// interaction features of detected events (k nearest opponents, --interaction), and a
// cross-validation run on a worker thread (progress, Cancel) whose confusion matrix is shown as a
// heat map; Finish stores the model trained on every window in the project (/models/<name>).
#include "core/util/Progress.h"

#include <QFutureWatcher>
#include <QStringList>
#include <QWizard>
#include <memory>

class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace athlos::ui {

class Workspace;

class TrainClassifierWizard : public QWizard {
    Q_OBJECT

public:
    enum PageId { DataPage, SettingsPage, EvaluationPage, SavePage };
    struct Result;  // of the worker: metrics text, confusion, the trained model

    explicit TrainClassifierWizard(Workspace& workspace, QWidget* parent = nullptr);
    ~TrainClassifierWizard() override;

    // Widgets for tests.
    QComboBox* streamCombo() const { return streamCombo_; }
    QListWidget* recordingList() const { return recordingList_; }
    QListWidget* classList() const { return classList_; }
    QComboBox* classifierCombo() const { return classifierCombo_; }
    QComboBox* validationCombo() const { return validationCombo_; }
    QComboBox* segmentationCombo() const { return segmentationCombo_; }
    QComboBox* balanceCombo() const { return balanceCombo_; }
    QSpinBox* selectFeaturesSpin() const { return selectFeatures_; }
    QSpinBox* interactionSpin() const { return interaction_; }
    QDoubleSpinBox* windowSpin() const { return window_; }
    QDoubleSpinBox* stepSpin() const { return step_; }
    QLineEdit* nameEdit() const { return nameEdit_; }
    QCustomPlot* confusionPlot() const { return confusionPlot_; }
    QString metricsText() const;
    bool isRunning() const { return watcher_.isRunning(); }
    double balancedAccuracy() const;  // of the last cross-validation; NaN without one
    bool hasModel() const;

public slots:
    // Runs the training (and cross-validation) on a worker; evaluationFinished() when done.
    void startTraining();
    void cancelTraining();

signals:
    void evaluationFinished(bool ok);

protected:
    void initializePage(int id) override;
    bool validateCurrentPage() override;

private:
    QWizardPage* createDataPage();
    QWizardPage* createSettingsPage();
    QWizardPage* createEvaluationPage();
    QWizardPage* createSavePage();
    void fillRecordings();
    void onFinished();
    void showConfusion();
    bool saveModel();

    Workspace& workspace_;
    CancelToken cancel_;
    QFutureWatcher<std::shared_ptr<Result>> watcher_;
    std::shared_ptr<Result> result_;

    QComboBox* streamCombo_ = nullptr;
    QListWidget* recordingList_ = nullptr;
    QListWidget* classList_ = nullptr;
    QDoubleSpinBox* window_ = nullptr;
    QDoubleSpinBox* step_ = nullptr;
    QComboBox* segmentationCombo_ = nullptr;
    QComboBox* classifierCombo_ = nullptr;
    QComboBox* validationCombo_ = nullptr;
    QComboBox* balanceCombo_ = nullptr;
    QSpinBox* selectFeatures_ = nullptr;
    QSpinBox* interaction_ = nullptr;  // nearest opponents of the interaction features; 0: none
    QProgressBar* progressBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QPlainTextEdit* metrics_ = nullptr;
    QCustomPlot* confusionPlot_ = nullptr;
    QLineEdit* nameEdit_ = nullptr;
    QLabel* saveError_ = nullptr;
};

}  // namespace athlos::ui
