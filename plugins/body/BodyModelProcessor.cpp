#include "plugins/body/BodyModelProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/body/BodyModel.h"

namespace athlos::body {

namespace {
constexpr Translator tr{"athlos::body", "BodyModelProcessor"};

bool hasColumns(const StreamInfo& info, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (info.columnIndex(QLatin1String(n)) < 0) return false;
    return true;
}

Expected<BodyModel> makeModel(const RunContext& c) {
    BodyModel m;
    m.height = c.number(QStringLiteral("height"));
    m.mass = c.number(QStringLiteral("mass"));
    auto sex = parseSex(c.text(QStringLiteral("sex")));
    if (!sex) return sex.error();
    m.sex = *sex;
    auto table = parseTable(c.text(QStringLiteral("table")));
    if (!table) return table.error();
    m.table = *table;
    auto sensors = parseSegmentList(c.text(QStringLiteral("sensors")), QStringLiteral("sensors"));
    if (!sensors) return sensors.error();
    for (const auto& [segment, path] : *sensors) {
        const Stream* s = c.project().stream(path);
        if (!s)
            return makeError(QStringLiteral("sensors: stream '%1' (on %2) not found in the project")
                                 .arg(path, segmentName(segment)));
        if (!hasColumns(s->info(), {"qw", "qx", "qy", "qz"}))
            return makeError(QStringLiteral("sensors: stream '%1' (on %2) is not an orientation stream (needs qw, qx, "
                                            "qy, qz; run orientation or drift-reduction on the IMU first)")
                                 .arg(path, segmentName(segment)));
        if (!m.sensor[static_cast<int>(segment)].isEmpty())
            return makeError(QStringLiteral("sensors: segment '%1' is given twice").arg(segmentName(segment)));
        m.sensor[static_cast<int>(segment)] = path;
    }
    auto equipment = parseSegmentList(c.text(QStringLiteral("equipment")), QStringLiteral("equipment"));
    if (!equipment) return equipment.error();
    for (const auto& [segment, kg] : *equipment) {
        bool ok = false;
        const double v = kg.toDouble(&ok);
        if (!ok)
            return makeError(QStringLiteral("equipment: '%1' on %2 is not a mass in kg").arg(kg, segmentName(segment)));
        m.equipment[static_cast<int>(segment)] += v;
    }
    auto antenna = parseSegmentList(c.text(QStringLiteral("antenna")), QStringLiteral("antenna"));
    if (!antenna) return antenna.error();
    if (antenna->size() > 1) return makeError(QStringLiteral("antenna: give one segment:stream"));
    if (!antenna->empty()) {
        const auto& [segment, path] = antenna->front();
        const Stream* s = c.project().stream(path);
        if (!s) return makeError(QStringLiteral("antenna: stream '%1' not found in the project").arg(path));
        if (!hasColumns(s->info(), {"x", "y", "z"}))
            return makeError(QStringLiteral("antenna: stream '%1' has no x, y, z columns (a GNSS stream in local ENU "
                                            "or an LPS position stream)")
                                 .arg(path));
        m.position[static_cast<int>(segment)] = path;
        const QString offset = c.text(QStringLiteral("antenna_offset"));
        if (!offset.isEmpty()) {
            const QStringList v = offset.split(QLatin1Char(','));
            bool ok = v.size() == 3;
            for (int i = 0; ok && i < 3; ++i) m.antennaOffset[i] = v[i].toDouble(&ok);
            if (!ok) return makeError(QStringLiteral("antenna_offset: '%1' is not x,y,z in m").arg(offset));
        } else {
            // Default: the helmet 3 cm above the head vertex; otherwise the segment's distal end.
            auto geometry = anthropometry(m.table, m.sex, std::clamp(m.height, 0.5, 2.5));
            if (!geometry) return geometry.error();
            m.antennaOffset = geometry->segments[static_cast<int>(segment)].distal;
            if (segment == Segment::Head) m.antennaOffset += Vec3(0.0, 0.03, 0.0);
        }
    }
    if (Status ok = m.check(); !ok) return ok.error();
    return m;
}
}  // namespace

QString BodyModelProcessor::name() const { return tr("Body model"); }

QString BodyModelProcessor::description() const {
    return tr(
        "The athlete's body model (Fasel 2017 ch. 7): 15 segments (pelvis, thorax, head, upper arms, forearms, "
        "hands, thighs, shanks, feet) with the anthropometric table scaled to height and mass (Dumas et al. 2007 "
        "Table 2 or de Leva 1996 Table 4), which orientation stream (sensor) sits on which segment, equipment "
        "masses and an optional GNSS/LPS antenna. A table of kind body-model, read by body-com.");
}

ParameterSpecs BodyModelProcessor::parameters() const {
    return {
        ParameterSpec::number(QStringLiteral("height"), 1.75, BodyModel::kMinHeight, BodyModel::kMaxHeight,
                              QStringLiteral("m"), tr("Athlete's height (scales the segment lengths).")),
        ParameterSpec::number(QStringLiteral("mass"), 70.0, BodyModel::kMinMass, BodyModel::kMaxMass,
                              QStringLiteral("kg"), tr("Athlete's body mass without equipment.")),
        ParameterSpec::choice(QStringLiteral("sex"), {QStringLiteral("male"), QStringLiteral("female")},
                              QStringLiteral("male"), tr("Selects the table's male or female column.")),
        ParameterSpec::choice(QStringLiteral("table"), {QStringLiteral("dumas-2007"), QStringLiteral("de-leva-1996")},
                              QStringLiteral("dumas-2007"),
                              tr("Anthropometric table: Dumas, Chèze & Verriest 2007 (J Biomech 40:543, Table 2) or "
                                 "de Leva 1996 (J Biomech 29:1223, Table 4).")),
        ParameterSpec::text(QStringLiteral("sensors"), QString(),
                            tr("segment:rec/stream,… — the orientation stream of the sensor on each segment (e.g. "
                               "the outputs of drift-reduction). Segments without one ride on their parent.")),
        ParameterSpec::text(QStringLiteral("equipment"), QString(),
                            tr("segment:kg,… — equipment masses (boots, helmet, skis), added at the segment's CoM.")),
        ParameterSpec::text(QStringLiteral("antenna"), QString(),
                            tr("segment:rec/stream — a GNSS (local x, y, z) or LPS position stream of an antenna on "
                               "that segment (helmet: head; back: thorax), for the absolute CoM (Fasel 2017 ch. 8).")),
        ParameterSpec::text(QStringLiteral("antenna_offset"), QString(),
                            tr("x,y,z (m): the antenna in the segment's coordinates from its proximal joint (default: "
                               "3 cm above the head vertex, or the segment's distal end).")),
    };
}

QList<OutputSpec> BodyModelProcessor::outputs() const {
    return {OutputSpec{kBodyModelKind, true, QString(),
                       tr("One row per segment: segment, parent, joints, sensor, position, equipment, mass, length.")}};
}

Status BodyModelProcessor::prepare(const RunContext& context) const { return statusOf(makeModel(context)); }

Expected<std::vector<ProcessorOutput>> BodyModelProcessor::run(const RunContext& context) const {
    auto model = makeModel(context);
    if (!model) return model.error();
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), bodyModelTable(*model)});
    return out;
}

}  // namespace athlos::body
