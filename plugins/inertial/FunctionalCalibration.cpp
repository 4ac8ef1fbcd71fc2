#include "plugins/inertial/FunctionalCalibration.h"

#include "core/math/Angles.h"
#include "core/math/PrincipalAxis.h"
#include "plugins/inertial/SegmentCalibration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace athlos::inertial {

using math::Vec3;

namespace {

constexpr std::array<const char*, kCalibrationMovements> kMovementNames{
    "upright", "squats", "trunk-rotations", "right-abduction", "left-abduction", "arm-swings"};

// Trunk: sternum and upper back (both on the thorax, Fasel §6.2.3 calibrates them alike).
enum class Role { Pelvis, Trunk, Thigh, Shank, Foot, Head, UpperArm, Forearm };
struct RoleInfo {
    Role role = Role::Pelvis;
    int side = 0;  // +1 right, −1 left, 0 midline
};

Expected<RoleInfo> roleOf(const QString& name) {
    if (name == QLatin1String("sacrum") || name == QLatin1String("pelvis") || name == QLatin1String("lower-back"))
        return RoleInfo{Role::Pelvis, 0};
    if (name == QLatin1String("sternum") || name == QLatin1String("trunk") || name == QLatin1String("thorax") ||
        name == QLatin1String("upper-back"))
        return RoleInfo{Role::Trunk, 0};
    if (name == QLatin1String("head")) return RoleInfo{Role::Head, 0};
    for (int s : {1, -1}) {
        const QString prefix = s > 0 ? QStringLiteral("right-") : QStringLiteral("left-");
        if (name == prefix + QLatin1String("thigh")) return RoleInfo{Role::Thigh, s};
        if (name == prefix + QLatin1String("shank")) return RoleInfo{Role::Shank, s};
        if (name == prefix + QLatin1String("foot")) return RoleInfo{Role::Foot, s};
        if (name == prefix + QLatin1String("upper-arm")) return RoleInfo{Role::UpperArm, s};
        if (name == prefix + QLatin1String("forearm")) return RoleInfo{Role::Forearm, s};
    }
    return makeError(QStringLiteral("segment '%1' is not part of the protocol; use sacrum (pelvis, lower-back), "
                                    "sternum (trunk, thorax), upper-back, head, right-/left-thigh, right-/left-shank, "
                                    "right-/left-foot, right-/left-upper-arm or right-/left-forearm")
                         .arg(name));
}

CalibrationMovement abductionOf(int side) {
    return side > 0 ? CalibrationMovement::RightAbduction : CalibrationMovement::LeftAbduction;
}

// Samples of one segment in [begin, end).
struct Range {
    std::size_t begin = 0, end = 0;
    std::size_t size() const { return end > begin ? end - begin : 0; }
};
Range rangeOf(const std::vector<double>& t, double begin, double end) {
    const auto b = std::lower_bound(t.begin(), t.end(), begin), e = std::lower_bound(t.begin(), t.end(), end);
    return {std::size_t(b - t.begin()), std::size_t(e - t.begin())};
}

// Principal axis of the second moment of the rates (PCA about the origin, SegmentCalibration.cpp)
// and the share of the energy on it; the RMS rate.
struct AxisStats {
    Vec3 axis = Vec3::UnitZ();
    double share = 0.0, rms = 0.0;
};
AxisStats axisStats(const std::vector<Vec3>& gyr, Range r, const Vec3& bias) {
    AxisStats s;
    if (r.size() == 0) return s;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (std::size_t k = r.begin; k < r.end; ++k) {
        const Vec3 w = gyr[k] - bias;
        moment += w * w.transpose();
    }
    const math::PrincipalAxis p = math::principalAxisOfMoment(moment);
    s.axis = p.axis;
    s.share = p.share;
    s.rms = std::sqrt(std::max(0.0, moment.trace()) / double(r.size()));
    return s;
}

// A segment with its role, sampling interval, gyroscope bias, upright direction and smoothed rate.
struct Prepared {
    const FunctionalCalibration::Segment* segment = nullptr;
    RoleInfo role;
    double dt = 0.0;
    Vec3 bias = Vec3::Zero(), up = Vec3::UnitY();
    std::vector<double> rate;  // moving average of |ω| over Params::smoothing
    Range rows(double begin, double end) const { return rangeOf(segment->t, begin, end); }
    double rateAt(double t) const {
        const auto& ts = segment->t;
        const auto k = std::size_t(std::lower_bound(ts.begin(), ts.end(), t) - ts.begin());
        return rate[std::min(k, rate.size() - 1)];
    }
};

// θ(t) = ∫ (ω − b)·a dt over the rows, linearly detrended so that it ends where it starts (the
// segment is back at rest; what remains is bias and drift).
std::vector<double> angleCurve(const Prepared& p, Range r, const Vec3& axis) {
    std::vector<double> theta(r.size() + 1, 0.0);
    for (std::size_t k = 0; k < r.size(); ++k)
        theta[k + 1] = theta[k] + (p.segment->gyr[r.begin + k] - p.bias).dot(axis) * p.dt;
    const double slope = theta.back() / double(std::max<std::size_t>(1, r.size()));
    for (std::size_t k = 0; k < theta.size(); ++k) theta[k] -= slope * double(k);
    return theta;
}

// Repetitions of a block: excursions of θ beyond half the largest (in the sign of the first), split
// at the least-moving instant between consecutive excursions.
std::vector<TimeInterval> repetitions(const Prepared& p, double begin, double end, const Vec3& axis) {
    const Range r = p.rows(begin, end);
    std::vector<TimeInterval> reps;
    if (r.size() < 3) return reps;
    const std::vector<double> theta = angleCurve(p, r, axis);
    double peak = 0.0;
    for (double v : theta) peak = std::max(peak, std::abs(v));
    if (!(peak > 0.0)) return reps;
    double sign = 1.0;
    for (double v : theta)
        if (std::abs(v) > 0.5 * peak) {
            sign = v > 0.0 ? 1.0 : -1.0;
            break;
        }
    double top = 0.0;
    for (double v : theta) top = std::max(top, sign * v);
    std::vector<std::pair<std::size_t, std::size_t>> cores;  // [first, last] indices above half
    for (std::size_t k = 0; k < theta.size(); ++k) {
        if (sign * theta[k] <= 0.5 * top) continue;
        if (!cores.empty() && cores.back().second + 1 == k)
            cores.back().second = k;
        else
            cores.push_back({k, k});
    }
    const auto timeOf = [&](std::size_t k) { return p.segment->t[std::min(r.begin + k, r.end - 1)]; };
    double start = begin;
    for (std::size_t c = 0; c + 1 < cores.size(); ++c) {
        std::size_t best = cores[c].second;
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t k = cores[c].second; k <= cores[c + 1].first; ++k) {
            const double rate = p.rate[std::min(r.begin + k, r.end - 1)];
            if (rate < least) least = rate, best = k;
        }
        reps.push_back({start, timeOf(best)});
        start = timeOf(best);
    }
    if (!cores.empty()) reps.push_back({start, end});
    return reps;
}

