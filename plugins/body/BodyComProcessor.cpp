#include "plugins/body/BodyComProcessor.h"

#include "core/math/Angles.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/body/BodyCom.h"
#include "plugins/body/BodyModel.h"
#include "plugins/inertial/SegmentMounts.h"

#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos::body {

namespace {
constexpr Translator tr{"athlos::body", "BodyComProcessor"};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
enum Input { ModelIn = 0, MountsIn, LeftMountsIn, VectorsIn };

// Segments whose orientation the chain cannot do without.
constexpr std::array<Segment, 6> kRequired{Segment::Pelvis,     Segment::Thorax,    Segment::RightThigh,
                                           Segment::RightShank, Segment::LeftThigh, Segment::LeftShank};

QString genericName(Segment s) {
    QString n = segmentName(s);
    if (n.startsWith(QLatin1String("right-"))) return n.mid(6);
    if (n.startsWith(QLatin1String("left-"))) return n.mid(5);
    return n;
}

Vec3 parseVector(const QString& text, bool& ok) {
    const QStringList v = text.split(QLatin1Char(','));
    ok = v.size() == 3;
    Vec3 r = Vec3::Zero();
    for (int i = 0; ok && i < 3; ++i) r[i] = v[i].toDouble(&ok);
    return r;
}

struct Plan {
    BodyModel model;
    BodyCom::Params params;
    std::array<Quat, kSegments> mount;
    std::array<const Stream*, kSegments> stream{};
    std::array<std::shared_ptr<const StreamData>, kSegments> data{};
    std::array<std::array<int, 4>, kSegments> columns{};
    QString vectorsSource;
    QStringList identityMounts;
    const Stream* antenna = nullptr;
    std::shared_ptr<const StreamData> antennaData;
    double speedWindow = 0.5;
    double alignSeconds = 0.0;  // > 0: align each segment's heading to the pelvis over the first seconds
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    auto modelTable = c.requireTable(ModelIn);
    if (!modelTable) return modelTable.error();
    auto model = readBodyModel(**modelTable, c.inputPath(ModelIn));
    if (!model) return model.error();
    plan.model = *model;
    const BodyModel& m = plan.model;
    auto geometry = anthropometry(m.table, m.sex, m.height);
    if (!geometry) return geometry.error();
    BodyCom::Params& p = plan.params;
    p.geometry = *geometry;
    p.mass = BodyCom::segmentMasses(*geometry, m.mass, m.equipment);
    p.shoulderFlexion = c.number(QStringLiteral("shoulder_flexion"));
    p.elbowFlexion = c.number(QStringLiteral("elbow_flexion"));
    plan.speedWindow = c.number(QStringLiteral("speed_window"));
    if (c.text(QStringLiteral("heading")) == QLatin1String("align-start")) plan.alignSeconds = 2.0;

