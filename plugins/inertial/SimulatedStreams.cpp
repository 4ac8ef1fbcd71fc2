#include "plugins/inertial/SimulatedStreams.h"

#include "core/processing/OutputStreams.h"

namespace athlos::inertial {

Stream simulatedImuStream(const std::vector<double>& t, const std::vector<math::Vec3>& acc,
                          const std::vector<math::Vec3>& gyr, const QString& segment, const math::Quat& mount,
                          QJsonObject attributes) {
    StreamData d(t.size(), 6);
    d.t = t;
    for (std::size_t k = 0; k < t.size(); ++k)
        for (int i = 0; i < 3; ++i) {
            d.at(k, i) = acc[k][i];
            d.at(k, 3 + i) = gyr[k][i];
        }
    attributes.insert(QStringLiteral("segment"), segment);
    attributes.insert(QStringLiteral("true_mount"), formatQuaternion(mount));
    return outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                        columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
                                  {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s"}),
                        std::move(d), std::move(attributes));
}

Stream trueSegmentOrientations(const std::vector<double>& t, const QStringList& segments,
                               const std::vector<const std::vector<math::Quat>*>& orientations,
                               const QJsonObject& attributes) {
    const int n = int(segments.size());
    StreamData d(t.size(), std::size_t(4 * n));
    d.t = t;
    QStringList names, units;
    for (int s = 0; s < n; ++s) {
        for (const char* q : {"_qw", "_qx", "_qy", "_qz"}) {
            names << segments[s] + QLatin1String(q);
            units << QStringLiteral("1");
        }
        const std::vector<math::Quat>& segment = *orientations[std::size_t(s)];
        for (std::size_t k = 0; k < t.size(); ++k) {
            const math::Quat q = math::canonical(segment[k]);
            d.at(k, 4 * s) = q.w();
            d.at(k, 4 * s + 1) = q.x();
            d.at(k, 4 * s + 2) = q.y();
            d.at(k, 4 * s + 3) = q.z();
        }
    }
    return outputStream(QStringLiteral("segment-orientation"), QStringLiteral("ENU"), columnsOf(names, units),
                        std::move(d), attributes);
}

Stream trueJointAngles(const std::vector<double>& t, const std::vector<AnatomicalAngles>& angles, Joint joint,
                       Side side, QJsonObject attributes) {
    StreamData d(t.size(), 3);
    d.t = t;
    for (std::size_t k = 0; k < t.size(); ++k) {
        d.at(k, 0) = angles[k].flexion;
        d.at(k, 1) = angles[k].abduction;
        d.at(k, 2) = angles[k].rotation;
    }
    attributes.insert(QStringLiteral("joint"), jointName(joint));
    attributes.insert(QStringLiteral("side"), sideName(side));
    attributes.insert(QStringLiteral("reference"), true);
    return outputStream(QStringLiteral("joint-angles"), QStringLiteral("segment"),
                        columnsOf({"flexion", "abduction", "rotation"}, {"rad", "rad", "rad"}), std::move(d),
                        std::move(attributes));
}

}  // namespace athlos::inertial
