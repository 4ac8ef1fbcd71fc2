#include "ui/PlotLanes.h"

#include <QRegularExpression>
#include <algorithm>

namespace athlos::ui {

QString PlotLanes::family(const QString& name) {
    // Components: axes (x y z w), local-frame directions after a separator (e n u), or an index.
    static const QRegularExpression suffix(QStringLiteral("^(.+?)[_.\\- ]+([xyzwenu]|[0-9]+)$"),
                                           QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch match = suffix.match(name.trimmed());
    return match.hasMatch() ? match.captured(1).toLower() : QString();
}

PlotLanes::Assignment PlotLanes::assign(const std::vector<Column>& columns, int maxLanes) {
    maxLanes = std::max(1, maxLanes);
    auto keysBy = [&](bool withFamily) {
        std::vector<QString> keys;
        for (const Column& c : columns)
            keys.push_back((withFamily ? family(c.name) : QString()) + QLatin1Char('\x1f') + c.unit);
        return keys;
    };
    auto distinct = [](const std::vector<QString>& keys) {
        std::vector<QString> order;
        for (const QString& k : keys)
            if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
        return order;
    };
    std::vector<QString> keys = keysBy(true);
    std::vector<QString> order = distinct(keys);
    if (int(order.size()) > maxLanes) {
        keys = keysBy(false);
        order = distinct(keys);
    }
    Assignment result;
    const int lanes = std::min(int(order.size()), maxLanes);
    result.unit.assign(std::size_t(lanes), QString());
    std::vector<bool> unitSet(std::size_t(lanes), false), mixed(std::size_t(lanes), false);
    for (std::size_t i = 0; i < columns.size(); ++i) {
        const int lane = std::min(int(std::find(order.begin(), order.end(), keys[i]) - order.begin()), lanes - 1);
        result.laneOf.push_back(lane);
        const auto l = std::size_t(lane);
        if (!unitSet[l]) {
            result.unit[l] = columns[i].unit;
            unitSet[l] = true;
        } else if (result.unit[l] != columns[i].unit) {
            mixed[l] = true;
        }
    }
    for (std::size_t l = 0; l < result.unit.size(); ++l)
        if (mixed[l]) result.unit[l].clear();
    return result;
}

}  // namespace athlos::ui