double angleBetweenLines(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0));
}

// Kadaba et al. (1989) coefficient of multiple correlation of G curves of T points (header).
double multipleCorrelation(const std::vector<std::vector<double>>& curves) {
    const std::size_t g = curves.size();
    if (g < 2) return 0.0;
    const std::size_t t = curves.front().size();
    double grand = 0.0;
    for (const auto& c : curves)
        for (double v : c) grand += v;
    grand /= double(g * t);
    double within = 0.0, total = 0.0;
    for (std::size_t i = 0; i < t; ++i) {
        double mean = 0.0;
        for (const auto& c : curves) mean += c[i];
        mean /= double(g);
        for (const auto& c : curves) {
            within += (c[i] - mean) * (c[i] - mean);
            total += (c[i] - grand) * (c[i] - grand);
        }
    }
    if (!(total > 0.0)) return 0.0;
    const double ratio = (within / double(t * (g - 1))) / (total / double(g * t - 1));
    return ratio < 1.0 ? std::sqrt(1.0 - ratio) : 0.0;
}

// θ over one repetition, resampled to 101 points of normalised time.
std::vector<double> normalisedCurve(const Prepared& p, const TimeInterval& rep, const Vec3& axis) {
    const Range r = p.rows(rep.begin, rep.end);
    const std::vector<double> theta = angleCurve(p, r, axis);
    std::vector<double> out(101, 0.0);
    const double last = double(theta.size() - 1);
    for (int i = 0; i <= 100; ++i) {
        const double x = last * i / 100.0;
        const auto k = std::min(std::size_t(x), theta.size() - 1);
        const double f = x - double(k);
        out[std::size_t(i)] = k + 1 < theta.size() ? theta[k] * (1.0 - f) + theta[k + 1] * f : theta[k];
    }
    return out;
}