    for (Segment s : kRequired)
        if (m.sensor[static_cast<int>(s)].isEmpty())
            return makeError(QStringLiteral("body model '%1': segment '%2' has no sensor; the chain needs pelvis, "
                                            "thorax, thighs and shanks (set sensors=%2:rec/stream in body-model)")
                                 .arg(c.inputPath(ModelIn), segmentName(s)));
    // Orientation streams on one time axis.
    for (int s = 0; s < kSegments; ++s) {
        if (m.sensor[s].isEmpty()) continue;
        const QString name = segmentName(static_cast<Segment>(s));
        const Stream* stream = c.project().stream(m.sensor[s]);
        if (!stream)
            return makeError(QStringLiteral("segment '%1': its sensor stream '%2' is not in the project (body model "
                                            "'%3')")
                                 .arg(name, m.sensor[s], c.inputPath(ModelIn)));
        int i = 0;
        for (const char* col : {"qw", "qx", "qy", "qz"}) {
            plan.columns[s][i] = stream->info().columnIndex(QLatin1String(col));
            if (plan.columns[s][i++] < 0)
                return makeError(QStringLiteral("segment '%1': stream '%2' has no orientation (column %3 missing)")
                                     .arg(name, m.sensor[s], QLatin1String(col)));
        }
        auto data = stream->data();
        if (!data)
            return makeError(QStringLiteral("segment '%1': stream '%2': %3").arg(name, m.sensor[s], data.message()));
        plan.stream[s] = stream;
        plan.data[s] = *data;
        if (plan.data[s]->rows() < 2)
            return makeError(
                QStringLiteral("segment '%1': stream '%2' has fewer than 2 samples").arg(name, m.sensor[s]));
        if (s > 0 && plan.data[s]->t != plan.data[0]->t)
            return makeError(
                QStringLiteral("segment '%1': stream '%2' is not on the time axis of the pelvis' '%3' (the "
                               "sensors must be sampled together)")
                    .arg(name, m.sensor[s], m.sensor[0]));
    }
    // Mounts: segment orientation = sensor orientation × mount.
    for (int s = 0; s < kSegments; ++s) {
        const Segment seg = static_cast<Segment>(s);
        plan.mount[s] = Quat::Identity();
        if (m.sensor[s].isEmpty()) continue;
        const int which = isLeft(seg) ? LeftMountsIn : MountsIn;
        bool found = false;
        for (int t : {MountsIn, LeftMountsIn}) {
            const Table* table = c.table(t);
            if (!table || !table->column(QStringLiteral("segment"))) continue;
            const QStringList& names = table->column(QStringLiteral("segment"))->texts;
            const QString name = names.contains(segmentName(seg))                   ? segmentName(seg)
                                 : (t == which && names.contains(genericName(seg))) ? genericName(seg)
                                                                                    : QString();
            if (name.isEmpty()) continue;
            auto q = inertial::segmentMount(*table, c.inputPath(t), name);
            if (!q) return q.error();
            plan.mount[s] = *q;
            found = true;
            break;
        }
        if (!found) plan.identityMounts << segmentName(seg);
    }
    // Measured joint vectors, in segment coordinates.
    const auto toSegment = [&](Segment s, const Vec3& v) {
        return Vec3(plan.mount[static_cast<int>(s)].conjugate() * v);
    };
    const QString vectors = c.text(QStringLiteral("vectors"));
    const Table* vt = c.table(VectorsIn);
    if (vectors == QLatin1String("table") && !vt)
        return makeError(QStringLiteral("vectors=table needs the joint-vectors input (a sensor-to-joint table)"));
    if (vt && vectors != QLatin1String("model")) {
        const TableColumn* joint = vt->column(QStringLiteral("joint"));
        std::array<const TableColumn*, 6> v{};
        int i = 0;
        for (const char* col : {"rp_x", "rp_y", "rp_z", "rd_x", "rd_y", "rd_z"})
            v[i++] = vt->column(QLatin1String(col));
        if (!joint || std::any_of(v.begin(), v.end(), [](const TableColumn* col) { return !col || col->isText; }))
            return makeError(QStringLiteral("joint vectors '%1': needs columns joint, rp_x..z, rd_x..z")
                                 .arg(c.inputPath(VectorsIn)));
        const auto row = [&](const char* name, bool proximal) -> Expected<Vec3> {
            const auto r = joint->texts.indexOf(QLatin1String(name));
            if (r < 0)
                return makeError(QStringLiteral("joint vectors '%1': no row for joint '%2'")
                                     .arg(c.inputPath(VectorsIn), QLatin1String(name)));
            const int o = proximal ? 0 : 3;
            return Vec3(v[o]->numbers[r], v[o + 1]->numbers[r], v[o + 2]->numbers[r]);
        };
        auto lumbar = row("lumbar", true);
        if (!lumbar) return lumbar.error();
        for (int side = 0; side < 2; ++side) {
            const bool right = side == 0;
            auto hipP = row(right ? "right-hip" : "left-hip", true),
                 hipD = row(right ? "right-hip" : "left-hip", false);
            auto kneeP = row(right ? "right-knee" : "left-knee", true),
                 kneeD = row(right ? "right-knee" : "left-knee", false);
            auto ankleP = row(right ? "right-ankle" : "left-ankle", true);
            for (auto* e : {&hipP, &hipD, &kneeP, &kneeD, &ankleP})
                if (!*e) return e->error();
            const Segment thigh = right ? Segment::RightThigh : Segment::LeftThigh;
            const Segment shank = right ? Segment::RightShank : Segment::LeftShank;
            (right ? p.rightHip : p.leftHip) = toSegment(Segment::Pelvis, *hipP - *lumbar);
            (right ? p.rightKnee : p.leftKnee) = toSegment(thigh, *kneeP - *hipD);
            (right ? p.rightAnkle : p.leftAnkle) = toSegment(shank, *ankleP - *kneeD);
        }
        plan.vectorsSource = QStringLiteral("table ") + c.inputPath(VectorsIn);
    } else if (vectors == QLatin1String("attributes") || vectors == QLatin1String("auto")) {
        // drift-reduction writes each distal segment's vectors into its output: sensor_to_joint (distal sensor →
        // the joint with its proximal segment) and proximal_sensor_to_joint.
        const auto attr = [&](Segment s, const char* key, Vec3& out) {
            const Stream* st = plan.stream[static_cast<int>(s)];
            if (!st) return false;
            bool ok = false;
            out = parseVector(st->info().attributes.value(QLatin1String(key)).toString(), ok);
            return ok;
        };
        Vec3 lumbar, hipP[2], hipD[2], kneeP[2], kneeD[2], ankleP[2];
        bool all = attr(Segment::Thorax, "proximal_sensor_to_joint", lumbar);
        for (int side = 0; side < 2; ++side) {
            const int o = 3 * side;
            all = all && attr(static_cast<Segment>(9 + o), "proximal_sensor_to_joint", hipP[side]) &&
                  attr(static_cast<Segment>(9 + o), "sensor_to_joint", hipD[side]) &&
                  attr(static_cast<Segment>(10 + o), "proximal_sensor_to_joint", kneeP[side]) &&
                  attr(static_cast<Segment>(10 + o), "sensor_to_joint", kneeD[side]) &&
                  attr(static_cast<Segment>(11 + o), "proximal_sensor_to_joint", ankleP[side]);
        }
        if (all) {
            p.rightHip = toSegment(Segment::Pelvis, hipP[0] - lumbar);
            p.leftHip = toSegment(Segment::Pelvis, hipP[1] - lumbar);
            p.rightKnee = toSegment(Segment::RightThigh, kneeP[0] - hipD[0]);
            p.leftKnee = toSegment(Segment::LeftThigh, kneeP[1] - hipD[1]);
            p.rightAnkle = toSegment(Segment::RightShank, ankleP[0] - kneeD[0]);
            p.leftAnkle = toSegment(Segment::LeftShank, ankleP[1] - kneeD[1]);
            plan.vectorsSource = QStringLiteral("drift-reduction attributes");
        } else if (vectors == QLatin1String("attributes")) {
            return makeError(
                QStringLiteral("vectors=attributes: the sensor streams of the model lack drift-reduction's "
                               "sensor_to_joint attributes (thorax, thighs, shanks and feet needed)"));
        }
    }
    if (plan.vectorsSource.isEmpty()) plan.vectorsSource = QStringLiteral("anthropometric table");
    // Plausibility of measured segment lengths: a result that cannot be right is refused.
    for (const auto& [v, what] : {std::pair{p.rightKnee, "right thigh"}, std::pair{p.leftKnee, "left thigh"},
                                  std::pair{p.rightAnkle, "right shank"}, std::pair{p.leftAnkle, "left shank"}})
        if (v && !(v->norm() > 0.12 * m.height && v->norm() < 0.40 * m.height))
            return makeError(QStringLiteral("the measured %1 length %2 m (%3) is implausible for a height of %4 m")
                                 .arg(QLatin1String(what))
                                 .arg(v->norm(), 0, 'f', 3)
                                 .arg(plan.vectorsSource)
                                 .arg(m.height));
    // Antenna.
    if (const int a = m.antennaSegment(); a >= 0) {
        plan.antenna = c.project().stream(m.position[a]);
        if (!plan.antenna)
            return makeError(QStringLiteral("segment '%1': its antenna stream '%2' is not in the project")
                                 .arg(segmentName(static_cast<Segment>(a)), m.position[a]));
        auto data = plan.antenna->data();
        if (!data) return makeError(QStringLiteral("antenna stream '%1': %2").arg(m.position[a], data.message()));
        plan.antennaData = *data;
        for (const char* col : {"x", "y", "z"})
            if (plan.antenna->info().columnIndex(QLatin1String(col)) < 0)
                return makeError(
                    QStringLiteral("antenna stream '%1' has no column %2").arg(m.position[a], QLatin1String(col)));
    }
    return plan;
}

Quat sample(const Plan& plan, int s, std::size_t k) {
    const StreamData& d = *plan.data[s];
    const auto& c = plan.columns[s];
    return Quat(d.at(k, c[0]), d.at(k, c[1]), d.at(k, c[2]), d.at(k, c[3]));
}
}  // namespace

