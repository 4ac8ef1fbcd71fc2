#pragma once
// "Functional calibration…": pick the recording and the IMU stream of each segment, run
// functional-calibration through the Workspace (worker thread, progress and Cancel — exactly as
// `athlos run … functional-calibration` would), then see the movements it found and the quality per
// segment (dispersion χ, orthogonality, CMC). Finish keeps the tables; Back or Cancel removes them.
#include "core/processing/ProcessorRunner.h"

#include <QStringList>
#include <QWizard>

class QComboBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace athlos {
struct Table;
}

namespace athlos::ui {

class Workspace;

class FunctionalCalibrationWizard : public QWizard {
    Q_OBJECT

public:
    enum PageId { SensorPage, ResultPage };

    explicit FunctionalCalibrationWizard(Workspace& workspace, QWidget* parent = nullptr);

    // The protocol's segments, in the order of the combo boxes.
    static QStringList segments();
    // The request the current choices describe (segments without a stream are left out).
    RunRequest request() const;
    QComboBox* segmentCombo(int index) const { return segmentCombos_.value(index); }
    QComboBox* recordingCombo() const { return recordingCombo_; }
    QTableWidget* movementTable() const { return movements_; }
    QTableWidget* qualityTable() const { return quality_; }
    QString lastError() const { return error_; }

public slots:
    void reject() override;

protected:
    bool validateCurrentPage() override;
    void cleanupPage(int id) override;

private:
    QWizardPage* createSensorPage();
    QWizardPage* createResultPage();
    void fillStreams();
    bool runCalibration();
    void showResult();
    void discardResult();

    Workspace& workspace_;
    QString error_;
    QStringList written_;
    QComboBox* recordingCombo_ = nullptr;
    QList<QComboBox*> segmentCombos_;
    QLineEdit* outputEdit_ = nullptr;
    QLabel* errorLabel_ = nullptr;
    QTableWidget* movements_ = nullptr;
    QTableWidget* quality_ = nullptr;
};

}  // namespace athlos::ui