const FunctionalCalibration::Movement* findMovement(const std::vector<FunctionalCalibration::Movement>& movements,
                                                    CalibrationMovement m) {
    for (const auto& x : movements)
        if (x.movement == m) return &x;
    return nullptr;
}

QString foundList(const std::vector<FunctionalCalibration::Movement>& movements) {
    QStringList names;
    for (const auto& m : movements) names << calibrationMovementName(m.movement);
    return names.isEmpty() ? QStringLiteral("nothing") : names.join(QStringLiteral(", "));
}

// The segment whose rotation defines a movement's repetitions.
const Prepared* driverOf(const std::vector<Prepared>& all, CalibrationMovement m) {
    const auto find = [&](Role role, int side) -> const Prepared* {
        for (const Prepared& p : all)
            if (p.role.role == role && (side == 0 || p.role.side == side)) return &p;
        return nullptr;
    };
    switch (m) {
        case CalibrationMovement::Squats:
            if (auto* p = find(Role::Thigh, 0)) return p;
            if (auto* p = find(Role::Shank, 0)) return p;
            if (auto* p = find(Role::Pelvis, 0)) return p;
            return find(Role::Trunk, 0);
        case CalibrationMovement::TrunkRotations:
            return find(Role::Trunk, 0);
        case CalibrationMovement::RightAbduction:
        case CalibrationMovement::LeftAbduction: {
            const int side = m == CalibrationMovement::RightAbduction ? 1 : -1;
            if (auto* p = find(Role::Thigh, side)) return p;
            if (auto* p = find(Role::Shank, side)) return p;
            return find(Role::Foot, side);
        }
        case CalibrationMovement::ArmSwings:
            if (auto* p = find(Role::UpperArm, 0)) return p;
            return find(Role::Forearm, 0);
        default:
            return nullptr;
    }
}

bool isArm(Role r) { return r == Role::UpperArm || r == Role::Forearm; }

struct PreparedSet {
    std::vector<Prepared> segments;
    TimeInterval upright;
    bool uprightGiven = false;
};

}  // namespace

QString calibrationMovementName(CalibrationMovement movement) {
    return QLatin1String(kMovementNames[static_cast<int>(movement)]);
}

Expected<CalibrationMovement> parseCalibrationMovement(const QString& name) {
    for (int i = 0; i < kCalibrationMovements; ++i)
        if (name == QLatin1String(kMovementNames[i])) return static_cast<CalibrationMovement>(i);
    return makeError(QStringLiteral("'%1' is not a calibration movement (upright, squats, trunk-rotations, "
                                    "right-abduction, left-abduction, arm-swings)")
                         .arg(name));
}

