#include "plugins/inertial/JointAngles.h"

#include "core/math/Angles.h"
#include "core/math/EulerAngles.h"
#include "plugins/inertial/VectorMath.h"

#include <QRegularExpression>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace athlos::inertial {

using math::Quat;
using math::Vec3;

namespace {

const math::EulerSequence& zxy() {
    static const math::EulerSequence sequence = *math::EulerSequence::parse(QStringLiteral("ZXY"));
    return sequence;
}

// Sign factors taking (α, β, γ) to (flexion, abduction, internal rotation); each is ±1, so the map
// is its own inverse.
Vec3 signs(Joint joint, Side side) {
    const double flexion = (joint == Joint::Knee || joint == Joint::Trunk) ? -1.0 : 1.0;
    if (joint == Joint::Trunk) return {flexion, 1.0, 1.0};
    // Right: a positive β tilts the distal long axis to the right, i.e. its lower end medially
    // (adduction); a positive γ turns the distal anterior axis to the left, i.e. medially (internal).
    // The left side is the mirror image through the sagittal plane, which flips both.
    return side == Side::Right ? Vec3(flexion, -1.0, 1.0) : Vec3(flexion, 1.0, -1.0);
}

double clampedAcos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }

// Normalised with one division.
Quat unit(const Quat& q) { return Quat(q.coeffs() * (1.0 / q.coeffs().norm())); }

// R(q) e_y for a unit quaternion: the segment's long axis in the earth frame.
Vec3 longAxis(const Quat& q) {
    return {2.0 * (q.x() * q.y() - q.w() * q.z()), 1.0 - 2.0 * (q.x() * q.x() + q.z() * q.z()),
            2.0 * (q.y() * q.z() + q.w() * q.x())};
}

}  // namespace

QStringList jointNames() {
    return {QStringLiteral("knee"), QStringLiteral("hip"), QStringLiteral("ankle"), QStringLiteral("trunk")};
}

Expected<Joint> parseJoint(const QString& name) {
    const int i = jointNames().indexOf(name);
    if (i < 0)
        return makeError(
            QStringLiteral("joint: '%1' is not one of %2").arg(name, jointNames().join(QStringLiteral(", "))));
    return static_cast<Joint>(i);
}

QString jointName(Joint joint) { return jointNames().at(static_cast<int>(joint)); }

Expected<Side> parseSide(const QString& name) {
    if (name == QLatin1String("right")) return Side::Right;
    if (name == QLatin1String("left")) return Side::Left;
    return makeError(QStringLiteral("side: '%1' is not one of right, left").arg(name));
}

QString sideName(Side side) { return side == Side::Right ? QStringLiteral("right") : QStringLiteral("left"); }

QStringList jointSegments(Joint joint) {
    switch (joint) {
        case Joint::Knee:
            return {QStringLiteral("thigh"), QStringLiteral("shank")};
        case Joint::Hip:
            return {QStringLiteral("pelvis"), QStringLiteral("thigh")};
        case Joint::Ankle:
            return {QStringLiteral("shank"), QStringLiteral("foot")};
        case Joint::Trunk:
            return {QStringLiteral("pelvis"), QStringLiteral("thorax")};
    }
    return {};
}

AnatomicalAngles anatomicalFromCardan(const Vec3& zxy, Joint joint, Side side) {
    const Vec3 a = zxy.cwiseProduct(signs(joint, side));
    return {a[0], a[1], a[2]};
}

Vec3 cardanFromAnatomical(const AnatomicalAngles& angles, Joint joint, Side side) {
    return angles.vector().cwiseProduct(signs(joint, side));
}

Quat relativeFromAnatomical(const AnatomicalAngles& angles, Joint joint, Side side) {
    return math::quaternionFromEuler(cardanFromAnatomical(angles, joint, side), zxy());
}

double segmentInclination(const Quat& segment) { return clampedAcos((segment * Vec3::UnitY()).z()); }

double longAxisAngle(const Quat& proximalSegment, const Quat& distalSegment) {
    return clampedAcos((proximalSegment * Vec3::UnitY()).dot(distalSegment * Vec3::UnitY()));
}

