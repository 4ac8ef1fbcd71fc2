#pragma once
// Stacked sub-plots of a time-series panel: which lane (axis rect, one y axis) each plotted column
// goes to. Columns of one channel family and one unit share a lane (acc_x, acc_y, acc_z [m/s^2];
// gyr_* [rad/s]; x, y, z [m]; lat, lon [deg]), so no y axis mixes units or scales as different as
// an accelerometer's and a gyroscope's. All lanes share the time axis.
#include <QString>
#include <vector>

namespace athlos::ui {

struct PlotLanes {
    static constexpr int kMaxLanes = 6;  // beyond this a lane gets too short to read

    struct Column {
        QString name, unit;
    };
    struct Assignment {
        std::vector<int> laneOf;    // per column
        std::vector<QString> unit;  // per lane: the unit its y axis shows (empty when mixed)
        int count() const { return int(unit.size()); }
    };

    // The family of a column name: the name without a component suffix after a separator
    // ("acc_x" → "acc", "left_gyr_z" → "left_gyr", "q.w" → "q"); single-letter names (x, y, z) and
    // names without such a suffix have no family ("") and group by unit alone.
    static QString family(const QString& name);

    // Lanes in order of first appearance, keyed by family and unit; with more than maxLanes keys,
    // by unit alone; with still more, the last lane takes the rest.
    static Assignment assign(const std::vector<Column>& columns, int maxLanes = kMaxLanes);
};

}  // namespace athlos::ui