namespace {

Expected<PreparedSet> prepare(const FunctionalCalibration::Params& params,
                              const std::vector<FunctionalCalibration::Segment>& segments,
                              const std::vector<FunctionalCalibration::Movement>& given) {
    if (segments.empty()) return makeError(QStringLiteral("no segment IMU was given"));
    PreparedSet set;
    for (const auto& s : segments) {
        auto role = roleOf(s.name);
        if (!role) return role.error();
        if (s.t.size() < 10 || s.acc.size() != s.t.size() || s.gyr.size() != s.t.size())
            return makeError(
                QStringLiteral("segment '%1': fewer than 10 samples or acc/gyr of another length than t").arg(s.name));
        for (const Prepared& other : set.segments)
            if (other.segment->name == s.name) return makeError(QStringLiteral("segment '%1' given twice").arg(s.name));
        Prepared p;
        p.segment = &s;
        p.role = *role;
        p.dt = (s.t.back() - s.t.front()) / double(s.t.size() - 1);
        if (!(p.dt > 0.0)) return makeError(QStringLiteral("segment '%1': time does not increase").arg(s.name));
        // Moving average of |ω| (centred, prefix sums).
        const std::size_t n = s.t.size();
        const auto half = std::size_t(std::max(1.0, 0.5 * params.smoothing / p.dt));
        std::vector<double> prefix(n + 1, 0.0);
        for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + s.gyr[k].norm();
        p.rate.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t a = k > half ? k - half : 0, b = std::min(n, k + half + 1);
            p.rate[k] = (prefix[b] - prefix[a]) / double(b - a);
        }
        set.segments.push_back(std::move(p));
    }
    // Rest on the first segment's time grid: every sensor below restRate.
    const std::vector<double>& grid = set.segments.front().segment->t;
    const auto restAt = [&](double t) {
        for (const Prepared& p : set.segments)
            if (p.rateAt(t) >= params.restRate) return false;
        return true;
    };
    if (const auto* u = findMovement(given, CalibrationMovement::Upright)) {
        set.upright = u->interval;
        set.uprightGiven = true;
    } else {
        bool found = false;
        double start = grid.front();
        bool resting = false;
        for (std::size_t k = 0; k <= grid.size() && !found; ++k) {
            const bool rest = k < grid.size() && restAt(grid[k]);
            if (rest && !resting) start = grid[k];
            if (!rest && resting && grid[k - 1] - start >= params.minUpright) {
                // Trim the smoothing's reach at both ends.
                set.upright = {start + 0.5 * params.smoothing, grid[k - 1] - 0.5 * params.smoothing};
                found = true;
            }
            resting = rest;
        }
        if (!found)
            return makeError(QStringLiteral("no upright standing found: every sensor must stay below %1 rad/s for at "
                                            "least %2 s (found no such rest)")
                                 .arg(params.restRate)
                                 .arg(params.minUpright));
    }
    for (Prepared& p : set.segments) {
        const Range r = p.rows(set.upright.begin, set.upright.end);
        if (r.size() < 2)
            return makeError(QStringLiteral("segment '%1': no samples in the upright window %2–%3 s")
                                 .arg(p.segment->name)
                                 .arg(set.upright.begin)
                                 .arg(set.upright.end));
        Vec3 acc = Vec3::Zero(), gyr = Vec3::Zero();
        for (std::size_t k = r.begin; k < r.end; ++k) acc += p.segment->acc[k], gyr += p.segment->gyr[k];
        p.up = acc.normalized();
        p.bias = gyr / double(r.size());
    }
    return set;
}

