#include "plugins/events/SkiImu.h"

#include <Eigen/Geometry>

namespace athlos::events {

Eigen::Vector3d skiAxis(const QString& name) {
    const QString n = name.trimmed().toLower();
    const double s = n.startsWith(QLatin1Char('-')) ? -1.0 : 1.0;
    const QString a = n.right(1);
    if (n.size() > 2 || (n.size() == 2 && s > 0)) return Eigen::Vector3d::Zero();
    if (a == QLatin1String("x")) return {s, 0, 0};
    if (a == QLatin1String("y")) return {0, s, 0};
    if (a == QLatin1String("z")) return {0, 0, s};
    return Eigen::Vector3d::Zero();
}

SkiImu toSkiFrame(const std::vector<double>& t, const std::vector<double>& acc, const std::vector<double>& gyr,
                  const Eigen::Vector3d& forward, const Eigen::Vector3d& left) {
    const Eigen::Vector3d up = forward.cross(left);
    SkiImu imu;
    imu.t = t;
    const std::size_t n = t.size();
    for (auto* v : {&imu.accForward, &imu.accLeft, &imu.accUp, &imu.gyrLeft, &imu.gyrNorm}) v->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d a(acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]);
        const Eigen::Vector3d g(gyr[3 * i], gyr[3 * i + 1], gyr[3 * i + 2]);
        imu.accForward[i] = a.dot(forward);
        imu.accLeft[i] = a.dot(left);
        imu.accUp[i] = a.dot(up);
        imu.gyrLeft[i] = g.dot(left);
        imu.gyrNorm[i] = g.norm();
    }
    return imu;
}

Expected<ImuRows> imuRowsOf(const RunContext& c, int index) {
    const Stream* stream = c.stream(index);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(c.inputRole(index)));
    const StreamInfo& info = stream->info();
    int col[6];
    const char* names[6] = {"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};
    for (int k = 0; k < 6; ++k) {
        col[k] = info.columnIndex(QLatin1String(names[k]));
        if (col[k] < 0)
            return c.inputError(index,
                                QStringLiteral("has no column %1 (it has: %2)")
                                    .arg(QLatin1String(names[k]), info.columnNames().join(QStringLiteral(", "))));
        const QString unit = info.columns[std::size_t(col[k])].unit;
        const QString want = k < 3 ? QStringLiteral("m/s^2") : QStringLiteral("rad/s");
        if (!unit.isEmpty() && unit != want)
            return c.inputError(
                index, QStringLiteral("column %1 is in '%2'; expected %3").arg(QLatin1String(names[k]), unit, want));
    }
    auto input = c.samples(index);
    if (!input) return input.error();
    auto interval = input->samplingInterval();
    if (!interval) return interval.error();
    const StreamData& d = *input->data;
    ImuRows rows;
    rows.t = d.t;
    rows.acc.reserve(3 * d.rows());
    rows.gyr.reserve(3 * d.rows());
    for (std::size_t i = 0; i < d.rows(); ++i)
        for (int k = 0; k < 3; ++k) {
            rows.acc.push_back(d.at(i, col[k]));
            rows.gyr.push_back(d.at(i, col[3 + k]));
        }
    return rows;
}

Expected<std::pair<Eigen::Vector3d, Eigen::Vector3d>> skiAxesOf(const RunContext& c) {
    const Eigen::Vector3d forward = skiAxis(c.text(QStringLiteral("forward_axis")));
    const Eigen::Vector3d left = skiAxis(c.text(QStringLiteral("ml_axis")));
    if (forward.norm() == 0.0)
        return makeError(QStringLiteral("forward_axis: '%1' is not one of x, -x, y, -y, z, -z")
                             .arg(c.text(QStringLiteral("forward_axis"))));
    if (left.norm() == 0.0)
        return makeError(
            QStringLiteral("ml_axis: '%1' is not one of x, -x, y, -y, z, -z").arg(c.text(QStringLiteral("ml_axis"))));
    if (std::abs(forward.dot(left)) > 0.5)
        return makeError(QStringLiteral("ml_axis: '%1' is along forward_axis '%2'; they must be different sensor axes")
                             .arg(c.text(QStringLiteral("ml_axis")), c.text(QStringLiteral("forward_axis"))));
    return std::make_pair(forward, left);
}

}  // namespace athlos::events
