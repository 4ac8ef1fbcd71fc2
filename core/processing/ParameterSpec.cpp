#include "core/processing/ParameterSpec.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace athlos {

ParameterSpec ParameterSpec::number(QString name, double def, double min, double max, QString unit, QString help) {
    ParameterSpec s;
    s.name = std::move(name);
    s.type = Type::Double;
    if (!std::isnan(def)) s.defaultValue = def;
    s.minimum = min;
    s.maximum = max;
    s.unit = std::move(unit);
    s.help = std::move(help);
    return s;
}

ParameterSpec ParameterSpec::integer(QString name, int def, int min, int max, QString help) {
    ParameterSpec s;
    s.name = std::move(name);
    s.type = Type::Int;
    s.defaultValue = def;
    s.minimum = min;
    s.maximum = max;
    s.help = std::move(help);
    return s;
}

ParameterSpec ParameterSpec::boolean(QString name, bool def, QString help) {
    ParameterSpec s;
    s.name = std::move(name);
    s.type = Type::Bool;
    s.defaultValue = def;
    s.help = std::move(help);
    return s;
}

ParameterSpec ParameterSpec::choice(QString name, QStringList choices, QString def, QString help) {
    ParameterSpec s;
    s.name = std::move(name);
    s.type = Type::Choice;
    s.choices = std::move(choices);
    s.defaultValue = std::move(def);
    s.help = std::move(help);
    return s;
}

ParameterSpec ParameterSpec::text(QString name, QString def, QString help) {
    ParameterSpec s;
    s.name = std::move(name);
    s.type = Type::String;
    s.defaultValue = std::move(def);
    s.help = std::move(help);
    return s;
}

QString ParameterSpec::typeName() const {
    switch (type) {
        case Type::Double:
            return QStringLiteral("number");
        case Type::Int:
            return QStringLiteral("integer");
        case Type::Bool:
            return QStringLiteral("boolean");
        case Type::String:
            return QStringLiteral("string");
        case Type::Choice:
            return QStringLiteral("choice");
    }
    return {};
}

QJsonObject ParameterSpec::toJson() const {
    QJsonObject json{
        {QStringLiteral("name"), name}, {QStringLiteral("type"), typeName()}, {QStringLiteral("help"), help}};
    if (defaultValue.isValid()) json[QStringLiteral("default")] = QJsonValue::fromVariant(defaultValue);
    json[QStringLiteral("required")] = !defaultValue.isValid() && !optional;
    if (type == Type::Double || type == Type::Int) {
        if (std::isfinite(minimum)) json[QStringLiteral("minimum")] = minimum;
        if (std::isfinite(maximum)) json[QStringLiteral("maximum")] = maximum;
    }
    if (type == Type::Choice) json[QStringLiteral("choices")] = QJsonArray::fromStringList(choices);
    if (!unit.isEmpty()) json[QStringLiteral("unit")] = unit;
    return json;
}

namespace {

QString rangeText(const ParameterSpec& s) {
    const QString lo = std::isfinite(s.minimum) ? QString::number(s.minimum) : QStringLiteral("-inf");
    const QString hi = std::isfinite(s.maximum) ? QString::number(s.maximum) : QStringLiteral("inf");
    return QStringLiteral("[%1, %2]%3").arg(lo, hi, s.unit.isEmpty() ? QString() : QLatin1Char(' ') + s.unit);
}

}  // namespace

Expected<QVariant> ParameterSpec::convert(const QVariant& value) const {
    const QString text = value.toString().trimmed();
    auto bad = [&](const QString& why) { return makeError(QStringLiteral("parameter '%1': %2").arg(name, why)); };
    switch (type) {
        case Type::Double: {
            bool ok = false;
            const double v = value.typeId() == QMetaType::QString ? text.toDouble(&ok) : value.toDouble(&ok);
            if (!ok || !std::isfinite(v)) return bad(QStringLiteral("'%1' is not a number").arg(text));
            if (v < minimum || v > maximum)
                return bad(QStringLiteral("%1 is outside the allowed range %2").arg(text, rangeText(*this)));
            return QVariant(v);
        }
        case Type::Int: {
            bool ok = false;
            const qlonglong v = value.typeId() == QMetaType::QString ? text.toLongLong(&ok) : value.toLongLong(&ok);
            if (!ok) return bad(QStringLiteral("'%1' is not an integer").arg(text));
            if (double(v) < minimum || double(v) > maximum)
                return bad(QStringLiteral("%1 is outside the allowed range %2").arg(text, rangeText(*this)));
            return QVariant(int(v));
        }
        case Type::Bool: {
            if (value.typeId() == QMetaType::Bool) return value;
            const QString t = text.toLower();
            if (t == u"true" || t == u"1" || t == u"yes" || t == u"on") return QVariant(true);
            if (t == u"false" || t == u"0" || t == u"no" || t == u"off") return QVariant(false);
            return bad(QStringLiteral("'%1' is not a boolean (use true or false)").arg(text));
        }
        case Type::Choice:
            if (!acceptsChoice(text))
                return bad(QStringLiteral("'%1' is not one of %2").arg(text, choices.join(QStringLiteral("|"))));
            return QVariant(text);
        case Type::String:
            return QVariant(value.toString());
    }
    return bad(QStringLiteral("unsupported type"));
}

bool ParameterSpec::acceptsChoice(const QString& text) const {
    if (choices.contains(text) && !text.endsWith(QLatin1Char(':'))) return true;
    return std::any_of(choices.begin(), choices.end(), [&](const QString& c) {
        return c.endsWith(QLatin1Char(':')) && text.size() > c.size() && text.startsWith(c);
    });
}

Expected<QVariantMap> validateParameters(const ParameterSpecs& specs, const QVariantMap& given) {
    QVariantMap result;
    for (auto it = given.begin(); it != given.end(); ++it) {
        const auto spec =
            std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& s) { return s.name == it.key(); });
        if (spec == specs.end()) {
            QStringList names;
            for (const auto& s : specs) names << s.name;
            return makeError(
                QStringLiteral("unknown parameter '%1' (known: %2)")
                    .arg(it.key(), names.isEmpty() ? QStringLiteral("none") : names.join(QStringLiteral(", "))));
        }
        auto converted = spec->convert(it.value());
        if (!converted) return converted.error();
        result.insert(it.key(), *converted);
    }
    for (const auto& spec : specs) {
        if (result.contains(spec.name)) continue;
        if (spec.defaultValue.isValid()) {
            result.insert(spec.name, spec.defaultValue);
        } else if (!spec.optional) {
            return makeError(QStringLiteral("parameter '%1' is required (%2)").arg(spec.name, spec.help));
        }
    }
    return result;
}

QStringList splitList(const QString& text) {
    QStringList items;
    for (const QString& item : text.split(QLatin1Char(','))) {
        const QString trimmed = item.trimmed();
        if (!trimmed.isEmpty()) items << trimmed;
    }
    return items;
}

}  // namespace athlos
