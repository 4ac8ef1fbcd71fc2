#include "ui/ParameterForm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <algorithm>
#include <climits>
#include <cmath>

namespace athlos::ui {

namespace {
// Spin boxes need finite limits; an unbounded spec gets a range far beyond any sensible value.
constexpr double kUnbounded = 1e12;

QString unitSuffix(const QString& unit)
{
    return unit.isEmpty() || unit == QLatin1String("1") ? QString() : QLatin1Char(' ') + unit;
}

double finiteOr(double value, double fallback)
{
    return std::isfinite(value) ? value : fallback;
}
}  // namespace

ParameterForm::ParameterForm(QWidget* parent) : QWidget(parent)
{
    layout_ = new QFormLayout(this);
    layout_->setContentsMargins(0, 0, 0, 0);
}

void ParameterForm::setSpecs(const ParameterSpecs& specs)
{
    while (layout_->rowCount() > 0) layout_->removeRow(0);
    editors_.clear();
    enableBoxes_.clear();
    specs_ = specs;
    if (specs_.isEmpty()) {
        layout_->addRow(new QLabel(tr("This processor has no parameters."), this));
        return;
    }
    for (const ParameterSpec& spec : specs_) {
        QWidget* editor = createEditor(spec);
        editor->setToolTip(spec.help);
        editor->setObjectName(spec.name);
        editors_[spec.name] = editor;
        auto* label = new QLabel(spec.name, this);
        label->setToolTip(spec.help);
        if (!spec.optional) {
            layout_->addRow(label, editor);
            continue;
        }
        // Optional: absent unless enabled; the editor only means something when checked.
        auto* row = new QWidget(this);
        auto* rowLayout = new QHBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        auto* enable = new QCheckBox(row);
        enable->setToolTip(tr("Set %1 (otherwise the processor decides)").arg(spec.name));
        enable->setObjectName(spec.name + QStringLiteral("_enabled"));
        editor->setParent(row);
        editor->setEnabled(false);
        connect(enable, &QCheckBox::toggled, editor, &QWidget::setEnabled);
        rowLayout->addWidget(enable);
        rowLayout->addWidget(editor, 1);
        enableBoxes_[spec.name] = enable;
        layout_->addRow(label, row);
    }
}

QWidget* ParameterForm::createEditor(const ParameterSpec& spec)
{
    switch (spec.type) {
    case ParameterSpec::Type::Double: {
        auto* box = new QDoubleSpinBox(this);
        box->setDecimals(6);
        box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        box->setRange(finiteOr(spec.minimum, -kUnbounded), finiteOr(spec.maximum, kUnbounded));
        box->setSuffix(unitSuffix(spec.unit));
        box->setValue(spec.defaultValue.isValid() ? spec.defaultValue.toDouble() : std::max(0.0, box->minimum()));
        return box;
    }
    case ParameterSpec::Type::Int: {
        auto* box = new QSpinBox(this);
        box->setRange(int(std::clamp(finiteOr(spec.minimum, INT_MIN), double(INT_MIN), double(INT_MAX))),
                      int(std::clamp(finiteOr(spec.maximum, INT_MAX), double(INT_MIN), double(INT_MAX))));
        box->setSuffix(unitSuffix(spec.unit));
        box->setValue(spec.defaultValue.isValid() ? spec.defaultValue.toInt() : std::max(0, box->minimum()));
        return box;
    }
    case ParameterSpec::Type::Bool: {
        auto* box = new QCheckBox(this);
        box->setChecked(spec.defaultValue.toBool());
        return box;
    }
    case ParameterSpec::Type::Choice: {
        auto* box = new QComboBox(this);
        box->addItems(spec.choices);
        box->setCurrentIndex(std::max<qsizetype>(0, spec.choices.indexOf(spec.defaultValue.toString())));
        return box;
    }
    case ParameterSpec::Type::String:
        break;
    }
    auto* edit = new QLineEdit(this);
    edit->setText(spec.defaultValue.toString());
    return edit;
}

void ParameterForm::setEditorValue(const ParameterSpec& spec, QWidget* editor, const QVariant& value)
{
    switch (spec.type) {
    case ParameterSpec::Type::Double:
        static_cast<QDoubleSpinBox*>(editor)->setValue(value.toDouble());
        return;
    case ParameterSpec::Type::Int:
        static_cast<QSpinBox*>(editor)->setValue(value.toInt());
        return;
    case ParameterSpec::Type::Bool:
        static_cast<QCheckBox*>(editor)->setChecked(value.toBool());
        return;
    case ParameterSpec::Type::Choice: {
        auto* box = static_cast<QComboBox*>(editor);
        const int index = box->findText(value.toString());
        if (index >= 0) box->setCurrentIndex(index);
        return;
    }
    case ParameterSpec::Type::String:
        static_cast<QLineEdit*>(editor)->setText(value.toString());
        return;
    }
}

QVariantMap ParameterForm::values() const
{
    QVariantMap map;
    for (const ParameterSpec& spec : specs_) {
        if (QCheckBox* enable = enableBox(spec.name); enable && !enable->isChecked()) continue;
        QWidget* editor = editors_.at(spec.name);
        switch (spec.type) {
        case ParameterSpec::Type::Double:
            map[spec.name] = static_cast<QDoubleSpinBox*>(editor)->value();
            break;
        case ParameterSpec::Type::Int:
            map[spec.name] = static_cast<QSpinBox*>(editor)->value();
            break;
        case ParameterSpec::Type::Bool:
            map[spec.name] = static_cast<QCheckBox*>(editor)->isChecked();
            break;
        case ParameterSpec::Type::Choice:
            map[spec.name] = static_cast<QComboBox*>(editor)->currentText();
            break;
        case ParameterSpec::Type::String:
            map[spec.name] = static_cast<QLineEdit*>(editor)->text();
            break;
        }
    }
    return map;
}

void ParameterForm::setValues(const QVariantMap& values)
{
    for (const ParameterSpec& spec : specs_) {
        const bool present = values.contains(spec.name);
        if (QCheckBox* enable = enableBox(spec.name)) enable->setChecked(present);
        if (present) setEditorValue(spec, editors_.at(spec.name), values.value(spec.name));
    }
}

QWidget* ParameterForm::editor(const QString& name) const
{
    const auto it = editors_.find(name);
    return it == editors_.end() ? nullptr : it->second;
}

QCheckBox* ParameterForm::enableBox(const QString& name) const
{
    const auto it = enableBoxes_.find(name);
    return it == enableBoxes_.end() ? nullptr : it->second;
}

}  // namespace athlos::ui
