#pragma once
// Processing → Run processor…: any registered processor, its inputs picked from the project's
// streams/tables of the accepted kinds, an output name and a form generated from its parameter
// schema. Runs through Workspace::runProcessor, so the GUI and `athlos run` share one code path.
// Pre-filled from a result's provenance it is "Re-run with changed parameters".
#include "core/processing/ProcessorRunner.h"

#include <QDialog>
#include <QList>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace athlos::ui {

class ParameterForm;
class Workspace;

class ProcessorDialog : public QDialog {
    Q_OBJECT

public:
    explicit ProcessorDialog(Workspace& workspace, QWidget* parent = nullptr);

    // Selects a processor by id; false if the registry has none with that id.
    bool selectProcessor(const QString& id);
    QString processorId() const;
    // Fills processor, inputs, output and parameters from a request (e.g. from provenance).
    bool setRequest(const RunRequest& request);
    // The request as currently entered (not validated).
    RunRequest request() const;
    // Checks output name and parameters without running; the message is also shown in the dialog.
    Status validate();
    // Validates and runs; on success the dialog is accepted. Errors stay in the dialog.
    Status run();

    QComboBox* processorBox() const { return processorBox_; }
    QComboBox* inputBox(int index) const { return inputBoxes_.value(index); }
    QLineEdit* outputEdit() const { return outputEdit_; }
    ParameterForm* parameterForm() const { return form_; }
    QString errorText() const;

    // The written outputs of the last successful run().
    QStringList written() const { return written_; }

private:
    void onProcessorChanged();
    void suggestOutput();
    void showError(const QString& message);

    Workspace& workspace_;
    QComboBox* processorBox_ = nullptr;
    QLabel* description_ = nullptr;
    QFormLayout* inputsLayout_ = nullptr;
    QList<QComboBox*> inputBoxes_;
    QLineEdit* outputEdit_ = nullptr;
    ParameterForm* form_ = nullptr;
    QLabel* error_ = nullptr;
    QStringList written_;
    bool outputEdited_ = false;
};

}  // namespace athlos::ui
