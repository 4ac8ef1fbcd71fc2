#pragma once
// Anthropometric tables for a whole-body model (issue #18 item 1, Fasel 2017 ch. 7, spec §6): segment mass
// fractions, lengths and centre-of-mass positions of
//   - Dumas, Chèze & Verriest 2007, "Adjustments to McConville et al. and Young et al. body segment inertial
//     parameters", J Biomech 40:543–553, Table 2 (lengths in mm of the reference samples, masses in % of
//     the body mass, CoM position in % of the segment length in the ISB segment frame: X anterior,
//     Y superior, Z right, origin at the proximal joint centre);
//   - de Leva 1996, "Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters", J Biomech
//     29:1223–1230, Table 4 (lengths in mm for the reference statures 1.741 m male / 1.735 m female,
//     masses in %, CoM in % of the length from the "origin" end point, on the line between the end points).
// Lengths are scaled by height / reference stature; masses by the body mass (renormalised to 100 % of the
// listed segments).
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <array>

namespace athlos::body {

using math::Quat;
using math::Vec3;

// The segments of the whole-body model. Arms, hands and the head carry no sensor in the thesis' lower-body
// set-up; they ride on the thorax (AthleteModel.h).
enum class Segment {
    Pelvis = 0,
    Thorax,
    Head,
    RightUpperArm,
    RightForearm,
    RightHand,
    LeftUpperArm,
    LeftForearm,
    LeftHand,
    RightThigh,
    RightShank,
    RightFoot,
    LeftThigh,
    LeftShank,
    LeftFoot
};
inline constexpr int kSegments = 15;

// Joint centres (and the head vertex) of the chain; the lumbar joint centre is the origin of the
// relative positions (Fasel 2017 ch. 7 expresses the CoM with respect to the lumbar joint centre).
enum class Joint {
    Lumbar = 0,
    Cervical,
    HeadVertex,
    RightShoulder,
    RightElbow,
    RightWrist,
    LeftShoulder,
    LeftElbow,
    LeftWrist,
    RightHip,
    RightKnee,
    RightAnkle,
    LeftHip,
    LeftKnee,
    LeftAnkle
};
inline constexpr int kJoints = 15;

QString segmentName(Segment s);  // "pelvis", "thorax", "head", "right-upper-arm", …, "left-foot"
QString jointName(Joint j);      // "lumbar", "cervical", "head-vertex", "right-shoulder", …
Expected<Segment> parseSegment(const QString& name);
QStringList segmentNames();
// The segment's proximal joint (its origin) and, for the chain, its distal joint (the joint of its first
// child; the head's is the vertex, the hands' and feet's none: Joint(-1)).
Joint proximalJoint(Segment s);
int distalJoint(Segment s);
Segment parentSegment(Segment s);  // the pelvis is its own parent
bool isLeft(Segment s);

enum class BspTable { Dumas2007, DeLeva1996 };
enum class Sex { Male, Female };
Expected<BspTable> parseTable(const QString& name);  // "dumas-2007", "de-leva-1996"
Expected<Sex> parseSex(const QString& name);         // "male", "female"
QString tableName(BspTable t);
QString sexName(Sex s);

// One segment at the athlete's size, in its ISB segment frame (X anterior, Y superior, Z right; left
// segments mirrored in Z), origin at the proximal joint centre.
struct SegmentParameters {
    double massFraction = 0;     // of the body mass (renormalised so the 15 segments sum to 1)
    Vec3 distal = Vec3::Zero();  // proximal → distal joint (m), upright neutral posture
    Vec3 com = Vec3::Zero();     // proximal joint → segment CoM (m)
    bool comFromMidHip = false;  // pelvis of de Leva: the CoM is measured from the mid-hip point
};

// Geometry that neither table gives (each an assumption, see Anthropometry.cpp).
struct BodyProportions {
    double hipWidth = 0.10;       // hip-joint-centre separation / height
    double shoulderWidth = 0.20;  // shoulder-joint-centre separation / height
    double shoulderDrop = 0.025;  // shoulder joint centres below the cervical joint centre / height
};

struct Anthropometry {
    BspTable table = BspTable::Dumas2007;
    Sex sex = Sex::Male;
    double height = 1.75;  // m
    std::array<SegmentParameters, kSegments> segments{};
    // Pelvis: lumbar joint → right hip joint centre (m, pelvis frame); the left one is mirrored.
    Vec3 rightHip = Vec3::Zero();
    // Thorax: lumbar → cervical (m, thorax frame) is segments[Thorax].distal; cervical → right shoulder:
    Vec3 rightShoulder = Vec3::Zero();
    const SegmentParameters& operator[](Segment s) const { return segments[static_cast<int>(s)]; }
};

// The table scaled to `height` (m); errors name the parameter when the height is out of 0.5–2.5 m.
Expected<Anthropometry> anthropometry(BspTable table, Sex sex, double height, const BodyProportions& proportions = {});

}  // namespace athlos::body
