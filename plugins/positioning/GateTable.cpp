#include "plugins/positioning/GateTable.h"

#include <QSet>
#include <cmath>

namespace athlos::positioning {

Expected<std::vector<Gate>> gatesFromTable(const Table& table, const QString& path) {
    const TableColumn* id = table.column(QStringLiteral("id"));
    if (!id || !id->isText)
        return makeError(
            QStringLiteral("gates table '%1': needs a text column 'id' and numeric columns east, north, up (m)")
                .arg(path));
    const TableColumn* axes[3] = {table.column(QStringLiteral("east")), table.column(QStringLiteral("north")),
                                  table.column(QStringLiteral("up"))};
    const char* names[3] = {"east", "north", "up"};
    for (int i = 0; i < 3; ++i) {
        if (!axes[i])
            return makeError(QStringLiteral("gates table '%1': no column '%2'").arg(path, QLatin1String(names[i])));
        if (axes[i]->isText)
            return makeError(
                QStringLiteral("gates table '%1': column '%2' must be numeric (m)").arg(path, QLatin1String(names[i])));
    }
    const long long rows = table.rows();
    if (rows < 2)
        return makeError(QStringLiteral("gates table '%1': needs at least two gates, has %2").arg(path).arg(rows));
    std::vector<Gate> gates;
    QSet<QString> seen;
    for (long long r = 0; r < rows; ++r) {
        const QString gid = id->texts.value(int(r)).trimmed();
        if (gid.isEmpty()) return makeError(QStringLiteral("gates table '%1': row %2: empty id").arg(path).arg(r + 1));
        if (seen.contains(gid))
            return makeError(
                QStringLiteral("gates table '%1': row %2: id '%3' appears twice").arg(path).arg(r + 1).arg(gid));
        seen.insert(gid);
        math::Vec3 p;
        for (int i = 0; i < 3; ++i) {
            const double v = axes[i]->numbers.at(std::size_t(r));
            if (!std::isfinite(v))
                return makeError(QStringLiteral("gates table '%1': row %2 (gate '%3'): column '%4' is not a number")
                                     .arg(path)
                                     .arg(r + 1)
                                     .arg(gid, QLatin1String(names[i])));
            p[i] = v;
        }
        gates.push_back({gid, p});
    }
    return gates;
}

Table gatesTable(const std::vector<Gate>& gates) {
    Table t;
    t.kind = QStringLiteral("gates");
    TableColumn id{QStringLiteral("id"), QString(), true, {}, {}};
    TableColumn east{QStringLiteral("east"), QStringLiteral("m"), false, {}, {}};
    TableColumn north{QStringLiteral("north"), QStringLiteral("m"), false, {}, {}};
    TableColumn up{QStringLiteral("up"), QStringLiteral("m"), false, {}, {}};
    for (const Gate& g : gates) {
        id.texts << g.id;
        east.numbers.push_back(g.position.x());
        north.numbers.push_back(g.position.y());
        up.numbers.push_back(g.position.z());
    }
    t.columns = {id, east, north, up};
    return t;
}

}  // namespace athlos::positioning
