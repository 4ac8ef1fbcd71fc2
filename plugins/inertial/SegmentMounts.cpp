#include "plugins/inertial/SegmentMounts.h"

#include <cmath>

namespace athlos::inertial {

Table segmentMountTable(const QStringList& segments, const std::vector<math::Quat>& mounts, QJsonObject attributes) {
    Table t;
    t.kind = kSegmentCalibrationKind;
    t.attributes = std::move(attributes);
    t.attributes.insert(QStringLiteral("convention"),
                        QStringLiteral("q maps segment coordinates to sensor coordinates (scalar first); "
                                       "segment orientation = sensor orientation * q"));
    TableColumn name{QStringLiteral("segment"), QString(), true, {}, segments};
    std::vector<TableColumn> q;
    for (const char* c : {"qw", "qx", "qy", "qz"})
        q.push_back(TableColumn{QLatin1String(c), QStringLiteral("1"), false, {}, {}});
    for (const math::Quat& m : mounts) {
        const math::Quat c = math::canonical(m.normalized());
        q[0].numbers.push_back(c.w());
        q[1].numbers.push_back(c.x());
        q[2].numbers.push_back(c.y());
        q[3].numbers.push_back(c.z());
    }
    t.columns = {name, q[0], q[1], q[2], q[3]};
    return t;
}

Expected<math::Quat> segmentMount(const Table& table, const QString& path, const QString& segment) {
    const TableColumn* name = table.column(QStringLiteral("segment"));
    const TableColumn* w = table.column(QStringLiteral("qw"));
    const TableColumn* x = table.column(QStringLiteral("qx"));
    const TableColumn* y = table.column(QStringLiteral("qy"));
    const TableColumn* z = table.column(QStringLiteral("qz"));
    if (!name || !name->isText || !w || !x || !y || !z || w->isText || x->isText || y->isText || z->isText)
        return makeError(
            QStringLiteral("calibration table '%1' needs a text column segment and numeric columns qw, qx, qy, qz")
                .arg(path));
    const auto row = name->texts.indexOf(segment);
    if (row < 0)
        return makeError(QStringLiteral("calibration table '%1' has no row for segment '%2' (it has: %3)")
                             .arg(path, segment, name->texts.join(QStringLiteral(", "))));
    const auto r = static_cast<std::size_t>(row);
    const math::Quat q(w->numbers.at(r), x->numbers.at(r), y->numbers.at(r), z->numbers.at(r));
    if (!q.coeffs().allFinite() || q.norm() < 1e-9)
        return makeError(
            QStringLiteral("calibration table '%1', segment '%2': the quaternion is not valid").arg(path, segment));
    return q.normalized();
}

}  // namespace athlos::inertial