// Classifies one movement block (header).
std::optional<CalibrationMovement> classify(const FunctionalCalibration::Params& params,
                                            const std::vector<Prepared>& all, double begin, double end) {
    std::array<double, 2> leg{-1.0, -1.0};  // RMS rate of each side's leg: right, left (−1 = no sensor)
    std::array<double, 2> legAxisToUp{0.0, 0.0};
    std::array<int, 2> legRank{9, 9};
    double trunkRate = -1.0, trunkAxisToUp = 0.0, midlineRate = -1.0;  // midline: largest of pelvis, trunk, head
    // The fastest arm (upper arm, else forearm, of either side) and its axis to its own Y.
    double armRate = -1.0, armAxisToUp = 0.0;
    std::array<int, 2> armRank{9, 9};
    std::array<double, 2> armSide{-1.0, -1.0}, armSideAxis{0.0, 0.0};
    for (const Prepared& p : all) {
        const AxisStats s = axisStats(p.segment->gyr, p.rows(begin, end), p.bias);
        if (isArm(p.role.role)) {
            const auto i = std::size_t(p.role.side > 0 ? 0 : 1);
            const int rank = p.role.role == Role::UpperArm ? 0 : 1;
            if (rank < armRank[i]) {
                armRank[i] = rank;
                armSide[i] = s.rms;
                armSideAxis[i] = angleBetweenLines(s.axis, p.up);
            }
            continue;
        }
        if (p.role.role == Role::Trunk) {
            trunkRate = s.rms;
            trunkAxisToUp = angleBetweenLines(s.axis, p.up);
        }
        if (p.role.side == 0) {
            midlineRate = std::max(midlineRate, s.rms);
            continue;
        }
        const int i = p.role.side > 0 ? 0 : 1;
        const int rank = p.role.role == Role::Thigh ? 0 : p.role.role == Role::Shank ? 1 : 2;
        if (rank < legRank[std::size_t(i)]) {
            legRank[std::size_t(i)] = rank;
            leg[std::size_t(i)] = s.rms;
            legAxisToUp[std::size_t(i)] = angleBetweenLines(s.axis, p.up);
        }
    }
    const double lateral = 0.5 * std::numbers::pi - params.axialTolerance;  // axis at least this far from Y
    const bool right = leg[0] > params.moveRate, left = leg[1] > params.moveRate;
    if (right && left && legAxisToUp[0] > lateral && legAxisToUp[1] > lateral) return CalibrationMovement::Squats;
    if (right && !left && leg[1] >= 0.0 && leg[1] < params.stillRatio * leg[0] && legAxisToUp[0] > lateral)
        return CalibrationMovement::RightAbduction;
    if (left && !right && leg[0] >= 0.0 && leg[0] < params.stillRatio * leg[1] && legAxisToUp[1] > lateral)
        return CalibrationMovement::LeftAbduction;
    // One leg only instrumented: squats turn the pelvis or trunk too, an ab/adduction does not (hips
    // fixed); without a pelvis or trunk sensor the turn counts as squats.
    for (int i = 0; i < 2; ++i) {
        const bool moves = i == 0 ? right : left, otherAbsent = leg[std::size_t(1 - i)] < 0.0;
        if (!moves || !otherAbsent || !(legAxisToUp[std::size_t(i)] > lateral)) continue;
        if (midlineRate < 0.0 || midlineRate > params.moveRate) return CalibrationMovement::Squats;
        return i == 0 ? CalibrationMovement::RightAbduction : CalibrationMovement::LeftAbduction;
    }
    if (!right && !left && trunkRate > params.moveRate && trunkAxisToUp < params.axialTolerance)
        return CalibrationMovement::TrunkRotations;
    for (std::size_t i = 0; i < 2; ++i)
        if (armSide[i] > armRate) armRate = armSide[i], armAxisToUp = armSideAxis[i];
    // Arm swings: legs and midline still (a squat or a trunk rotation carries the arms along); with arm
    // sensors only nothing tells a swing from a squat (give the intervals then).
    const bool nonArm = midlineRate >= 0.0 || leg[0] >= 0.0 || leg[1] >= 0.0;
    if (nonArm && !right && !left && armRate > params.moveRate && armAxisToUp > lateral &&
        midlineRate < params.stillRatio * armRate)
        return CalibrationMovement::ArmSwings;
    return std::nullopt;
}

