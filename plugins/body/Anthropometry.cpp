#include "plugins/body/Anthropometry.h"

namespace athlos::body {

namespace {

constexpr std::array<const char*, kSegments> kSegmentNames{
    "pelvis",      "thorax",         "head",         "right-upper-arm", "right-forearm",
    "right-hand",  "left-upper-arm", "left-forearm", "left-hand",       "right-thigh",
    "right-shank", "right-foot",     "left-thigh",   "left-shank",      "left-foot"};
constexpr std::array<const char*, kJoints> kJointNames{"lumbar",      "cervical",    "head-vertex",   "right-shoulder",
                                                       "right-elbow", "right-wrist", "left-shoulder", "left-elbow",
                                                       "left-wrist",  "right-hip",   "right-knee",    "right-ankle",
                                                       "left-hip",    "left-knee",   "left-ankle"};

// One row of a table: length (mm at the reference stature), mass (% of body mass), CoM (% of the length).
struct Row {
    double length, mass, x, y, z;
};
// Segment types shared by both sides.
enum Type { Head, Torso, UpperArm, Forearm, Hand, Pelvis, Thigh, Shank, Foot, kTypes };

// Dumas, Chèze & Verriest 2007, Table 2 (male | female): length (mm), mass (%), CoM (x, y, z) in % of the
// length in the ISB segment frame with its origin at the proximal joint centre (head & neck and torso:
// the cervical joint centre; pelvis: the lumbar joint centre).
// [NOTE] the female head & neck x, z were not available to us and are set to 0 (y = 55.9 %).
constexpr std::array<Row, kTypes> kDumasMale{{{278, 6.7, 2.0, 53.4, 0.1},
                                              {477, 33.3, -3.6, -42.0, -0.2},
                                              {271, 2.4, 1.7, -45.2, -2.6},
                                              {283, 1.7, 1.0, -41.7, 1.4},
                                              {80, 0.6, 3.5, -35.7, 3.2},
                                              {94, 14.2, 2.8, -28.0, -0.6},
                                              {432, 12.3, -4.1, -42.9, 3.3},
                                              {433, 4.8, -4.8, -41.0, 0.7},
                                              {183, 1.2, 38.2, -15.1, 2.6}}};
constexpr std::array<Row, kTypes> kDumasFemale{{{244, 6.7, 0.0, 55.9, 0.0},
                                                {429, 30.4, -1.6, -43.6, -0.6},
                                                {243, 2.2, -7.3, -45.4, -2.8},
                                                {247, 1.3, 2.1, -41.1, 1.9},
                                                {71, 0.5, 3.3, -32.7, 2.1},
                                                {107, 14.6, -0.9, -23.2, 0.2},
                                                {379, 14.6, -7.7, -37.7, 0.8},
                                                {388, 4.5, -4.9, -40.4, 3.1},
                                                {165, 1.0, 27.0, -21.8, 3.9}}};
// Mean statures of the samples behind Table 2 (McConville et al. 1980 men, Young et al. 1983 women), used to
// scale the lengths to the athlete. [NOTE] taken as 1.77 m / 1.61 m; check against the paper's Table 1.
constexpr double kDumasStatureMale = 1.77, kDumasStatureFemale = 1.61;

// de Leva 1996, Table 4 (male | female): length (mm, reference statures 1741 / 1735 mm), mass (%), CoM in %
// of the length from the first end point (longitudinal only). Head: VERT–CERV (lower half of the table);
// upper (SUPR–XYPH), middle (XYPH–OMPH) and lower (OMPH–MIDH) trunk; upper arm SJC–EJC; forearm EJC–WJC;
// hand WJC–MET3; thigh HJC–KJC; shank KJC–LMAL; foot HEEL–TTIP.
struct DeLevaRow {
    double length, mass, com;
};
enum DeLevaType {
    DHead,
    DUpperTrunk,
    DMiddleTrunk,
    DLowerTrunk,
    DUpperArm,
    DForearm,
    DHand,
    DThigh,
    DShank,
    DFoot,
    kD
};
constexpr std::array<DeLevaRow, kD> kDeLevaMale{{{242.9, 6.94, 50.02},
                                                 {170.7, 15.96, 29.99},
                                                 {215.5, 16.33, 45.02},
                                                 {145.7, 11.17, 61.15},
                                                 {281.7, 2.71, 57.72},
                                                 {268.9, 1.62, 45.74},
                                                 {86.2, 0.61, 79.00},
                                                 {422.2, 14.16, 40.95},
                                                 {434.0, 4.33, 44.59},
                                                 {258.1, 1.37, 44.15}}};
constexpr std::array<DeLevaRow, kD> kDeLevaFemale{{{243.7, 6.68, 48.41},
                                                   {142.5, 15.45, 20.77},
                                                   {205.3, 14.65, 45.12},
                                                   {181.5, 12.47, 49.20},
                                                   {275.1, 2.55, 57.54},
                                                   {264.3, 1.38, 45.59},
                                                   {78.0, 0.56, 74.74},
                                                   {368.5, 14.78, 36.12},
                                                   {432.3, 4.81, 44.16},
                                                   {228.3, 1.29, 40.14}}};
constexpr double kDeLevaStatureMale = 1.741, kDeLevaStatureFemale = 1.735;
// de Leva's foot runs heel → toe tip; the ankle (lateral malleolus) is taken 20 % of the foot length in
// front of the heel (an assumption: the table gives no ankle position) and the CoM at ankle height.
constexpr double kDeLevaHeelBehindAnkle = 0.20;

Type typeOf(Segment s) {
    switch (s) {
        case Segment::Pelvis:
            return Pelvis;
        case Segment::Thorax:
            return Torso;
        case Segment::Head:
            return Head;
        case Segment::RightUpperArm:
        case Segment::LeftUpperArm:
            return UpperArm;
        case Segment::RightForearm:
        case Segment::LeftForearm:
            return Forearm;
        case Segment::RightHand:
        case Segment::LeftHand:
            return Hand;
        case Segment::RightThigh:
        case Segment::LeftThigh:
            return Thigh;
        case Segment::RightShank:
        case Segment::LeftShank:
            return Shank;
        default:
            return Foot;
    }
}

}  // namespace

QString segmentName(Segment s) { return QLatin1String(kSegmentNames[static_cast<int>(s)]); }
QString jointName(Joint j) { return QLatin1String(kJointNames[static_cast<int>(j)]); }

QStringList segmentNames() {
    QStringList names;
    for (const char* n : kSegmentNames) names << QLatin1String(n);
    return names;
}

Expected<Segment> parseSegment(const QString& name) {
    for (int s = 0; s < kSegments; ++s)
        if (name == QLatin1String(kSegmentNames[s])) return static_cast<Segment>(s);
    return makeError(
        QStringLiteral("unknown segment '%1' (one of %2)").arg(name, segmentNames().join(QStringLiteral(", "))));
}

bool isLeft(Segment s) {
    const int i = static_cast<int>(s);
    return (i >= 6 && i <= 8) || i >= 12;
}

Joint proximalJoint(Segment s) {
    switch (s) {
        case Segment::Pelvis:
        case Segment::Thorax:
            return Joint::Lumbar;
        case Segment::Head:
            return Joint::Cervical;
        case Segment::RightUpperArm:
            return Joint::RightShoulder;
        case Segment::RightForearm:
            return Joint::RightElbow;
        case Segment::RightHand:
            return Joint::RightWrist;
        case Segment::LeftUpperArm:
            return Joint::LeftShoulder;
        case Segment::LeftForearm:
            return Joint::LeftElbow;
        case Segment::LeftHand:
            return Joint::LeftWrist;
        case Segment::RightThigh:
            return Joint::RightHip;
        case Segment::RightShank:
            return Joint::RightKnee;
        case Segment::RightFoot:
            return Joint::RightAnkle;
        case Segment::LeftThigh:
            return Joint::LeftHip;
        case Segment::LeftShank:
            return Joint::LeftKnee;
        case Segment::LeftFoot:
            return Joint::LeftAnkle;
    }
    return Joint::Lumbar;
}

int distalJoint(Segment s) {
    switch (s) {
        case Segment::Thorax:
            return static_cast<int>(Joint::Cervical);
        case Segment::Head:
            return static_cast<int>(Joint::HeadVertex);
        case Segment::RightUpperArm:
            return static_cast<int>(Joint::RightElbow);
        case Segment::RightForearm:
            return static_cast<int>(Joint::RightWrist);
        case Segment::LeftUpperArm:
            return static_cast<int>(Joint::LeftElbow);
        case Segment::LeftForearm:
            return static_cast<int>(Joint::LeftWrist);
        case Segment::RightThigh:
            return static_cast<int>(Joint::RightKnee);
        case Segment::RightShank:
            return static_cast<int>(Joint::RightAnkle);
        case Segment::LeftThigh:
            return static_cast<int>(Joint::LeftKnee);
        case Segment::LeftShank:
            return static_cast<int>(Joint::LeftAnkle);
        default:
            return -1;  // pelvis (two hips: Anthropometry::rightHip), hands, feet
    }
}

Segment parentSegment(Segment s) {
    switch (s) {
        case Segment::Pelvis:
        case Segment::Thorax:
        case Segment::RightThigh:
        case Segment::LeftThigh:
            return Segment::Pelvis;
        case Segment::Head:
        case Segment::RightUpperArm:
        case Segment::LeftUpperArm:
            return Segment::Thorax;
        default:
            return static_cast<Segment>(static_cast<int>(s) - 1);
    }
}

Expected<BspTable> parseTable(const QString& name) {
    if (name == QLatin1String("dumas-2007")) return BspTable::Dumas2007;
    if (name == QLatin1String("de-leva-1996")) return BspTable::DeLeva1996;
    return makeError(QStringLiteral("table: '%1' is not one of dumas-2007, de-leva-1996").arg(name));
}

Expected<Sex> parseSex(const QString& name) {
    if (name == QLatin1String("male")) return Sex::Male;
    if (name == QLatin1String("female")) return Sex::Female;
    return makeError(QStringLiteral("sex: '%1' is not one of male, female").arg(name));
}

QString tableName(BspTable t) {
    return t == BspTable::Dumas2007 ? QStringLiteral("dumas-2007") : QStringLiteral("de-leva-1996");
}
QString sexName(Sex s) { return s == Sex::Male ? QStringLiteral("male") : QStringLiteral("female"); }

Expected<Anthropometry> anthropometry(BspTable table, Sex sex, double height, const BodyProportions& proportions) {
    if (!(height >= 0.5 && height <= 2.5))
        return makeError(QStringLiteral("height: %1 m is outside 0.5–2.5 m").arg(height));
    Anthropometry a;
    a.table = table;
    a.sex = sex;
    a.height = height;
    const bool male = sex == Sex::Male;
    const double hip = 0.5 * proportions.hipWidth * height;
    a.rightShoulder = Vec3(0.0, -proportions.shoulderDrop * height, 0.5 * proportions.shoulderWidth * height);
    double total = 0.0;
    if (table == BspTable::Dumas2007) {
        const std::array<Row, kTypes>& rows = male ? kDumasMale : kDumasFemale;
        const double scale = height / (male ? kDumasStatureMale : kDumasStatureFemale) / 1000.0;  // mm → m
        for (int s = 0; s < kSegments; ++s) {
            const Segment seg = static_cast<Segment>(s);
            const Row& r = rows[typeOf(seg)];
            const double l = r.length * scale, mirror = isLeft(seg) ? -1.0 : 1.0;
            SegmentParameters& p = a.segments[s];
            p.massFraction = r.mass;
            p.com = Vec3(r.x, r.y, mirror * r.z) * (l / 100.0);
            p.distal = Vec3(0.0, -l, 0.0);
            switch (typeOf(seg)) {
                case Head:
                    p.distal = Vec3(0.0, l, 0.0);  // cervical joint → head vertex
                    break;
                case Torso:
                    // Table 2 places the torso's origin at the cervical joint; our chain starts at the lumbar
                    // joint centre, l below it along Y.
                    p.distal = Vec3(0.0, l, 0.0);
                    p.com += p.distal;
                    break;
                case Pelvis:
                    a.rightHip = Vec3(0.0, -l, hip);  // length: lumbar joint → hip joints in the sagittal plane
                    p.distal = Vec3::Zero();
                    break;
                case Foot:
                    p.distal = Vec3(l, 0.0, 0.0);  // ankle → toe (metatarsal heads), forward
                    break;
                default:
                    break;
            }
            total += r.mass;
        }
    } else {
        const std::array<DeLevaRow, kD>& rows = male ? kDeLevaMale : kDeLevaFemale;
        const double scale = height / (male ? kDeLevaStatureMale : kDeLevaStatureFemale) / 1000.0;
        const auto set = [&](Segment s, double mass, Vec3 distal, Vec3 com) {
            SegmentParameters& p = a.segments[static_cast<int>(s)];
            p.massFraction = mass;
            p.distal = distal;
            p.com = com;
            total += mass;
        };
        const auto limb = [&](Segment s, DeLevaType t) {
            const double l = rows[t].length * scale;
            set(s, rows[t].mass, Vec3(0.0, -l, 0.0), Vec3(0.0, -rows[t].com / 100.0 * l, 0.0));
        };
        // Head: VERT → CERV, CoM measured from the vertex; our head starts at the cervical joint.
        const double lh = rows[DHead].length * scale;
        set(Segment::Head, rows[DHead].mass, Vec3(0.0, lh, 0.0), Vec3(0.0, (1.0 - rows[DHead].com / 100.0) * lh, 0.0));
        // Thorax = upper + middle trunk (SUPR → OMPH), its CoM the mass-weighted mean of the two; the lumbar
        // joint is taken at OMPH.
        const DeLevaRow& u = rows[DUpperTrunk];
        const DeLevaRow& m = rows[DMiddleTrunk];
        const double lu = u.length * scale, lm = m.length * scale, lt = lu + lm;
        const double fromTop = (u.mass * u.com / 100.0 * lu + m.mass * (lu + m.com / 100.0 * lm)) / (u.mass + m.mass);
        set(Segment::Thorax, u.mass + m.mass, Vec3(0.0, lt, 0.0), Vec3(0.0, lt - fromTop, 0.0));
        // Pelvis = lower trunk (OMPH → MIDH): CoM measured from OMPH, i.e. (1 − f) l above the mid-hip point.
        const DeLevaRow& lo = rows[DLowerTrunk];
        const double ll = lo.length * scale;
        set(Segment::Pelvis, lo.mass, Vec3::Zero(), Vec3(0.0, (1.0 - lo.com / 100.0) * ll, 0.0));
        a.segments[static_cast<int>(Segment::Pelvis)].comFromMidHip = true;
        a.rightHip = Vec3(0.0, -ll, hip);
        for (int side = 0; side < 2; ++side) {
            const int o = side == 0 ? 0 : 3;
            limb(static_cast<Segment>(3 + o), DUpperArm);
            limb(static_cast<Segment>(4 + o), DForearm);
            limb(static_cast<Segment>(5 + o), DHand);
            const int q = side == 0 ? 0 : 3;
            limb(static_cast<Segment>(9 + q), DThigh);
            limb(static_cast<Segment>(10 + q), DShank);
            const double lf = rows[DFoot].length * scale;
            set(static_cast<Segment>(11 + q), rows[DFoot].mass, Vec3(lf * (1.0 - kDeLevaHeelBehindAnkle), 0.0, 0.0),
                Vec3((rows[DFoot].com / 100.0 - kDeLevaHeelBehindAnkle) * lf, 0.0, 0.0));
        }
    }
    for (SegmentParameters& p : a.segments) p.massFraction /= total;
    return a;
}

}  // namespace athlos::body
