#include "plugins/activity/TorsoPitch.h"

#include "plugins/activity/EventDetectors.h"
#include "plugins/signal/Butterworth.h"

#include <algorithm>
#include <cmath>

namespace athlos::activity {

namespace {
using signal::Butterworth;

// The zero-phase low-passed accelerometer, rows × 3.
Expected<Eigen::MatrixX3d> lowPassed(const StreamInfo& info, const StreamData& data, double cutoff) {
    auto columns = accelerometerColumns(info);
    if (!columns) return makeError(QStringLiteral("torso pitch: ") + columns.message());
    const double dt = data.medianInterval();
    if (data.rows() < 8 || !(dt > 0)) return makeError(QStringLiteral("torso pitch: the stream is too short"));
    Butterworth::Params p;
    p.order = 2;
    p.cutoff = cutoff;
    p.samplingRate = 1.0 / dt;
    if (Status s = Butterworth::check(p); !s) return makeError(QStringLiteral("torso pitch, cutoff: ") + s.message());
    const Butterworth filter(p);
    Eigen::MatrixX3d g(Eigen::Index(data.rows()), 3);
    for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd x(Eigen::Index(data.rows()));
        for (std::size_t i = 0; i < data.rows(); ++i) x[Eigen::Index(i)] = data.at(i, (*columns)[std::size_t(c)]);
        filter.filterSegments(x, true);
        g.col(c) = x;
    }
    return g;
}

Expected<Eigen::Vector3d> axisOf(const QString& name) {
    const QString n = name.trimmed().toLower();
    const double sign = n.startsWith(u'-') ? -1.0 : 1.0;
    const QString axis = n.startsWith(u'-') || n.startsWith(u'+') ? n.mid(1) : n;
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (axis == u"x")
        v.x() = sign;
    else if (axis == u"y")
        v.y() = sign;
    else if (axis == u"z")
        v.z() = sign;
    else
        return makeError(QStringLiteral("up_axis: '%1' is not one of x, -x, y, -y, z, -z").arg(name));
    return v;
}

Expected<Eigen::Vector3d> referenceFrom(const StreamInfo& info, const StreamData& data,
                                        const TorsoPitch::Params& params, const Eigen::MatrixX3d& g) {
    if (params.referenceDuration <= 0.0) return axisOf(params.upAxis);
    auto columns = accelerometerColumns(info);
    if (!columns) return columns.error();
    const double t0 = data.t.empty() ? 0.0 : data.t.front();
    const double a = t0 + params.referenceStart, b = a + params.referenceDuration;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double n = 0.0, norm = 0.0, norm2 = 0.0;
    for (std::size_t i = 0; i < data.rows(); ++i) {
        if (data.t[i] < a || data.t[i] > b) continue;
        sum += g.row(Eigen::Index(i)).transpose();
        Eigen::Vector3d raw;
        for (int c = 0; c < 3; ++c) raw[c] = data.at(i, (*columns)[std::size_t(c)]);
        norm += raw.norm();
        norm2 += raw.squaredNorm();
        n += 1.0;
    }
    if (n < 8.0)
        return makeError(QStringLiteral("reference_start/reference_duration: the standing period [%1, %2] s holds "
                                        "fewer than 8 samples")
                             .arg(a)
                             .arg(b));
    const double sd = std::sqrt(std::max(0.0, norm2 / n - (norm / n) * (norm / n)));
    if (sd > params.stillness)
        return makeError(QStringLiteral("reference_start/reference_duration: the player was not standing still in "
                                        "[%1, %2] s (SD of |a| %3 m/s² > %4); give another period or up_axis")
                             .arg(a)
                             .arg(b)
                             .arg(sd, 0, 'f', 2)
                             .arg(params.stillness));
    if (sum.norm() < 1e-9) return makeError(QStringLiteral("torso pitch: no gravity in the standing period"));
    return Eigen::Vector3d(sum.normalized());
}
}  // namespace

Expected<Eigen::Vector3d> TorsoPitch::reference(const StreamInfo& info, const StreamData& data, const Params& params) {
    auto g = lowPassed(info, data, params.cutoff);
    if (!g) return g.error();
    return referenceFrom(info, data, params, *g);
}

Expected<std::vector<double>> TorsoPitch::compute(const StreamInfo& info, const StreamData& data,
                                                  const Params& params) {
    auto g = lowPassed(info, data, params.cutoff);
    if (!g) return g.error();
    auto up = referenceFrom(info, data, params, *g);
    if (!up) return up.error();
    std::vector<double> pitch(data.rows());
    for (Eigen::Index i = 0; i < g->rows(); ++i) {
        const Eigen::Vector3d d = g->row(i).transpose();
        const double n = d.norm();
        // α = angle between the gravity direction now and when upright (Fig. 5.5).
        pitch[std::size_t(i)] = n > 1e-9 ? std::acos(std::clamp(d.dot(*up) / n, -1.0, 1.0)) : 0.0;
    }
    return pitch;
}

}  // namespace athlos::activity
