#include "plugins/lps/BeaconTable.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <cmath>
#include <optional>

namespace athlos::lps {

bool isReferenceId(const QString& id) {
    const QString lower = id.trimmed().toLower();
    return lower == QLatin1String("ref") || lower == QLatin1String("reference");
}

namespace {

QString idText(const TableColumn& column, long long row) {
    if (column.isText) return column.texts.at(row).trimmed();
    return QString::number(column.numbers.at(size_t(row)), 'g', 17);
}

std::optional<long long> trailingNumber(const QString& id) {
    static const QRegularExpression digits(QStringLiteral("(\\d+)$"));
    const auto match = digits.match(id);
    if (!match.hasMatch()) return std::nullopt;
    return match.captured(1).toLongLong();
}

}  // namespace

Expected<BeaconLayout> layoutFromTable(const Table& table, const QString& path, int minimum, const QString& use) {
    const TableColumn* id = table.column(QStringLiteral("id"));
    const TableColumn* x = table.column(QStringLiteral("x"));
    const TableColumn* y = table.column(QStringLiteral("y"));
    const TableColumn* z = table.column(QStringLiteral("z"));
    if (!id || !x || !y)
        return makeError(QStringLiteral("beacon table '%1' needs columns id, x, y (and z); it has: %2").arg(path, [&] {
            QStringList names;
            for (const auto& c : table.columns) names << c.name;
            return names.join(QStringLiteral(", "));
        }()));
    for (const TableColumn* c : {x, y, z})
        if (c && c->isText)
            return makeError(QStringLiteral("beacon table '%1': column %2 must be numeric (m)").arg(path, c->name));

    BeaconLayout layout;
    bool referenceRow = false;
    for (long long r = 0; r < table.rows(); ++r) {
        const QString name = idText(*id, r);
        const Vector3 p(x->numbers[size_t(r)], y->numbers[size_t(r)], z ? z->numbers[size_t(r)] : 0.0);
        if (!p.allFinite())
            return makeError(QStringLiteral("beacon table '%1', row %2 (id %3): coordinates must be finite numbers")
                                 .arg(path)
                                 .arg(r + 1)
                                 .arg(name));
        if (isReferenceId(name)) {
            layout.reference = p;
            referenceRow = true;
            continue;
        }
        if (layout.ids.contains(name))
            return makeError(QStringLiteral("beacon table '%1': id %2 appears twice").arg(path, name));
        layout.ids << name;
        layout.positions.push_back(p);
    }
    if (!referenceRow) {
        const QJsonArray ref = table.attributes.value(QStringLiteral("reference_node")).toArray();
        if (ref.size() == 3) layout.reference = Vector3(ref[0].toDouble(), ref[1].toDouble(), ref[2].toDouble());
    }
    if (layout.size() < minimum)
        return makeError(QStringLiteral("beacon table '%1' has %2 beacon(s); %3 needs at least %4")
                             .arg(path)
                             .arg(layout.size())
                             .arg(use)
                             .arg(minimum));
    return layout;
}

Table tableFromLayout(const BeaconLayout& layout, const QString& name) {
    Table table;
    table.name = name;
    table.kind = QStringLiteral("beacons");
    TableColumn id{QStringLiteral("id"), QString(), true, {}, {}};
    TableColumn x{QStringLiteral("x"), QStringLiteral("m"), false, {}, {}};
    TableColumn y = x, z = x;
    y.name = QStringLiteral("y");
    z.name = QStringLiteral("z");
    auto add = [&](const QString& label, const Vector3& p) {
        id.texts << label;
        x.numbers.push_back(p.x());
        y.numbers.push_back(p.y());
        z.numbers.push_back(p.z());
    };
    for (int i = 0; i < layout.size(); ++i) add(layout.ids.value(i), layout.positions[size_t(i)]);
    if (!layout.reference.isZero(0.0)) add(QStringLiteral("ref"), layout.reference);
    table.attributes.insert(QStringLiteral("reference_node"),
                            QJsonArray{layout.reference.x(), layout.reference.y(), layout.reference.z()});
    table.columns = {std::move(id), std::move(x), std::move(y), std::move(z)};
    return table;
}

int matchBeaconId(const BeaconLayout& layout, const QString& id) {
    const QString trimmed = id.trimmed();
    if (const int exact = layout.ids.indexOf(trimmed); exact >= 0) return exact;
    bool numeric = false;
    const double value = trimmed.toDouble(&numeric);
    if (numeric) {
        for (int i = 0; i < int(layout.ids.size()); ++i) {
            bool ok = false;
            const double other = layout.ids[i].toDouble(&ok);
            if (ok && other == value) return i;
        }
        if (value == std::round(value)) {
            int found = -1;
            for (int i = 0; i < int(layout.ids.size()); ++i) {
                if (trailingNumber(layout.ids[i]) == static_cast<long long>(value)) {
                    if (found >= 0) return -1;  // ambiguous ("A1" and "B1")
                    found = i;
                }
            }
            return found;
        }
    }
    return -1;
}

}  // namespace athlos::lps
