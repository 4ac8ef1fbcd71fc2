#include "plugins/body/BodyModel.h"

#include <QJsonObject>
#include <cmath>

namespace athlos::body {

Status BodyModel::check() const {
    if (!(height >= kMinHeight && height <= kMaxHeight))
        return makeError(QStringLiteral("height: %1 m is outside %2–%3 m").arg(height).arg(kMinHeight).arg(kMaxHeight));
    if (!(mass >= kMinMass && mass <= kMaxMass))
        return makeError(QStringLiteral("mass: %1 kg is outside %2–%3 kg").arg(mass).arg(kMinMass).arg(kMaxMass));
    for (int s = 0; s < kSegments; ++s)
        if (!(equipment[s] >= 0.0 && equipment[s] <= 50.0))
            return makeError(QStringLiteral("equipment: %1 kg on '%2' is outside 0–50 kg")
                                 .arg(equipment[s])
                                 .arg(segmentName(static_cast<Segment>(s))));
    int antennas = 0;
    for (const QString& p : position) antennas += p.isEmpty() ? 0 : 1;
    if (antennas > 1) return makeError(QStringLiteral("antenna: more than one segment carries a position stream"));
    return {};
}

int BodyModel::antennaSegment() const {
    for (int s = 0; s < kSegments; ++s)
        if (!position[s].isEmpty()) return s;
    return -1;
}

QString tableSource(BspTable t) {
    return t == BspTable::Dumas2007 ? QStringLiteral("Dumas, Cheze, Verriest 2007, J Biomech 40:543-553, Table 2")
                                    : QStringLiteral("de Leva 1996, J Biomech 29:1223-1230, Table 4");
}

athlos::Table bodyModelTable(const BodyModel& m) {
    athlos::Table t;
    t.kind = kBodyModelKind;
    t.attributes = QJsonObject{
        {"height", m.height},
        {"mass", m.mass},
        {"sex", sexName(m.sex)},
        {"table", tableName(m.table)},
        {"table_source", tableSource(m.table)},
        {"antenna_offset",
         QStringLiteral("%1,%2,%3").arg(m.antennaOffset.x()).arg(m.antennaOffset.y()).arg(m.antennaOffset.z())},
        {"arms", QStringLiteral("segments without a sensor ride rigidly on their parent "
                                "(arms on the thorax in a fixed posture)")}};
    const auto text = [](const char* name) { return TableColumn{QLatin1String(name), QString(), true, {}, {}}; };
    const auto number = [](const char* name, const char* unit) {
        return TableColumn{QLatin1String(name), QLatin1String(unit), false, {}, {}};
    };
    TableColumn segment = text("segment"), parent = text("parent"), proximal = text("proximal_joint"),
                distal = text("distal_joint"), sensor = text("sensor"), position = text("position"),
                equipment = number("equipment", "kg"), mass = number("mass", "kg"), length = number("length", "m");
    const auto geometry = anthropometry(m.table, m.sex, m.height);
    for (int s = 0; s < kSegments; ++s) {
        const Segment seg = static_cast<Segment>(s);
        segment.texts << segmentName(seg);
        parent.texts << (s == 0 ? QString() : segmentName(parentSegment(seg)));
        proximal.texts << jointName(proximalJoint(seg));
        const int d = distalJoint(seg);
        distal.texts << (d >= 0 ? jointName(static_cast<Joint>(d)) : QString());
        sensor.texts << m.sensor[s];
        position.texts << m.position[s];
        equipment.numbers.push_back(m.equipment[s]);
        mass.numbers.push_back(geometry ? geometry->segments[s].massFraction * m.mass + m.equipment[s] : NAN);
        length.numbers.push_back(
            geometry ? (seg == Segment::Pelvis ? geometry->rightHip.y() * -1.0 : geometry->segments[s].distal.norm())
                     : NAN);
    }
    t.columns = {segment, parent, proximal, distal, sensor, position, equipment, mass, length};
    return t;
}

Expected<BodyModel> readBodyModel(const athlos::Table& t, const QString& path) {
    const auto fail = [&](const QString& what) {
        return makeError(QStringLiteral("body model '%1': %2").arg(path, what));
    };
    if (t.kind != kBodyModelKind) return fail(QStringLiteral("kind is '%1', not '%2'").arg(t.kind, kBodyModelKind));
    BodyModel m;
    m.height = t.attributes.value(QStringLiteral("height")).toDouble(NAN);
    m.mass = t.attributes.value(QStringLiteral("mass")).toDouble(NAN);
    auto sex = parseSex(t.attributes.value(QStringLiteral("sex")).toString());
    if (!sex) return fail(sex.error().message);
    m.sex = *sex;
    auto table = parseTable(t.attributes.value(QStringLiteral("table")).toString());
    if (!table) return fail(table.error().message);
    m.table = *table;
    const QStringList offset = t.attributes.value(QStringLiteral("antenna_offset")).toString().split(QLatin1Char(','));
    if (offset.size() == 3)
        for (int i = 0; i < 3; ++i) m.antennaOffset[i] = offset[i].toDouble();
    const TableColumn* segment = t.column(QStringLiteral("segment"));
    const TableColumn* sensor = t.column(QStringLiteral("sensor"));
    const TableColumn* position = t.column(QStringLiteral("position"));
    const TableColumn* equipment = t.column(QStringLiteral("equipment"));
    if (!segment || !segment->isText || !sensor || !sensor->isText || !position || !position->isText || !equipment ||
        equipment->isText)
        return fail(QStringLiteral("needs the columns segment, sensor, position (text) and equipment (kg)"));
    std::array<bool, kSegments> seen{};
    for (long long r = 0; r < t.rows(); ++r) {
        auto s = parseSegment(segment->texts[r]);
        if (!s) return fail(QStringLiteral("row %1: %2").arg(r + 1).arg(s.error().message));
        const int i = static_cast<int>(*s);
        if (seen[i])
            return fail(QStringLiteral("row %1: segment '%2' appears twice").arg(r + 1).arg(segment->texts[r]));
        seen[i] = true;
        m.sensor[i] = sensor->texts[r];
        m.position[i] = position->texts[r];
        m.equipment[i] = equipment->numbers[r];
    }
    for (int s = 0; s < kSegments; ++s)
        if (!seen[s]) return fail(QStringLiteral("segment '%1' is missing").arg(segmentName(static_cast<Segment>(s))));
    if (Status ok = m.check(); !ok) return fail(ok.error().message);
    return m;
}

Expected<std::vector<std::pair<Segment, QString>>> parseSegmentList(const QString& text, const QString& parameter) {
    std::vector<std::pair<Segment, QString>> out;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const int colon = item.indexOf(QLatin1Char(':'));
        if (colon <= 0)
            return makeError(QStringLiteral("%1: '%2' is not segment:value").arg(parameter, item.trimmed()));
        auto s = parseSegment(item.left(colon).trimmed());
        if (!s) return makeError(QStringLiteral("%1: %2").arg(parameter, s.error().message));
        out.emplace_back(*s, item.mid(colon + 1).trimmed());
    }
    return out;
}

}  // namespace athlos::body
