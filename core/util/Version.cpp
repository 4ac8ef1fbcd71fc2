#include "core/util/Version.h"

#include "core/util/BuildInfo.h"

#include <Eigen/Core>
#include <ceres/version.h>
#include <hdf5.h>
#include <opencv2/core/version.hpp>

#include <QStringList>

namespace athlos {

QString appVersion() { return QStringLiteral(ATHLOS_VERSION); }

QString libraryVersions() {
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    QStringList lines;
    lines << QStringLiteral("Athlos %1").arg(appVersion());
    lines
        << QStringLiteral("Qt %1 (built with %2)").arg(QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR));
    lines
        << QStringLiteral("Eigen %1.%2.%3").arg(EIGEN_WORLD_VERSION).arg(EIGEN_MAJOR_VERSION).arg(EIGEN_MINOR_VERSION);
    lines << QStringLiteral("Ceres Solver %1").arg(QStringLiteral(CERES_VERSION_STRING));
    lines << QStringLiteral("OpenCV %1").arg(QStringLiteral(CV_VERSION));
    lines << QStringLiteral("HDF5 %1.%2.%3").arg(major).arg(minor).arg(release);
    return lines.join(QLatin1Char('\n'));
}

}  // namespace athlos