QString BodyComProcessor::name() const { return tr("Centre of mass (body model)"); }

QString BodyComProcessor::description() const {
    return tr(
        "Joint centres and centre of mass relative to the lumbar joint centre (ENU axes) through the kinematic chain "
        "p_hip = R_pelvis v_hip, p_knee = p_hip + R_thigh v_knee, … (Fasel 2017 ch. 7) with the body model's "
        "anthropometric table; segment orientations = sensor orientation × mount. Sensor-to-joint vectors from a "
        "table or drift-reduction's attributes replace the table's thigh/shank/pelvis lengths. Head and arms without "
        "sensors ride on the thorax (arms in a fixed posture). Also the fore-aft CoM against the feet and, with an "
        "antenna in the model, the absolute CoM = antenna + chain offset and its speed (ch. 8).");
}

ParameterSpecs BodyComProcessor::parameters() const {
    return {
        ParameterSpec::choice(
            QStringLiteral("vectors"),
            {QStringLiteral("auto"), QStringLiteral("table"), QStringLiteral("attributes"), QStringLiteral("model")},
            QStringLiteral("auto"),
            tr("Joint vectors: the joint-vectors table, drift-reduction's sensor_to_joint attributes "
               "of the sensor streams, or the anthropometric table only (auto: the first present).")),
        ParameterSpec::number(QStringLiteral("shoulder_flexion"), 20.0 * math::kDeg, -std::numbers::pi,
                              std::numbers::pi, QStringLiteral("rad"),
                              tr("Fixed arm posture on the thorax: shoulder flexion (a skier holding the poles; "
                                 "an assumption, arms carry no sensor).")),
        ParameterSpec::number(QStringLiteral("elbow_flexion"), 60.0 * math::kDeg, 0.0, std::numbers::pi,
                              QStringLiteral("rad"), tr("Fixed arm posture: elbow flexion.")),
        ParameterSpec::choice(QStringLiteral("heading"), {QStringLiteral("none"), QStringLiteral("align-start")},
                              QStringLiteral("none"),
                              tr("none: the orientations share one heading (drift-reduction outputs, 9D); align-start: "
                                 "6D orientations with unrelated headings, each segment turned about the vertical so "
                                 "its anterior axis matches the pelvis' over the first 2 s (standing upright).")),
        ParameterSpec::number(QStringLiteral("speed_window"), 0.5, 0.0, 10.0, QStringLiteral("s"),
                              tr("Absolute CoM speed: central difference over this span (antenna noise).")),
    };
}