JointAngles::Sample JointAngles::update(const Quat& proximalSensor, const Quat& distalSensor) const {
    return sample(proximalSensor, distalSensor, math::headingRotation(params_.headingOffset));
}

// One sample with the heading rotation given; each segment's long axis (its rotation matrix's second
// column) is shared by the three 2D angles. updateBatch computes the same in blocks.
JointAngles::Sample JointAngles::sample(const Quat& proximalSensor, const Quat& distalSensor,
                                        const Quat& heading) const {
    const Quat proximal = unit(proximalSensor * params_.proximalMount);
    const Quat distal = unit(heading * distalSensor * params_.distalMount);
    Sample s;
    s.relative = unit(proximal.conjugate() * distal);
    if (s.relative.w() < 0.0) s.relative.coeffs() = -s.relative.coeffs();  // canonical: w ≥ 0
    s.cardan = math::eulerFromQuaternion(s.relative, zxy());
    s.angles = anatomicalFromCardan(s.cardan, params_.joint, params_.side);
    const Vec3 yp = longAxis(proximal), yd = longAxis(distal);
    s.longAxisAngle = clampedAcos(yp.dot(yd));
    s.proximalInclination = clampedAcos(yp.z());
    s.distalInclination = clampedAcos(yd.z());
    return s;
}

void JointAngles::updateBatch(std::span<const Quat> proximalSensor, std::span<const Quat> distalSensor,
                              std::span<double> rows) const {
    const std::size_t n = std::min(proximalSensor.size(), distalSensor.size());
    assert(rows.size() >= n * kColumns);
    const Quat heading = math::headingRotation(params_.headingOffset);
    const Vec3 sign = signs(params_.joint, params_.side);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // As sample(), in blocks: first every sample's arguments of its three atan2 (the Cardan angles,
    // core/math/EulerAngles.h) and three acos (long axes), then those 6 × block calls vectorised
    // (VectorMath.h: they are most of the time), then the rows.
    constexpr std::size_t kBlock = 256;
    std::array<std::array<double, kBlock>, 3> atanY, atanX, cosine;
    std::array<unsigned char, kBlock> gap;
    for (std::size_t start = 0; start < n; start += kBlock) {
        const std::size_t m = std::min(kBlock, n - start);
        for (std::size_t i = 0; i < m; ++i) {
            const Quat& ps = proximalSensor[start + i];
            const Quat& ds = distalSensor[start + i];
            gap[i] = !ps.coeffs().allFinite() || !ds.coeffs().allFinite();
            if (gap[i]) {  // a gap in either input (e.g. outside the other stream's span) is a gap in the angles
                for (int c = 0; c < 3; ++c) atanY[c][i] = atanX[c][i] = cosine[c][i] = 0.0;
                continue;
            }
            const Quat proximal = unit(ps * params_.proximalMount);
            const Quat distal = unit(heading * ds * params_.distalMount);
            Quat relative = proximal.conjugate() * distal;
            if (relative.w() < 0.0) relative.coeffs() = -relative.coeffs();                  // canonical: w ≥ 0
            const math::EulerAtan2Arguments a = math::eulerAtan2Arguments(relative, zxy());  // normalises
            const Vec3 yp = longAxis(proximal), yd = longAxis(distal);
            for (int c = 0; c < 3; ++c) {
                atanY[c][i] = a.y[c];
                atanX[c][i] = a.x[c];
            }
            cosine[0][i] = yp.dot(yd);
            cosine[1][i] = yp.z();
            cosine[2][i] = yd.z();
        }
        for (int c = 0; c < 3; ++c) {
            atan2Batch(std::span(atanY[c]).first(m), std::span(atanX[c]).first(m), atanY[c]);
            acosBatch(std::span(cosine[c]).first(m), cosine[c]);
        }
        for (std::size_t i = 0; i < m; ++i) {
            double* row = rows.data() + (start + i) * kColumns;
            if (gap[i]) {
                std::fill(row, row + kColumns, nan);
                continue;
            }
            const Vec3 cardan = math::eulerFromAtan2({atanY[0][i], atanY[1][i], atanY[2][i]}, zxy());
            for (int c = 0; c < 3; ++c) {
                row[c] = cardan[c] * sign[c];
                row[3 + c] = cosine[c][i];
            }
        }
    }
}

