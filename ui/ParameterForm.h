#pragma once
// A form generated from a processor's ParameterSpecs: one editor per parameter (spin boxes with
// range and unit, check boxes, choice combos, line edits), help as tooltip, and an enable box for
// optional parameters, so absent and "set to a value" stay distinguishable.
#include "core/processing/ParameterSpec.h"

#include <QVariantMap>
#include <QWidget>
#include <map>

class QCheckBox;
class QFormLayout;

namespace athlos::ui {

class ParameterForm : public QWidget {
    Q_OBJECT

public:
    explicit ParameterForm(QWidget* parent = nullptr);

    void setSpecs(const ParameterSpecs& specs);
    const ParameterSpecs& specs() const { return specs_; }

    // Typed values of every parameter that is set (optional ones only when enabled).
    QVariantMap values() const;
    // Fills editors from values (e.g. a result's provenance); others keep their defaults.
    void setValues(const QVariantMap& values);

    QWidget* editor(const QString& name) const;
    // The enable box of an optional parameter, else nullptr.
    QCheckBox* enableBox(const QString& name) const;

private:
    QWidget* createEditor(const ParameterSpec& spec);
    void setEditorValue(const ParameterSpec& spec, QWidget* editor, const QVariant& value);

    QFormLayout* layout_ = nullptr;
    ParameterSpecs specs_;
    std::map<QString, QWidget*> editors_;
    std::map<QString, QCheckBox*> enableBoxes_;
};

}  // namespace athlos::ui
