#pragma once
// The athlete's body model as stored in the project (issue #18 item 1): a table of kind "body-model" with
// one row per segment — segment, parent, proximal_joint, distal_joint, sensor (the orientation stream of the
// sensor on it, "rec/stream", may be empty), position (a GNSS or LPS position stream of an antenna on it, may
// be empty), equipment (kg: boots, helmet, skis…), mass (kg, equipment included) and length (m) — and the
// attributes height (m), mass (kg), sex, table, table_source, antenna_offset ("x,y,z" m in the antenna
// segment's coordinates from its proximal joint). body-com recomputes the geometry from height, sex and
// table; mass and length are there to read.
#include "core/model/Table.h"
#include "plugins/body/Anthropometry.h"

namespace athlos::body {

inline const QString kBodyModelKind = QStringLiteral("body-model");

struct BodyModel {
    double height = 1.75, mass = 70.0;  // m, kg
    Sex sex = Sex::Male;
    BspTable table = BspTable::Dumas2007;
    std::array<double, kSegments> equipment{};  // kg
    std::array<QString, kSegments> sensor;      // orientation stream per segment ("" = rides on its parent)
    std::array<QString, kSegments> position;    // antenna position stream ("" = none; at most one)
    Vec3 antennaOffset = Vec3::Zero();          // in the antenna segment's coordinates, from its proximal joint

    // Limits of a plausible athlete (errors name the parameter).
    static constexpr double kMinHeight = 1.0, kMaxHeight = 2.3, kMinMass = 20.0, kMaxMass = 200.0;
    Status check() const;
    int antennaSegment() const;  // -1 = none
};

QString tableSource(BspTable t);  // the citation
athlos::Table bodyModelTable(const BodyModel& model);
// Reads a body-model table; errors name `path` and the row or attribute at fault.
Expected<BodyModel> readBodyModel(const athlos::Table& table, const QString& path);
// "segment:value,segment:value" → pairs; errors name `parameter`.
Expected<std::vector<std::pair<Segment, QString>>> parseSegmentList(const QString& text, const QString& parameter);

}  // namespace athlos::body