QList<InputSpec> BodyComProcessor::inputs() const {
    return {InputSpec{QStringLiteral("model"), {kBodyModelKind}, true, false, tr("Body model (body-model).")},
            InputSpec{QStringLiteral("mounts"),
                      {inertial::kSegmentCalibrationKind},
                      true,
                      true,
                      tr("Sensor mounts (segment-calibration): pelvis, thorax, right leg (or full segment names); "
                         "absent = sensors aligned with their segments.")},
            InputSpec{QStringLiteral("left-mounts"),
                      {inertial::kSegmentCalibrationKind},
                      true,
                      true,
                      tr("Mounts of the left leg (thigh, shank, foot).")},
            InputSpec{QStringLiteral("joint-vectors"),
                      {QStringLiteral("sensor-to-joint")},
                      true,
                      true,
                      tr("Sensor-to-joint vectors (joint, rp_x..z, rd_x..z in the sensors' frames).")}};
}

QList<OutputSpec> BodyComProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("centre-of-mass"), false, QString(),
                       tr("com_x, com_y, com_z (m, relative to the lumbar joint centre, ENU axes), fore_aft and "
                          "above_ankles (m, against the mid-ankle point along the feet's heading / vertical).")},
            OutputSpec{QStringLiteral("joint-centres"), false, QStringLiteral("joints"),
                       tr("<joint>_x..z of the 15 joints (m, relative to the lumbar joint centre, ENU axes).")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("absolute"),
                       tr("Only with an antenna: the absolute CoM x, y, z (m, the antenna stream's frame), vx, vy, vz "
                          "and speed (m/s) on the antenna's time axis (a trajectory: drawn on the venue).")}};
}

