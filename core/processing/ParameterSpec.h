#pragma once
// A processor parameter: drives CLI --param parsing/validation, the GUI's generated dialog, and docs.
#include "core/util/Expected.h"

#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <QVariantMap>
#include <limits>

namespace athlos {

struct ParameterSpec {
    enum class Type { Double, Int, Bool, String, Choice };

    QString name;
    Type type = Type::Double;
    QVariant defaultValue;                                      // invalid QVariant = required
    double minimum = -std::numeric_limits<double>::infinity();  // inclusive, numbers only
    double maximum = std::numeric_limits<double>::infinity();
    // Choice only. A choice ending in ':' takes an argument: "profile:" accepts "profile:NAME" for any
    // non-empty NAME (the GUI then offers an editable list).
    QStringList choices;
    QString unit;  // SI unit of the value ("Hz", "s", "m", ...)
    QString help;
    bool optional = false;  // may be absent (no default), e.g. output_rate

    // def = NaN makes the parameter required (no default).
    static ParameterSpec number(QString name, double def, double min, double max, QString unit, QString help);
    static ParameterSpec integer(QString name, int def, int min, int max, QString help);
    static ParameterSpec boolean(QString name, bool def, QString help);
    static ParameterSpec choice(QString name, QStringList choices, QString def, QString help);
    static ParameterSpec text(QString name, QString def, QString help);

    QString typeName() const;
    QJsonObject toJson() const;
    // Converts a user-given value (a string from the CLI or any QVariant from the GUI) to the
    // parameter's type and checks range/choices. The error names the parameter and the range.
    Expected<QVariant> convert(const QVariant& value) const;
    // Whether `text` is one of the choices or an argument choice ("profile:" + NAME).
    bool acceptsChoice(const QString& text) const;
};

using ParameterSpecs = QList<ParameterSpec>;

// Validates a full parameter map against specs: unknown names are errors, defaults are filled in.
Expected<QVariantMap> validateParameters(const ParameterSpecs& specs, const QVariantMap& given);

// The items of a list parameter ("acc_x, acc_y,acc_z"): split at commas, blanks trimmed, empty
// items dropped.
QStringList splitList(const QString& text);

}  // namespace athlos