Expected<std::vector<FunctionalCalibration::Movement>> detectIn(
    const FunctionalCalibration::Params& params, const PreparedSet& set,
    const std::vector<FunctionalCalibration::Movement>& given) {
    using Movement = FunctionalCalibration::Movement;
    const std::vector<Prepared>& all = set.segments;
    const std::vector<double>& grid = all.front().segment->t;
    const auto restAt = [&](double t) {
        for (const Prepared& p : all)
            if (p.rateAt(t) >= params.restRate) return false;
        return true;
    };
    // Blocks: movement between rests of at least minPause (shorter rests stay inside the block).
    std::vector<TimeInterval> blocks;
    double restStart = grid.front(), moveStart = grid.front();
    bool moving = false, resting = false;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const double t = grid[k];
        const bool rest = restAt(t);
        if (rest && !resting) restStart = t;
        if (!rest && !moving) moveStart = t, moving = true;
        if (moving && rest && t - restStart >= params.minPause) {
            if (restStart - moveStart > 1.0) blocks.push_back({moveStart, restStart});
            moving = false;
        }
        resting = rest;
    }
    if (moving && (resting ? restStart : grid.back()) - moveStart > 1.0)
        blocks.push_back({moveStart, resting ? restStart : grid.back()});

    std::vector<Movement> out;
    Movement upright;
    upright.movement = CalibrationMovement::Upright;
    upright.interval = set.upright;
    upright.given = set.uprightGiven;
    out.push_back(upright);
    std::array<std::vector<TimeInterval>, kCalibrationMovements> byKind;
    for (const TimeInterval& b : blocks) {
        if (b.end <= set.upright.end && b.begin >= set.upright.begin) continue;
        if (auto kind = classify(params, all, b.begin, b.end)) byKind[std::size_t(*kind)].push_back(b);
    }
    for (int m = 1; m < kCalibrationMovements; ++m) {
        const auto kind = static_cast<CalibrationMovement>(m);
        std::vector<TimeInterval> spans = byKind[std::size_t(m)];
        bool isGiven = false;
        if (const Movement* g = findMovement(given, kind)) {
            spans = {g->interval};
            isGiven = true;
        }
        if (spans.empty()) continue;
        const Prepared* driver = driverOf(all, kind);
        if (!driver) continue;
        Movement mv;
        mv.movement = kind;
        mv.given = isGiven;
        mv.interval = {spans.front().begin, spans.back().end};
        for (const TimeInterval& s : spans) {
            const AxisStats stats = axisStats(driver->segment->gyr, driver->rows(s.begin, s.end), driver->bias);
            const auto reps = repetitions(*driver, s.begin, s.end, stats.axis);
            mv.repetitions.insert(mv.repetitions.end(), reps.begin(), reps.end());
        }
        out.push_back(std::move(mv));
    }
    std::sort(out.begin(), out.end(),
              [](const Movement& a, const Movement& b) { return a.interval.begin < b.interval.begin; });
    return out;
}

}  // namespace

Expected<std::vector<FunctionalCalibration::Movement>> FunctionalCalibration::detect(
    const std::vector<Segment>& segments, const std::vector<Movement>& given) const {
    auto set = prepare(params_, segments, given);
    if (!set) return set.error();
    return detectIn(params_, *set, given);
}

