#include "ui/report/GaitReportDialog.h"

#include "core/processing/ProcessorRegistry.h"
#include "ui/ParameterForm.h"

#include <QComboBox>
#include <QPushButton>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace athlos::ui {

GaitReportDialog::GaitReportDialog(const Project& project, const GaitReportInput& input, QWidget* parent)
    : QDialog(parent), recording_(input.recording) {
    setWindowTitle(tr("Export gait report"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Stride tables of '%1' (gait-parameters), one per foot:").arg(recording_)));
    auto* feet = new QFormLayout;
    left_ = new QComboBox;
    right_ = new QComboBox;
    left_->setObjectName(QStringLiteral("left_strides"));
    right_->setObjectName(QStringLiteral("right_strides"));
    right_->addItem(tr("(none)"), QString());
    if (const Recording* rec = project.recording(recording_))
        for (const auto& [name, table] : rec->tables) {
            if (!GaitReport::isStrideTable(table)) continue;
            const bool right = table.attributes.value(QStringLiteral("foot")).toString() == QLatin1String("right");
            (right ? right_ : left_)->addItem(name, QString(recording_ + u'/' + name));
        }
    left_->addItem(tr("(none)"), QString());              // a recording of the right foot only
    if (right_->count() > 1) right_->setCurrentIndex(1);  // the first right-foot table, not "(none)"
    // The given tables first: a left (or unknown) foot's in the first combo, a right foot's in the second.
    for (const QString& path : input.strides)
        for (QComboBox* combo : {left_, right_})
            if (const int i = combo->findData(path); i >= 0) combo->setCurrentIndex(i);
    feet->addRow(tr("Left foot (or the only one):"), left_);
    feet->addRow(tr("Right foot:"), right_);
    layout->addLayout(feet);
    layout->addWidget(new QLabel(tr("Steady state (gait-summary):")));
    ParameterSpecs specs;
    if (const auto summary = ProcessorRegistry::instance().find(QStringLiteral("gait-summary")))
        specs = summary->parameters();
    form_ = new ParameterForm(specs, ParameterForm::NumberStyle::SpinBox);
    layout->addWidget(form_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setEnabled(left_->count() + right_->count() > 2);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

GaitReportInput GaitReportDialog::input() const {
    GaitReportInput input{recording_, {}};
    for (const QComboBox* combo : {left_, right_})
        if (const QString path = combo->currentData().toString(); !path.isEmpty()) input.strides << path;
    return input;
}

QVariantMap GaitReportDialog::parameters() const { return form_->values(); }

}  // namespace athlos::ui
