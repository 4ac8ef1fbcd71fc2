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

QString unitSuffix(const QString& unit) {
    return unit.isEmpty() || unit == QLatin1String("1") ? QString() : QLatin1Char(' ') + unit;
}

double finiteOr(double value, double fallback) { return std::isfinite(value) ? value : fallback; }

// 'g' with 8 digits keeps 1e-6 and 25 alike readable and editable.
QString numberText(double value) { return QString::number(value, 'g', 8); }
}  // namespace

ParameterForm::ParameterForm(QWidget* parent) : QWidget(parent) {
    layout_ = new QFormLayout(this);
    layout_->setContentsMargins(0, 0, 0, 0);
}

ParameterForm::ParameterForm(const ParameterSpecs& specs, NumberStyle style, QWidget* parent) : ParameterForm(parent) {
    style_ = style;
    setSpecs(specs);
}

void ParameterForm::setSpecs(const ParameterSpecs& specs) {
    while (layout_->rowCount() > 0) layout_->removeRow(0);
    editors_.clear();
    enableBoxes_.clear();
    specs_ = specs;
    if (specs_.isEmpty()) {
        // A wizard page explains a missing processor itself.
        if (style_ == NumberStyle::SpinBox) layout_->addRow(new QLabel(tr("This processor has no parameters."), this));
        return;
    }
    for (const ParameterSpec& spec : specs_) {
        QWidget* editor = createEditor(spec);
        editor->setToolTip(spec.help);
        editor->setObjectName(QStringLiteral("param_") + spec.name);
        editors_[spec.name] = editor;
        // A text field has no suffix: the unit goes into the label.
        const bool unitInLabel = qobject_cast<QLineEdit*>(editor) && !unitSuffix(spec.unit).isEmpty();
        auto* label = new QLabel(unitInLabel ? QStringLiteral("%1 [%2]").arg(spec.name, spec.unit) : spec.name, this);
        label->setToolTip(spec.help);
        if (!spec.optional || emptyMeansAbsent(spec)) {
            layout_->addRow(label, editor);
            continue;
        }
        // Optional: absent unless enabled; the editor only means something when checked.
        auto* row = new QWidget(this);
        auto* rowLayout = new QHBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        auto* enable = new QCheckBox(row);
        enable->setToolTip(tr("Set %1 (otherwise the processor decides)").arg(spec.name));
        enable->setObjectName(QStringLiteral("param_") + spec.name + QStringLiteral("_enabled"));
        editor->setParent(row);
        editor->setEnabled(false);
        connect(enable, &QCheckBox::toggled, editor, &QWidget::setEnabled);
        rowLayout->addWidget(enable);
        rowLayout->addWidget(editor, 1);
        enableBoxes_[spec.name] = enable;
        layout_->addRow(label, row);
    }
}

bool ParameterForm::emptyMeansAbsent(const ParameterSpec& spec) const {
    return style_ == NumberStyle::Text && spec.optional &&
           (spec.type == ParameterSpec::Type::Double || spec.type == ParameterSpec::Type::String);
}

QWidget* ParameterForm::createEditor(const ParameterSpec& spec) {
    switch (spec.type) {
        case ParameterSpec::Type::Double: {
            if (style_ == NumberStyle::Text) {
                auto* edit = new QLineEdit(this);
                if (spec.optional) edit->setPlaceholderText(tr("(not set)"));  // empty = let the processor decide
                if (spec.defaultValue.isValid()) edit->setText(numberText(spec.defaultValue.toDouble()));
                return edit;
            }
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
            // A choice that takes an argument ("profile:" + NAME) is typed into the box.
            box->setEditable(std::any_of(spec.choices.begin(), spec.choices.end(),
                                         [](const QString& c) { return c.endsWith(QLatin1Char(':')); }));
            return box;
        }
        case ParameterSpec::Type::String:
            break;
    }
    auto* edit = new QLineEdit(this);
    if (emptyMeansAbsent(spec)) edit->setPlaceholderText(tr("(not set)"));
    edit->setText(spec.defaultValue.toString());
    return edit;
}

void ParameterForm::setEditorValue(QWidget* editor, const QVariant& value) {
    if (auto* box = qobject_cast<QDoubleSpinBox*>(editor))
        box->setValue(value.toDouble());
    else if (auto* spin = qobject_cast<QSpinBox*>(editor))
        spin->setValue(value.toInt());
    else if (auto* check = qobject_cast<QCheckBox*>(editor))
        check->setChecked(value.toBool());
    else if (auto* combo = qobject_cast<QComboBox*>(editor)) {
        const int index = combo->findText(value.toString());
        if (index >= 0)
            combo->setCurrentIndex(index);
        else if (combo->isEditable())
            combo->setEditText(value.toString());
    } else if (auto* edit = qobject_cast<QLineEdit*>(editor)) {
        edit->setText(value.typeId() == QMetaType::Double ? numberText(value.toDouble()) : value.toString());
    }
}

QVariant ParameterForm::rawValue(QWidget* editor) const {
    if (auto* box = qobject_cast<QDoubleSpinBox*>(editor)) return box->value();
    if (auto* spin = qobject_cast<QSpinBox*>(editor)) return spin->value();
    if (auto* check = qobject_cast<QCheckBox*>(editor)) return check->isChecked();
    if (auto* combo = qobject_cast<QComboBox*>(editor)) return combo->currentText();
    if (auto* edit = qobject_cast<QLineEdit*>(editor)) return edit->text().trimmed();
    return {};
}

std::optional<Expected<QVariant>> ParameterForm::converted(const ParameterSpec& spec) const {
    if (QCheckBox* enable = enableBox(spec.name); enable && !enable->isChecked()) return std::nullopt;
    QWidget* editor = editors_.at(spec.name);
    const QVariant raw = rawValue(editor);
    // Spin boxes, check boxes and combos hold only values of the right type and range; typed text
    // is converted (and checked) by the spec.
    if (!qobject_cast<QLineEdit*>(editor)) return Expected<QVariant>(raw);
    if (emptyMeansAbsent(spec) && raw.toString().isEmpty()) return std::nullopt;
    return spec.convert(raw);
}

QVariantMap ParameterForm::values() const {
    QVariantMap map;
    for (const ParameterSpec& spec : specs_)
        if (auto value = converted(spec); value && *value) map.insert(spec.name, **value);
    return map;
}

QStringList ParameterForm::errors() const {
    QStringList list;
    for (const ParameterSpec& spec : specs_)
        if (auto value = converted(spec); value && !*value) list << value->message();
    return list;
}

void ParameterForm::setValues(const QVariantMap& values) {
    for (const ParameterSpec& spec : specs_) {
        if (values.contains(spec.name)) {
            setValue(spec.name, values.value(spec.name));
        } else if (QCheckBox* enable = enableBox(spec.name)) {
            enable->setChecked(false);
        } else if (emptyMeansAbsent(spec)) {
            static_cast<QLineEdit*>(editors_.at(spec.name))->clear();
        }
    }
}

void ParameterForm::setValue(const QString& name, const QVariant& value) {
    QWidget* widget = editor(name);
    if (!widget) return;
    if (QCheckBox* enable = enableBox(name)) enable->setChecked(true);
    setEditorValue(widget, value);
}

QWidget* ParameterForm::editor(const QString& name) const {
    const auto it = editors_.find(name);
    return it == editors_.end() ? nullptr : it->second;
}

QCheckBox* ParameterForm::enableBox(const QString& name) const {
    const auto it = enableBoxes_.find(name);
    return it == enableBoxes_.end() ? nullptr : it->second;
}

}  // namespace athlos::ui
