#include "plugins/positioning/NoiseProfile.h"

#include <cmath>
#include <limits>

namespace athlos::positioning {

namespace {

struct Entry {
    const char* name;
    const char* unit;
    double NoiseSettings::*plain = nullptr;
    double CtraNoise::*ctra = nullptr;
};

// Every field of NoiseSettings, in the order of the table.
const std::vector<Entry>& entries() {
    static const std::vector<Entry> e{{"q_position", "m^2/s", nullptr, &CtraNoise::qPosition},
                                      {"q_speed", "m^2/s^3", nullptr, &CtraNoise::qSpeed},
                                      {"q_accel", "m^2/s^5", nullptr, &CtraNoise::qAccel},
                                      {"q_accel_cv", "m^2/s^3", &NoiseSettings::qAccelCv, nullptr},
                                      {"q_heading", "rad^2/s", nullptr, &CtraNoise::qHeading},
                                      {"q_turn_rate", "rad^2/s^3", nullptr, &CtraNoise::qTurnRate},
                                      {"r_x", "m^2", nullptr, &CtraNoise::rX},
                                      {"r_y", "m^2", nullptr, &CtraNoise::rY},
                                      {"r_heading", "rad^2", &NoiseSettings::rHeading, nullptr},
                                      {"r_turn_rate", "rad^2/s^2", &NoiseSettings::rTurnRate, nullptr},
                                      {"r_accel", "m^2/s^4", &NoiseSettings::rAccel, nullptr},
                                      {"gate", "1", &NoiseSettings::gate, nullptr}};
    return e;
}

double& field(NoiseSettings& n, const Entry& e) { return e.plain ? n.*e.plain : n.ctra.*e.ctra; }

}  // namespace

QString modelKindName(ModelKind model) {
    switch (model) {
        case ModelKind::Unconstrained:
            return QStringLiteral("unconstrained");
        case ModelKind::Pseudo:
            return QStringLiteral("pseudo");
        case ModelKind::Augmented:
            return QStringLiteral("augmented");
        case ModelKind::ConstantVelocity:
            return QStringLiteral("constant-velocity");
    }
    return {};
}

Table noiseProfileTable(const NoiseProfile& profile, QJsonObject attributes) {
    Table t;
    t.kind = kNoiseProfileKind;
    t.attributes = std::move(attributes);
    t.attributes.insert(QStringLiteral("model"), modelKindName(profile.model));
    TableColumn name{QStringLiteral("parameter"), QString(), true, {}, {}};
    TableColumn value{QStringLiteral("value"), QStringLiteral("1"), false, {}, {}};
    TableColumn unit{QStringLiteral("unit"), QString(), true, {}, {}};
    NoiseSettings n = profile.noise;
    for (const Entry& e : entries()) {
        name.texts << QLatin1String(e.name);
        // An infinite gate (gating off) is stored as 0, as position-filter's `gate` parameter reads it.
        const double v = field(n, e);
        value.numbers.push_back(std::isfinite(v) ? v : 0.0);
        unit.texts << QLatin1String(e.unit);
    }
    t.columns = {name, value, unit};
    return t;
}

Expected<NoiseProfile> noiseProfileFromTable(const Table& table, const QString& path) {
    if (table.kind != kNoiseProfileKind)
        return makeError(QStringLiteral("'%1' is a table of kind '%2', not a noise profile (kind %3; write one with "
                                        "the noise-profile processor)")
                             .arg(path, table.kind, kNoiseProfileKind));
    const TableColumn* name = table.column(QStringLiteral("parameter"));
    const TableColumn* value = table.column(QStringLiteral("value"));
    if (!name || !name->isText || !value || value->isText)
        return makeError(
            QStringLiteral("noise profile '%1' needs a text column parameter and a numeric column value").arg(path));
    NoiseProfile profile;
    const QString model = table.attributes.value(QStringLiteral("model")).toString();
    bool known = false;
    for (ModelKind m : {ModelKind::Unconstrained, ModelKind::Pseudo, ModelKind::Augmented, ModelKind::ConstantVelocity})
        if (modelKindName(m) == model) {
            profile.model = m;
            known = true;
        }
    if (!known) return makeError(QStringLiteral("noise profile '%1': unknown model '%2'").arg(path, model));
    for (const Entry& e : entries()) {
        const auto row = name->texts.indexOf(QLatin1String(e.name));
        if (row < 0) return makeError(QStringLiteral("noise profile '%1' has no row '%2'").arg(path, e.name));
        const double v = value->numbers[static_cast<std::size_t>(row)];
        if (!std::isfinite(v) || v < 0.0)
            return makeError(QStringLiteral("noise profile '%1': %2 = %3 is not a variance (finite, >= 0)")
                                 .arg(path, QLatin1String(e.name))
                                 .arg(v));
        field(profile.noise, e) = v;
    }
    if (!(profile.noise.gate > 0.0)) profile.noise.gate = std::numeric_limits<double>::infinity();
    return profile;
}

}  // namespace athlos::positioning
