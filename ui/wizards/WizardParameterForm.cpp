#include "ui/wizards/WizardParameterForm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QSpinBox>
#include <cmath>

namespace athlos::ui {

WizardParameterForm::WizardParameterForm(const ParameterSpecs& specs, QWidget* parent) : QWidget(parent), specs_(specs)
{
    auto* layout = new QFormLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (const ParameterSpec& spec : specs_) {
        QWidget* editor = nullptr;
        switch (spec.type) {
        case ParameterSpec::Type::Bool: {
            auto* box = new QCheckBox(this);
            box->setChecked(spec.defaultValue.toBool());
            editor = box;
            break;
        }
        case ParameterSpec::Type::Choice: {
            auto* box = new QComboBox(this);
            box->addItems(spec.choices);
            box->setCurrentText(spec.defaultValue.toString());
            editor = box;
            break;
        }
        case ParameterSpec::Type::Int: {
            auto* box = new QSpinBox(this);
            box->setRange(int(std::max(spec.minimum, -2e9)), int(std::min(spec.maximum, 2e9)));
            box->setValue(spec.defaultValue.toInt());
            editor = box;
            break;
        }
        default: {
            // Noise densities span many decades: a text field in 'g' format keeps 1e-6 and 25 alike
            // editable, where a spin box would round one of them away.
            auto* edit = new QLineEdit(this);
            if (spec.optional) edit->setPlaceholderText(tr("(not set)"));  // empty = let the processor decide
            if (spec.defaultValue.isValid())
                edit->setText(spec.type == ParameterSpec::Type::Double ? QString::number(spec.defaultValue.toDouble(), 'g', 8)
                                                                       : spec.defaultValue.toString());
            editor = edit;
            break;
        }
        }
        editor->setObjectName(QStringLiteral("param_") + spec.name);
        editor->setToolTip(spec.help);
        const QString label = spec.unit.isEmpty() ? spec.name : QStringLiteral("%1 [%2]").arg(spec.name, spec.unit);
        layout->addRow(label, editor);
        editors_[spec.name] = editor;
    }
}

QWidget* WizardParameterForm::editor(const QString& name) const
{
    auto it = editors_.find(name);
    return it == editors_.end() ? nullptr : it->second;
}

void WizardParameterForm::setValue(const QString& name, const QVariant& value)
{
    QWidget* w = editor(name);
    if (auto* box = qobject_cast<QCheckBox*>(w)) box->setChecked(value.toBool());
    else if (auto* combo = qobject_cast<QComboBox*>(w)) combo->setCurrentText(value.toString());
    else if (auto* spin = qobject_cast<QSpinBox*>(w)) spin->setValue(value.toInt());
    else if (auto* edit = qobject_cast<QLineEdit*>(w))
        edit->setText(value.typeId() == QMetaType::Double ? QString::number(value.toDouble(), 'g', 8) : value.toString());
}

QVariant WizardParameterForm::rawValue(const ParameterSpec& spec) const
{
    QWidget* w = editor(spec.name);
    if (auto* box = qobject_cast<QCheckBox*>(w)) return box->isChecked();
    if (auto* combo = qobject_cast<QComboBox*>(w)) return combo->currentText();
    if (auto* spin = qobject_cast<QSpinBox*>(w)) return spin->value();
    if (auto* edit = qobject_cast<QLineEdit*>(w)) return edit->text().trimmed();
    return {};
}

std::optional<Expected<QVariant>> WizardParameterForm::converted(const ParameterSpec& spec) const
{
    const QVariant raw = rawValue(spec);
    if (raw.typeId() == QMetaType::QString && raw.toString().isEmpty() && spec.optional) return std::nullopt;
    return spec.convert(raw);
}

QVariantMap WizardParameterForm::values() const
{
    QVariantMap map;
    for (const ParameterSpec& spec : specs_)
        if (auto value = converted(spec); value && *value) map.insert(spec.name, **value);
    return map;
}

QStringList WizardParameterForm::errors() const
{
    QStringList list;
    for (const ParameterSpec& spec : specs_)
        if (auto value = converted(spec); value && !*value) list << value->message();
    return list;
}

}  // namespace athlos::ui
