#pragma once
// Unit parsing and conversion to SI at import. Header cells may carry a unit in brackets,
// e.g. "gyr_x [deg/s]" or "acc_x(g)"; values are converted to the SI unit the kind requires.
#include "core/util/Expected.h"

#include <QString>

namespace athlos {

struct UnitConversion {
    QString si;          // canonical SI unit, e.g. "rad/s"
    double scale = 1.0;  // value_si = value * scale + offset
    double offset = 0.0;
};

// Splits "name [unit]" / "name(unit)" into name and unit (unit empty if none).
void splitNameAndUnit(const QString& header, QString& name, QString& unit);
// Canonical spelling of a unit ("m/s²" → "m/s^2", "°/s" → "deg/s", "µT" → "uT").
QString canonicalUnit(const QString& unit);
// The known units, sorted (only those of the same quantity as sameQuantityAs if it is a known unit).
QString knownUnitNames(const QString& sameQuantityAs = {});
// Conversion from unit to targetSi; error if they measure different quantities.
Expected<UnitConversion> conversionTo(const QString& unit, const QString& targetSi);

}  // namespace athlos