Expected<FunctionalCalibration::Result> FunctionalCalibration::calibrate(const std::vector<Segment>& segments,
                                                                         const std::vector<Movement>& given) const {
    auto set = prepare(params_, segments, given);
    if (!set) return set.error();
    auto movements = detectIn(params_, *set, given);
    if (!movements) return movements.error();
    Result result;
    result.movements = *movements;
    for (const Prepared& p : set->segments) {
        const QString& name = p.segment->name;
        // The frame's movement and the sign of its first turn (SegmentCalibration.h; JointAngles.h signs:
        // hip flexion +Z, knee flexion and forward lean −Z, right-leg abduction −X, left +X).
        SegmentCalibration::Params sp;
        CalibrationMovement needed = CalibrationMovement::Squats;
        switch (p.role.role) {
            case Role::Thigh:
                sp.firstRotation = 1.0;
                break;
            case Role::Shank:
            case Role::Pelvis:
            case Role::Trunk:
                sp.firstRotation = -1.0;
                break;
            case Role::Foot:
                needed = abductionOf(p.role.side);
                sp.functionalAxis = 0;
                sp.firstRotation = p.role.side > 0 ? -1.0 : 1.0;
                break;
            case Role::Head:  // head flexion in the squats (Fasel Table 6.2): forward, −Z
                sp.firstRotation = -1.0;
                break;
            case Role::UpperArm:  // the swing starts upward: shoulder flexion, +Z (header)
                needed = CalibrationMovement::ArmSwings;
                sp.firstRotation = 1.0;
                break;
            case Role::Forearm:  // pronated by the grip: the right forearm turns about −X, the left about +X
                needed = CalibrationMovement::ArmSwings;
                sp.functionalAxis = 0;
                sp.firstRotation = p.role.side > 0 ? -1.0 : 1.0;
                break;
        }
        const Movement* m = findMovement(*movements, needed);
        if (!m)
            return makeError(QStringLiteral("segment '%1': no %2 found in the recording (found: %3); its frame needs "
                                            "them, or mark them as an annotation")
                                 .arg(name, calibrationMovementName(needed), foundList(*movements)));
        if (int(m->repetitions.size()) < params_.minRepetitions)
            return makeError(QStringLiteral("segment '%1': %2 has %3 repetition(s); the protocol needs %4")
                                 .arg(name, calibrationMovementName(needed))
                                 .arg(m->repetitions.size())
                                 .arg(params_.minRepetitions));
        std::vector<Vec3> acc, gyr;
        const Range still = p.rows(set->upright.begin, set->upright.end);
        for (std::size_t k = still.begin; k < still.end; ++k) acc.push_back(p.segment->acc[k]);
        for (const TimeInterval& rep : m->repetitions) {
            const Range r = p.rows(rep.begin, rep.end);
            for (std::size_t k = r.begin; k < r.end; ++k) gyr.push_back(p.segment->gyr[k] - p.bias);
        }
        auto cal = SegmentCalibration(sp).calibrate(acc, gyr, p.dt);
        if (!cal)
            return makeError(
                QStringLiteral("segment '%1' (%2): %3").arg(name, calibrationMovementName(needed), cal.message()));
        if (cal->orthogonality > params_.maxAxisTilt)
            return makeError(QStringLiteral("segment '%1' (%2): the turning axis is %3° out of the plane perpendicular "
                                            "to gravity (more than %4°); the movement does not turn this segment "
                                            "about a horizontal axis")
                                 .arg(name, calibrationMovementName(needed))
                                 .arg(cal->orthogonality / math::kDeg, 0, 'f', 1)
                                 .arg(params_.maxAxisTilt / math::kDeg, 0, 'f', 1));
        SegmentResult s;
        s.name = name;
        s.mount = cal->mount;
        s.movement = needed;
        s.axisShare = cal->axisShare;
        s.orthogonality = cal->orthogonality;
        s.repetitions = int(m->repetitions.size());
        // χ: RMS angle between each repetition's axis and the axis of all of them.
        double sum = 0.0;
        std::vector<std::vector<double>> curves;
        for (const TimeInterval& rep : m->repetitions) {
            const AxisStats a = axisStats(p.segment->gyr, p.rows(rep.begin, rep.end), p.bias);
            const double angle = angleBetweenLines(a.axis, cal->functional);
            sum += angle * angle;
            curves.push_back(normalisedCurve(p, rep, cal->functional));
        }
        s.dispersion = std::sqrt(sum / double(m->repetitions.size()));
        s.cmc = multipleCorrelation(curves);
        if (s.dispersion > params_.maxDispersion)
            return makeError(QStringLiteral("segment '%1' (%2): the axis varies by %3° between repetitions (more "
                                            "than %4°); repeat the movement the same way each time")
                                 .arg(name, calibrationMovementName(needed))
                                 .arg(s.dispersion / math::kDeg, 0, 'f', 1)
                                 .arg(params_.maxDispersion / math::kDeg, 0, 'f', 1));
        // The second functional axis, where the protocol has one.
        const auto axisOver = [&](CalibrationMovement which) -> std::optional<Vec3> {
            const Movement* other = findMovement(*movements, which);
            if (!other || other->repetitions.empty()) return std::nullopt;
            return axisStats(p.segment->gyr, p.rows(other->interval.begin, other->interval.end), p.bias).axis;
        };
        if (p.role.role == Role::Thigh || p.role.role == Role::Shank) {
            if (auto x = axisOver(abductionOf(p.role.side)))
                s.crossOrthogonality = 0.5 * std::numbers::pi - angleBetweenLines(*x, cal->functional);
        } else if (p.role.role == Role::Trunk || p.role.role == Role::Head) {
            if (auto y = axisOver(CalibrationMovement::TrunkRotations))
                s.crossOrthogonality = angleBetweenLines(*y, p.up);
        }
        result.segments.push_back(s);
    }
    return result;
}

}  // namespace athlos::inertial