Status BodyComProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> BodyComProcessor::run(const RunContext& context) const {
    auto planned = makePlan(context);
    if (!planned) return planned.error();
    const Plan& plan = *planned;
    // The sensor and antenna streams the body model names are inputs of the result: recorded so provenance
    // lists them and `athlos batch` sees them change.
    for (int s = 0; s < kSegments; ++s)
        if (plan.stream[s]) context.recordRead(plan.model.sensor[s], plan.stream[s]->info().contentHash);
    if (plan.antenna)
        context.recordRead(plan.model.position[plan.model.antennaSegment()], plan.antenna->info().contentHash);
    const BodyCom com(plan.params);
    const StreamData& axis = *plan.data[0];
    const std::size_t n = axis.rows();
    StreamData main(n, 5), joints(n, 3 * kJoints);
    main.t = axis.t;
    joints.t = axis.t;
    const int antennaSegment = plan.model.antennaSegment();
    std::vector<Vec3> antennaOffset(antennaSegment >= 0 ? n : 0);  // CoM − antenna, from the chain
    // Heading alignment (heading=align-start): circular mean of the pelvis' minus the segment's anterior-axis yaw.
    std::array<Quat, kSegments> align;
    align.fill(Quat::Identity());
    if (plan.alignSeconds > 0.0) {
        const auto yaw = [](const Quat& q) {
            const Vec3 x = q * Vec3::UnitX();
            return std::atan2(x.y(), x.x());
        };
        for (int s = 1; s < kSegments; ++s) {
            if (!plan.data[s]) continue;
            double cs = 0.0, sn = 0.0;
            for (std::size_t k = 0; k < n && axis.t[k] - axis.t[0] <= plan.alignSeconds; ++k) {
                const double d = yaw(sample(plan, 0, k).normalized() * plan.mount[0]) -
                                 yaw(sample(plan, s, k).normalized() * plan.mount[s]);
                cs += std::cos(d);
                sn += std::sin(d);
            }
            align[s] = math::quatFromAxisAngle(Vec3::UnitZ(), std::atan2(sn, cs));
        }
    }
    std::array<std::optional<Quat>, kSegments> q;
    for (std::size_t k = 0; k < n; ++k) {
        if (k % 4096 == 0) {
            if (context.isCancelled()) return cancelledError();
            context.report(0.9 * double(k) / double(n), QStringLiteral("chain"));
        }
        for (int s = 0; s < kSegments; ++s) {
            q[s].reset();
            if (!plan.data[s]) continue;
            const Quat sensor = sample(plan, s, k);
            if (!sensor.coeffs().allFinite() || sensor.norm() < 1e-9)
                return makeError(QStringLiteral("segment '%1': stream '%2' row %3 holds no valid quaternion")
                                     .arg(segmentName(static_cast<Segment>(s)), plan.model.sensor[s])
                                     .arg(k));
            q[s] = align[s] * sensor.normalized() * plan.mount[s];
        }
        const BodyCom::Pose pose = com.update(q);
        for (int i = 0; i < 3; ++i) main.at(k, i) = pose.com[i];
        main.at(k, 3) = pose.foreAft;
        main.at(k, 4) = pose.aboveAnkles;
        for (int j = 0; j < kJoints; ++j)
            for (int i = 0; i < 3; ++i) joints.at(k, 3 * j + i) = pose.joint[j][i];
        if (antennaSegment >= 0)
            antennaOffset[k] =
                pose.com - BodyCom::pointOn(pose, static_cast<Segment>(antennaSegment), plan.model.antennaOffset);
    }
    QJsonObject attributes{{"origin", QStringLiteral("lumbar joint centre")},
                           {"table", tableName(plan.model.table)},
                           {"table_source", tableSource(plan.model.table)},
                           {"joint_vectors", plan.vectorsSource},
                           {"rigid_on_parent", QStringLiteral("segments without a sensor ride on their parent; arms on "
                                                              "the thorax in a fixed posture")}};
    if (!plan.identityMounts.isEmpty())
        attributes.insert(QStringLiteral("identity_mounts"), plan.identityMounts.join(QLatin1Char(',')));
    QJsonObject sources;
    for (int s = 0; s < kSegments; ++s)
        if (plan.stream[s])
            sources.insert(plan.model.sensor[s], QString::fromLatin1(plan.stream[s]->info().contentHash));
    attributes.insert(QStringLiteral("orientation_inputs"), sources);
    QStringList jointColumns, jointUnits;
    for (int j = 0; j < kJoints; ++j)
        for (const char* a : {"_x", "_y", "_z"}) {
            jointColumns << jointName(static_cast<Joint>(j)) + QLatin1String(a);
            jointUnits << QStringLiteral("m");
        }
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), outputStream(QStringLiteral("centre-of-mass"), QStringLiteral("pelvis-ENU"),
                                           columnsOf({"com_x", "com_y", "com_z", "fore_aft", "above_ankles"},
                                                     {"m", "m", "m", "m", "m"}),
                                           std::move(main), attributes)});
    out.push_back(
        {QStringLiteral("joints"), outputStream(QStringLiteral("joint-centres"), QStringLiteral("pelvis-ENU"),
                                                columnsOf(jointColumns, jointUnits), std::move(joints), attributes)});
    if (antennaSegment >= 0) {
        // Absolute CoM on the antenna's time axis inside the orientation span: antenna + (CoM − antenna) of the
        // chain, linearly interpolated between orientation samples.
        const StreamData& g = *plan.antennaData;
        const int cx = plan.antenna->info().columnIndex(QStringLiteral("x"));
        const int cy = plan.antenna->info().columnIndex(QStringLiteral("y"));
        const int cz = plan.antenna->info().columnIndex(QStringLiteral("z"));
        std::vector<double> t;
        std::vector<Vec3> p;
        for (std::size_t r = 0; r < g.rows(); ++r) {
            const double tr = g.t[r];
            if (tr < axis.t.front() || tr > axis.t.back()) continue;
            const Vec3 a(g.at(r, cx), g.at(r, cy), g.at(r, cz));
            if (!a.allFinite()) continue;
            const auto it = std::upper_bound(axis.t.begin(), axis.t.end(), tr);
            const std::size_t k1 = std::min<std::size_t>(n - 1, std::size_t(it - axis.t.begin()));
            const std::size_t k0 = k1 == 0 ? 0 : k1 - 1;
            const double w = axis.t[k1] > axis.t[k0] ? (tr - axis.t[k0]) / (axis.t[k1] - axis.t[k0]) : 0.0;
            t.push_back(tr);
            p.push_back(a + (1.0 - w) * antennaOffset[k0] + w * antennaOffset[k1]);
        }
        if (t.size() < 2)
            return makeError(
                QStringLiteral("antenna stream '%1' has fewer than 2 fixes inside the orientation streams' "
                               "time span")
                    .arg(plan.model.position[antennaSegment]));
        StreamData d(t.size(), 7);
        d.t = t;
        const double half = 0.5 * plan.speedWindow;
        for (std::size_t r = 0, lo = 0, hi = 0; r < t.size(); ++r) {
            while (t[r] - t[lo] > half) ++lo;
            while (hi + 1 < t.size() && t[hi + 1] - t[r] <= half) ++hi;
            const std::size_t a = std::min(lo, r == 0 ? 0 : r - 1), b = std::max(hi, std::min(r + 1, t.size() - 1));
            const Vec3 v = t[b] > t[a] ? Vec3((p[b] - p[a]) / (t[b] - t[a])) : Vec3(Vec3::Constant(kNaN));
            for (int i = 0; i < 3; ++i) {
                d.at(r, i) = p[r][i];
                d.at(r, 3 + i) = v[i];
            }
            d.at(r, 6) = v.norm();
        }
        attributes.insert(QStringLiteral("antenna"), plan.model.position[antennaSegment]);
        out.push_back(
            {QStringLiteral("absolute"), outputStream(QStringLiteral("trajectory"), plan.antenna->info().frame,
                                                      columnsOf({"x", "y", "z", "vx", "vy", "vz", "speed"},
                                                                {"m", "m", "m", "m/s", "m/s", "m/s", "m/s"}),
                                                      std::move(d), attributes)});
    }
    context.report(1.0);
    return out;
}

}  // namespace athlos::body
