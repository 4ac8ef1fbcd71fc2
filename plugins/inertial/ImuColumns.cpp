#include "plugins/inertial/ImuColumns.h"

namespace athlos::inertial {

int tripleIndex(const StreamInfo& info, const QString& prefix) {
    const int x = info.columnIndex(prefix + QStringLiteral("x"));
    if (x < 0 || info.columnIndex(prefix + QStringLiteral("y")) != x + 1 ||
        info.columnIndex(prefix + QStringLiteral("z")) != x + 2)
        return -1;
    return x;
}

Expected<ImuColumns> imuColumns(const InputSamples& input, bool requireMag) {
    const StreamInfo& info = input.info();
    ImuColumns c;
    c.acc = tripleIndex(info, QStringLiteral("acc_"));
    c.gyr = tripleIndex(info, QStringLiteral("gyr_"));
    c.mag = tripleIndex(info, QStringLiteral("mag_"));
    const QString have = info.columnNames().join(QStringLiteral(", "));
    if (c.acc < 0 || c.gyr < 0)
        return input.error(QStringLiteral("needs adjacent columns acc_x, acc_y, acc_z and gyr_x, gyr_y, gyr_z "
                                          "(it has: %1)")
                               .arg(have));
    if (requireMag && c.mag < 0)
        return input.error(QStringLiteral("mode: 9d needs magnetometer columns mag_x, mag_y, mag_z (it has: %1); "
                                          "use mode=6d")
                               .arg(have));
    return c;
}

Expected<std::vector<math::Quat>> orientationQuaternions(const InputSamples& s) {
    int col[4];
    int i = 0;
    for (const char* name : {"qw", "qx", "qy", "qz"}) {
        col[i] = s.info().columnIndex(QLatin1String(name));
        if (col[i] < 0)
            return s.error(
                QStringLiteral("no column '%1' (an orientation stream needs qw, qx, qy, qz)").arg(QLatin1String(name)));
        ++i;
    }
    const StreamData& d = *s.data;
    std::vector<math::Quat> q(d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k) {
        q[k] = math::Quat(d.at(k, col[0]), d.at(k, col[1]), d.at(k, col[2]), d.at(k, col[3]));
        if (!q[k].coeffs().allFinite() || q[k].norm() < 1e-9)
            return s.error(QStringLiteral("row %1 holds no valid quaternion").arg(k));
        q[k].normalize();
    }
    return q;
}

}  // namespace athlos::inertial
