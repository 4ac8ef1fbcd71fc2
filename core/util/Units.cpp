#include "core/util/Units.h"

#include "core/math/Angles.h"

#include <QHash>
#include <cmath>
#include <numbers>

namespace athlos {
namespace {

// A unit as a linear map onto the base unit of its quantity: value_base = value * scale + offset.
struct UnitDef {
    const char* quantity;
    double scale;
    double offset = 0.0;
};

const QHash<QString, UnitDef>& unitTable() {
    constexpr double kStandardGravity = 9.80665;
    static const QHash<QString, UnitDef> table{
        {"s", {"time", 1.0}},
        {"ms", {"time", 1e-3}},
        {"us", {"time", 1e-6}},
        {"ns", {"time", 1e-9}},
        {"min", {"time", 60.0}},
        {"h", {"time", 3600.0}},
        {"d", {"time", 86400.0}},
        {"m", {"length", 1.0}},
        {"mm", {"length", 1e-3}},
        {"cm", {"length", 1e-2}},
        {"km", {"length", 1e3}},
        {"m/s", {"speed", 1.0}},
        {"km/h", {"speed", 1.0 / 3.6}},
        {"mm/s", {"speed", 1e-3}},
        {"cm/s", {"speed", 1e-2}},
        {"m/s^2", {"acceleration", 1.0}},
        {"g", {"acceleration", kStandardGravity}},
        {"mg", {"acceleration", kStandardGravity * 1e-3}},
        {"rad/s", {"angular rate", 1.0}},
        {"deg/s", {"angular rate", math::kDeg}},
        {"rpm", {"angular rate", 2.0 * std::numbers::pi / 60.0}},
        {"rad", {"angle", 1.0}},
        {"deg", {"angle", math::kDeg}},
        {"T", {"magnetic flux density", 1e6}},
        {"mT", {"magnetic flux density", 1e3}},
        {"uT", {"magnetic flux density", 1.0}},
        {"nT", {"magnetic flux density", 1e-3}},
        {"G", {"magnetic flux density", 100.0}},
        {"mG", {"magnetic flux density", 0.1}},
        {"1", {"ratio", 1.0}},
        {"%", {"ratio", 0.01}},
        {"degC", {"temperature", 1.0}},
        {"K", {"temperature", 1.0, -273.15}},
        {"Hz", {"frequency", 1.0}},
        {"kHz", {"frequency", 1e3}},
        {"dB", {"level", 1.0}},
        {"dBm", {"power level", 1.0}},
        {"bpm", {"frequency", 1.0 / 60.0}},
        {"mph", {"speed", 0.44704}},
        {"ft", {"length", 0.3048}},
        {"mi", {"length", 1609.344}},
        {"ft/s", {"speed", 0.3048}},
        {"Pa", {"pressure", 1.0}},
        {"hPa", {"pressure", 100.0}},
        {"kPa", {"pressure", 1e3}},
        {"mbar", {"pressure", 100.0}},
        {"bar", {"pressure", 1e5}},
        {"lx", {"illuminance", 1.0}},
    };
    return table;
}

// Spellings seen in sensor exports, mapped to the canonical name. Case matters for units
// (g vs G, mG vs MG), so only exact spellings are aliased.
const QHash<QString, QString>& aliases() {
    static const QHash<QString, QString> table{
        {"sec", "s"},
        {"secs", "s"},
        {"second", "s"},
        {"seconds", "s"},
        {"msec", "ms"},
        {"millisecond", "ms"},
        {"milliseconds", "ms"},
        {"usec", "us"},
        {"day", "d"},
        {"days", "d"},
        {"hour", "h"},
        {"hours", "h"},
        {"meter", "m"},
        {"meters", "m"},
        {"metre", "m"},
        {"metres", "m"},
        {"m/s2", "m/s^2"},
        {"m/s/s", "m/s^2"},
        {"ms^-2", "m/s^2"},
        {"m*s^-2", "m/s^2"},
        {"m s^-2", "m/s^2"},
        {"m/sec^2", "m/s^2"},
        {"deg/sec", "deg/s"},
        {"dps", "deg/s"},
        {"degree/s", "deg/s"},
        {"degrees/s", "deg/s"},
        {"rad/sec", "rad/s"},
        {"rps", "rad/s"},
        {"degree", "deg"},
        {"degrees", "deg"},
        {"radian", "rad"},
        {"radians", "rad"},
        {"gauss", "G"},
        {"Gauss", "G"},
        {"tesla", "T"},
        {"microtesla", "uT"},
        {"-", "1"},
        {"C", "degC"},
        {"celsius", "degC"},
        {"kmh", "km/h"},
        {"kph", "km/h"},
        {"m/sec", "m/s"},
        {"Hertz", "Hz"},
        {"lux", "lx"},
        {"BPM", "bpm"},
        {"beats/min", "bpm"},
        {"1/min", "bpm"},
        {"percent", "%"},
        {"MPH", "mph"},
        {"km/hr", "km/h"},
        {"kmph", "km/h"},
        {"hpa", "hPa"},
        {"pa", "Pa"},
        {"Lux", "lx"},
        {"µs", "us"},
        {"mins", "min"},
        {"minute", "min"},
        {"minutes", "min"},
        {"nsec", "ns"},
    };
    return table;
}

}  // namespace

QString knownUnitNames(const QString& sameQuantityAs) {
    const auto& table = unitTable();
    const auto ref = table.constFind(canonicalUnit(sameQuantityAs));
    QStringList names;
    for (auto it = table.cbegin(); it != table.cend(); ++it)
        if (ref == table.cend() || qstrcmp(it->quantity, ref->quantity) == 0) names << it.key();
    names.sort(Qt::CaseInsensitive);
    return names.join(QStringLiteral(", "));
}

void splitNameAndUnit(const QString& header, QString& name, QString& unit) {
    const QString cell = header.trimmed();
    unit.clear();
    name = cell;
    if (cell.isEmpty()) return;
    const QChar last = cell.back();
    const QChar open = last == QLatin1Char(']')   ? QLatin1Char('[')
                       : last == QLatin1Char(')') ? QLatin1Char('(')
                                                  : QChar();
    if (open.isNull()) return;
    const qsizetype start = cell.lastIndexOf(open);
    if (start <= 0) return;  // "(g)" alone is a name, not a unit
    name = cell.left(start).trimmed();
    unit = canonicalUnit(cell.mid(start + 1, cell.size() - start - 2));
}

QString canonicalUnit(const QString& unit) {
    QString u = unit.trimmed();
    u.replace(QChar(0x00B2), QLatin1String("^2"));  // ²
    u.replace(QChar(0x00B3), QLatin1String("^3"));  // ³
    u.replace(QChar(0x00B5), QLatin1Char('u'));     // micro sign
    u.replace(QChar(0x03BC), QLatin1Char('u'));     // greek mu
    u.replace(QChar(0x2212), QLatin1Char('-'));     // minus sign
    u.replace(QStringLiteral("\u00B0C"), QLatin1String("degC"));
    u.replace(QChar(0x00B0), QLatin1String("deg"));  // °
    u.remove(QLatin1Char(' '));
    if (u.isEmpty()) return u;
    const auto alias = aliases().constFind(u);
    return alias != aliases().cend() ? *alias : u;
}

Expected<UnitConversion> conversionTo(const QString& unit, const QString& targetSi) {
    const QString from = canonicalUnit(unit);
    const QString to = canonicalUnit(targetSi);
    if (from == to || from.isEmpty()) return UnitConversion{to, 1.0, 0.0};
    const auto& table = unitTable();
    const auto f = table.constFind(from);
    if (f == table.cend())
        return makeError(QStringLiteral("unknown unit '%1' (accepted for %2: %3)").arg(unit, to, knownUnitNames(to)));
    const auto t = table.constFind(to);
    if (t == table.cend()) return makeError(QStringLiteral("unknown target unit '%1'").arg(to));
    if (qstrcmp(f->quantity, t->quantity) != 0)
        return makeError(QStringLiteral("unit '%1' (%2) cannot be converted to '%3' (%4)")
                             .arg(unit, QLatin1String(f->quantity), to, QLatin1String(t->quantity)));
    // v_to = (v * s_from + o_from - o_to) / s_to
    return UnitConversion{to, f->scale / t->scale, (f->offset - t->offset) / t->scale};
}

}  // namespace athlos
