#pragma once
// "Filter positions": choose an LPS position stream, place the track over the raw fixes, pick
// filter, motion model, noise and smoothing, and run position-filter through the Workspace (so it
// runs exactly as `athlos run … position-filter` would). The last page shows the result on the track.
#include "core/geometry/TrackGeometry.h"
#include "core/processing/ParameterSpec.h"
#include "core/processing/ProcessorRunner.h"

#include <QVector>
#include <QWizard>
#include <memory>

class QCheckBox;
class QComboBox;
class QCPCurve;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace athlos::ui {

class EqualAspectFrame;
class ParameterForm;
class TrackOverlay;
class TrackTrajectoryView;
class Workspace;

class PositionFilterWizard : public QWizard {
    Q_OBJECT

public:
    enum PageId { InputPage, TrackPage, FilterPage, OutputPage, ResultPage };

    // specs: the processor's parameters; empty = look position-filter up in the registry.
    explicit PositionFilterWizard(Workspace& workspace, QWidget* parent = nullptr, ParameterSpecs specs = {});
    ~PositionFilterWizard() override;

    // The request the current settings describe.
    RunRequest request() const;
    TrackGeometry currentTrack() const;  // with the pose of the spin boxes
    QCustomPlot* posePlot() const { return posePlot_; }
    TrackOverlay* poseOverlay() const { return overlay_.get(); }
    TrackTrajectoryView* resultView() const { return resultView_; }
    QString lastError() const { return error_; }

public slots:
    // Places the track over the raw fixes: centre of their extent, rotation of their principal axis.
    void fitPose();

protected:
    bool validateCurrentPage() override;
    void initializePage(int id) override;

private:
    QWizardPage* createInputPage();
    QWizardPage* createTrackPage();
    QWizardPage* createFilterPage();
    QWizardPage* createOutputPage();
    QWizardPage* createResultPage();
    void loadRawPositions();
    void onTrackChosen();
    void updateOverlay();
    void updateEnabled();
    bool runFilter();

    Workspace& workspace_;
    ParameterSpecs specs_;
    QString error_;
    QVector<double> rawX_, rawY_;

    QComboBox* streamCombo_ = nullptr;
    QComboBox* trackCombo_ = nullptr;
    QDoubleSpinBox* trackX_ = nullptr;
    QDoubleSpinBox* trackY_ = nullptr;
    QDoubleSpinBox* trackRotation_ = nullptr;  // degrees in the UI, radians in the request
    QCustomPlot* posePlot_ = nullptr;
    QCPCurve* rawCurve_ = nullptr;
    std::unique_ptr<TrackOverlay> overlay_;
    EqualAspectFrame* aspect_ = nullptr;
    QComboBox* filterCombo_ = nullptr;
    QComboBox* modelCombo_ = nullptr;
    QComboBox* noiseCombo_ = nullptr;
    ParameterForm* noiseForm_ = nullptr;
    QComboBox* smootherCombo_ = nullptr;
    QDoubleSpinBox* lag_ = nullptr;
    QCheckBox* rateCheck_ = nullptr;
    QDoubleSpinBox* rate_ = nullptr;
    QLineEdit* outputEdit_ = nullptr;
    QLabel* errorLabel_ = nullptr;
    TrackTrajectoryView* resultView_ = nullptr;
};

}  // namespace athlos::ui
