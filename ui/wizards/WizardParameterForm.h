#pragma once
// Editors generated from a processor's ParameterSpecs for wizard pages. Unlike ui/ParameterForm
// (spin boxes with 6 decimals), numbers are text fields in 'g' format: noise densities and
// variances span many decades (1e-8 … 25) and a fixed-decimal spin box would round small ones to 0.
#include "core/processing/ParameterSpec.h"

#include <QVariantMap>
#include <QWidget>
#include <map>
#include <optional>

namespace athlos::ui {

class WizardParameterForm : public QWidget {
    Q_OBJECT

public:
    explicit WizardParameterForm(const ParameterSpecs& specs, QWidget* parent = nullptr);

    // Current values, converted and range-checked by each spec; invalid entries are left out and
    // reported by errors().
    QVariantMap values() const;
    QStringList errors() const;
    // The editor of a parameter (object name "param_<name>"), or nullptr.
    QWidget* editor(const QString& name) const;
    void setValue(const QString& name, const QVariant& value);
    bool isEmpty() const { return specs_.isEmpty(); }

private:
    QVariant rawValue(const ParameterSpec& spec) const;
    // The converted value of the editor; nullopt when an optional parameter is left empty.
    std::optional<Expected<QVariant>> converted(const ParameterSpec& spec) const;

    ParameterSpecs specs_;
    std::map<QString, QWidget*> editors_;
};

}  // namespace athlos::ui
