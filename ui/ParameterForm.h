#pragma once
// A form generated from a processor's ParameterSpecs: one editor per parameter (numbers, check
// boxes, choice combos, line edits) named "param_<name>", help as tooltip. Numbers are edited in
// one of two styles:
//   SpinBox (the processor dialog): spin boxes with the spec's range and the unit as suffix; an
//     optional parameter gets an enable box, so absent and "set to a value" stay distinguishable;
//     a processor without parameters says so.
//   Text (wizard pages): real numbers are text fields in 'g' format, because noise densities and
//     variances span many decades (1e-8 … 25) and a fixed-decimal spin box would round small ones
//     to 0. The unit is in the label; an optional text field left empty is absent; an entry the
//     spec refuses is left out of values() and reported by errors().
#include "core/processing/ParameterSpec.h"

#include <QStringList>
#include <QVariantMap>
#include <QWidget>
#include <map>
#include <optional>

class QCheckBox;
class QFormLayout;

namespace athlos::ui {

class ParameterForm : public QWidget {
    Q_OBJECT

public:
    enum class NumberStyle { SpinBox, Text };

    explicit ParameterForm(QWidget* parent = nullptr);
    ParameterForm(const ParameterSpecs& specs, NumberStyle style, QWidget* parent = nullptr);

    // Replaces the editors (defaults filled in).
    void setSpecs(const ParameterSpecs& specs);
    const ParameterSpecs& specs() const { return specs_; }
    bool isEmpty() const { return specs_.isEmpty(); }
    NumberStyle numberStyle() const { return style_; }

    // Values of every parameter that is set (optional ones only when enabled or filled in),
    // converted and range-checked by its spec; entries that fail are left out.
    QVariantMap values() const;
    // The messages of the entries values() left out (only text fields can fail).
    QStringList errors() const;
    // Fills editors from values (e.g. a result's provenance); optional parameters absent from it
    // are unset, others keep their values.
    void setValues(const QVariantMap& values);
    // Sets one parameter (and enables it if optional).
    void setValue(const QString& name, const QVariant& value);

    QWidget* editor(const QString& name) const;
    // The enable box of an optional parameter, else nullptr.
    QCheckBox* enableBox(const QString& name) const;

private:
    QWidget* createEditor(const ParameterSpec& spec);
    // Whether an optional parameter is absent when its text field is empty (instead of having an
    // enable box).
    bool emptyMeansAbsent(const ParameterSpec& spec) const;
    void setEditorValue(QWidget* editor, const QVariant& value);
    QVariant rawValue(QWidget* editor) const;
    // The converted value of the parameter; nullopt when it is absent.
    std::optional<Expected<QVariant>> converted(const ParameterSpec& spec) const;

    NumberStyle style_ = NumberStyle::SpinBox;
    QFormLayout* layout_ = nullptr;
    ParameterSpecs specs_;
    std::map<QString, QWidget*> editors_;
    std::map<QString, QCheckBox*> enableBoxes_;
};

}  // namespace athlos::ui
