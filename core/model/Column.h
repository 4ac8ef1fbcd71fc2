#pragma once
#include <QString>
#include <vector>

namespace athlos {

// A named column with its SI unit ("m", "m/s^2", "rad/s", "uT", "1", "s", "deg" for geodetic angles).
struct Column {
    QString name;
    QString unit;
    bool operator==(const Column&) const = default;
};

using Columns = std::vector<Column>;

}  // namespace athlos
