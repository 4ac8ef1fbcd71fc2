#pragma once
// "Calibrate LPS": initial beacon table (from the project or a CSV) on the venue drawing, the
// calibration walk, lps-calibration through the Workspace, before/after residuals and the walk,
// then accept or retry (retry removes the result items again), optional alignment to venue marks
// (lps-align) and saving under a chosen name.
#include "core/processing/ParameterSpec.h"
#include "core/processing/ProcessorRunner.h"

#include <QStringList>
#include <QWizard>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QLabel;
class QLineEdit;

namespace athlos::ui {

class ParameterForm;
class VenuePlot;
class Workspace;

class LpsCalibrationWizard : public QWizard {
    Q_OBJECT

public:
    enum PageId { BeaconsPage, WalkPage, ResultPage, SavePage };

    // Empty specs = look the processors up in the registry.
    explicit LpsCalibrationWizard(Workspace& workspace, QWidget* parent = nullptr, ParameterSpecs calibrationSpecs = {},
                                  ParameterSpecs alignSpecs = {});
    ~LpsCalibrationWizard() override;

    // Imports a beacon CSV into the project as `target` ("rec/item") and selects it.
    bool importBeacons(const QString& file, const QString& target);
    RunRequest calibrationRequest() const;
    // Items the last calibration wrote (calibrated table, report, walk positions).
    const QStringList& resultItems() const { return written_; }
    QString lastError() const { return error_; }
    VenuePlot* beaconView() const { return beaconView_; }
    VenuePlot* resultView() const { return resultView_; }
    QCustomPlot* residualPlot() const { return residualPlot_; }

public slots:
    // Discards the result (removes its items from the project) and returns to the walk page.
    void retry();
    void reject() override;

protected:
    bool validateCurrentPage() override;
    void initializePage(int id) override;

private:
    QWizardPage* createBeaconsPage();
    QWizardPage* createWalkPage();
    QWizardPage* createResultPage();
    QWizardPage* createSavePage();
    void fillBeaconCombo();
    void showInitialBeacons();
    void discardResult();
    bool runCalibration();
    void showResult();
    bool save();
    QString reportPath() const;

    Workspace& workspace_;
    ParameterSpecs calibrationSpecs_;
    ParameterSpecs alignSpecs_;
    QStringList written_;
    QString calibrated_;
    QString error_;
    bool saved_ = false;

    QComboBox* beaconCombo_ = nullptr;
    QComboBox* trackCombo_ = nullptr;
    VenuePlot* beaconView_ = nullptr;
    QComboBox* tdoaCombo_ = nullptr;
    ParameterForm* calibrationForm_ = nullptr;
    QCheckBox* walkCheck_ = nullptr;
    QLineEdit* outputEdit_ = nullptr;
    QLabel* walkError_ = nullptr;
    QLabel* summary_ = nullptr;
    QCustomPlot* residualPlot_ = nullptr;
    VenuePlot* resultView_ = nullptr;
    QCheckBox* alignCheck_ = nullptr;
    QLineEdit* marksEdit_ = nullptr;
    QComboBox* modeCombo_ = nullptr;
    QLineEdit* saveEdit_ = nullptr;
    QLabel* saveError_ = nullptr;
};

}  // namespace athlos::ui
