#include "plugins/events/MediolateralAxis.h"

#include "core/math/PrincipalAxis.h"
#include "core/processing/Translator.h"

#include <cmath>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events"};
}  // namespace

MediolateralAxis principalRotationAxis(const double* gyr, std::size_t rows, std::size_t stride) {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < rows; ++k) {
        const Eigen::Vector3d w(gyr + k * stride);
        if (w.allFinite()) s.noalias() += w * w.transpose();
    }
    MediolateralAxis out;
    const math::PrincipalAxis p = math::principalAxisOfMoment(s, Eigen::Vector3d::UnitY());
    if (p.share == 0.0) return out;
    Eigen::Vector3d u = p.axis;
    Eigen::Index largest = 0;
    u.cwiseAbs().maxCoeff(&largest);
    if (u[largest] < 0.0) u = -u;
    out.axis = out.principal = u.normalized();
    out.dominance = p.share;
    return out;
}

std::optional<MediolateralAxis> mediolateralAxis(const QString& choice, const double* gyr, std::size_t rows,
                                                 std::size_t stride) {
    if (choice == QLatin1String("auto")) {
        MediolateralAxis out = principalRotationAxis(gyr, rows, stride);
        Eigen::Index nearest = 0;
        if (out.principal.cwiseAbs().maxCoeff(&nearest) >= std::cos(kSnapAngle))
            out.axis = Eigen::Vector3d::Unit(nearest);  // the largest component is positive
        return out;
    }
    MediolateralAxis out;
    if (choice == QLatin1String("x"))
        out.axis = Eigen::Vector3d::UnitX();
    else if (choice == QLatin1String("y"))
        out.axis = Eigen::Vector3d::UnitY();
    else if (choice == QLatin1String("z"))
        out.axis = Eigen::Vector3d::UnitZ();
    else
        return std::nullopt;
    return out;
}

ParameterSpec mlAxisParameter() {
    return ParameterSpec::choice(
        QStringLiteral("ml_axis"),
        {QStringLiteral("auto"), QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")}, QStringLiteral("auto"),
        tr("Sensor axis along the medio-lateral direction (y when x points forward and z up); auto: the "
           "principal axis of the angular velocity, whatever the mounting."));
}

ParameterSpec swingSignParameter() {
    return ParameterSpec::choice(QStringLiteral("swing_sign"),
                                 {QStringLiteral("auto"), QStringLiteral("positive"), QStringLiteral("negative")},
                                 QStringLiteral("auto"),
                                 tr("Sign of the medio-lateral angular velocity during swing; auto: the sign of "
                                    "the longest sustained rotation."));
}

int swingSignOf(const QString& choice) {
    return choice == QLatin1String("positive") ? 1 : choice == QLatin1String("negative") ? -1 : 0;
}

QString axisText(const Eigen::Vector3d& axis) {
    return QStringLiteral("[%1, %2, %3]").arg(axis.x(), 0, 'f', 3).arg(axis.y(), 0, 'f', 3).arg(axis.z(), 0, 'f', 3);
}

}  // namespace athlos::events
