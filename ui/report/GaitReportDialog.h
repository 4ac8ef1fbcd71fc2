#pragma once
// File ▸ Export gait report…, its first step: which stride tables of the recording (a combo per foot,
// filled with its gait-parameters tables, the other foot optional) and the steady-state parameters
// (gait-summary's declaration as a form, defaults filled in).
#include "core/model/Project.h"
#include "ui/report/GaitReport.h"

#include <QDialog>
#include <QVariantMap>

class QComboBox;

namespace athlos::ui {

class ParameterForm;

class GaitReportDialog : public QDialog {
    Q_OBJECT

public:
    // input.strides: the tables chosen first in their foot's combo (GaitReport::strideTables' choice).
    GaitReportDialog(const Project& project, const GaitReportInput& input, QWidget* parent = nullptr);

    // The tables chosen (left first; a foot set to "(none)" left out) and the summary's parameters.
    GaitReportInput input() const;
    QVariantMap parameters() const;

    QComboBox* footCombo(int foot) const { return foot == 0 ? left_ : right_; }
    ParameterForm* form() const { return form_; }

private:
    QString recording_;
    QComboBox* left_ = nullptr;
    QComboBox* right_ = nullptr;
    ParameterForm* form_ = nullptr;
};

}  // namespace athlos::ui