std::vector<double> JointAngles::updateBatch(std::span<const Quat> proximalSensor,
                                             std::span<const Quat> distalSensor) const {
    std::vector<double> rows(std::min(proximalSensor.size(), distalSensor.size()) * kColumns);
    updateBatch(proximalSensor, distalSensor, rows);
    return rows;
}

double JointAngles::estimateHeadingOffset(std::span<const Quat> proximalSensor, std::span<const Quat> distalSensor,
                                          const Quat& proximalMount, const Quat& distalMount) {
    double sumSin = 0.0, sumCos = 0.0;
    const std::size_t n = std::min(proximalSensor.size(), distalSensor.size());
    for (std::size_t k = 0; k < n; ++k) {
        if (!proximalSensor[k].coeffs().allFinite() || !distalSensor[k].coeffs().allFinite()) continue;
        const Vec3 ap = (proximalSensor[k] * proximalMount) * Vec3::UnitX();
        const Vec3 ad = (distalSensor[k] * distalMount) * Vec3::UnitX();
        // A nearly vertical anterior axis has no meaningful heading (weight by horizontal length).
        const double wp = ap.head<2>().norm(), wd = ad.head<2>().norm();
        if (wp < 0.2 || wd < 0.2) continue;
        const double delta = math::wrapAngle(std::atan2(ap.y(), ap.x()) - std::atan2(ad.y(), ad.x()));
        sumSin += wp * wd * std::sin(delta);
        sumCos += wp * wd * std::cos(delta);
    }
    return (sumSin == 0.0 && sumCos == 0.0) ? 0.0 : std::atan2(sumSin, sumCos);
}

std::vector<Quat> slerpAt(std::span<const double> sourceTime, std::span<const Quat> source, std::span<const double> t) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Quat> out(t.size(), Quat(nan, nan, nan, nan));
    for (std::size_t k = 0; k < t.size(); ++k) {
        const auto it = std::lower_bound(sourceTime.begin(), sourceTime.end(), t[k]);
        if (it == sourceTime.end()) continue;
        const auto j = static_cast<std::size_t>(it - sourceTime.begin());
        if (*it == t[k]) {
            out[k] = source[j];
        } else if (j > 0) {
            const Quat& a = source[j - 1];
            const Quat& b = source[j];
            if (!a.coeffs().allFinite() || !b.coeffs().allFinite()) continue;
            const double f = (t[k] - sourceTime[j - 1]) / (sourceTime[j] - sourceTime[j - 1]);
            out[k] = math::slerp(a.normalized(), b.normalized(), f);
        }
    }
    return out;
}

Expected<Quat> parseQuaternion(const QString& text, const QString& parameter) {
    static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
    const QStringList parts = text.trimmed().split(separators, Qt::SkipEmptyParts);
    if (parts.size() != 4)
        return makeError(QStringLiteral("%1: '%2' is not a quaternion; give four numbers w,x,y,z (scalar first)")
                             .arg(parameter, text));
    Eigen::Vector4d v;
    for (int i = 0; i < 4; ++i) {
        bool ok = false;
        v[i] = parts[i].toDouble(&ok);
        if (!ok || !std::isfinite(v[i]))
            return makeError(
                QStringLiteral("%1: component %2 '%3' is not a number").arg(parameter).arg(i + 1).arg(parts[i]));
    }
    if (v.norm() < 1e-9)
        return makeError(QStringLiteral("%1: the quaternion '%2' has zero length").arg(parameter, text));
    return math::quatFromWxyz(v.normalized());
}

QString formatQuaternion(const Quat& q) {
    const Quat c = math::canonical(q.normalized());
    return QStringLiteral("%1,%2,%3,%4")
        .arg(c.w(), 0, 'g', 12)
        .arg(c.x(), 0, 'g', 12)
        .arg(c.y(), 0, 'g', 12)
        .arg(c.z(), 0, 'g', 12);
}

}  // namespace athlos::inertial
