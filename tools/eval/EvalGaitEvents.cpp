// athlos-eval-gait-events <gaitmap folder> [--tolerance <ms>] [--list]
// Runs the gait event detector (default parameters) on gaitmap's foot IMU example
// (imu_sample_ic_stride.csv) and scores the initial contacts against the motion-capture strides
// (stride_borders_sample_ic_stride.csv): detection rate, false detections inside the reference
// bouts, IC timing error mean ± SD. Then reports what it finds on the stair files (no reference).
#include "tools/eval/GaitEvaluation.h"

#include <QCoreApplication>
#include <QDir>
#include <algorithm>
#include <cstdio>
#include <numeric>

using namespace athlos;
using namespace athlos::events;

namespace {

void print(const char* name, const IcScore& s) {
    std::printf("%-6s ICs %2d/%2d (%.1f %%)  strides %2d/%2d (%.1f %%)  false ICs %d  IC error %+.1f ± %.1f ms\n", name,
                s.matchedIcs, s.referenceIcs, 100.0 * s.icRate(), s.matchedStrides, s.referenceStrides,
                100.0 * s.strideRate(), s.falseIcs, s.meanErrorMs, s.sdErrorMs);
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: athlos-eval-gait-events <gaitmap folder> [--tolerance <ms>] [--list]\n");
        return 2;
    }
    const bool list = args.contains(QStringLiteral("--list"));  // every stride of the stair files
    double tolMs = 50.0;
    if (const qsizetype i = args.indexOf(QStringLiteral("--tolerance")); i > 0 && i + 1 < args.size())
        tolMs = args[i + 1].toDouble();
    const QDir dir(args[1]);
    auto v = validateGaitmap(dir.filePath(QStringLiteral("imu_sample_ic_stride.csv")),
                             dir.filePath(QStringLiteral("stride_borders_sample_ic_stride.csv")), tolMs / 1000.0);
    if (!v) {
        std::fprintf(stderr, "%s\n", qUtf8Printable(v.message()));
        return 1;
    }
    std::printf("gaitmap imu_sample_ic_stride (102.4 Hz), tolerance ±%.0f ms\n", tolMs);
    print("left", v->left);
    print("right", v->right);
    print("total", v->total);
    for (const char* stairs : {"imu_sample_healthy_stair_up.csv", "imu_sample_healthy_stair_down.csv"}) {
        const QString file = dir.filePath(QString::fromLatin1(stairs));
        if (!QFileInfo::exists(file)) continue;
        auto feet = detectGaitmapFile(file);
        if (!feet) {
            std::fprintf(stderr, "%s\n", qUtf8Printable(feet.message()));
            return 1;
        }
        for (const auto& f : *feet) {
            std::vector<double> times;
            double conf = 0.0;
            for (const auto& s : f.strides) {
                times.push_back(s.tEnd - s.tStart);
                conf += s.confidence;
            }
            if (list)
                for (const auto& s : f.strides)
                    std::printf(
                        "  %8.3f–%8.3f s (%.3f s)  tc %.3f  min_vel %.3f  swing peak %.2f rad/s  rest %.2f rad/s  "
                        "confidence %.2f\n",
                        s.tStart, s.tEnd, s.tEnd - s.tStart, s.tTc, s.tMinVel, s.swingPeak, s.restGyr, s.confidence);
            std::sort(times.begin(), times.end());
            std::printf(
                "%s %-5s (%.1f Hz, swing sign %+d): %zu ICs, %zu strides, median stride %.3f s, mean confidence %.2f\n",
                stairs, qUtf8Printable(f.foot), f.rate, f.swingSign, f.ics.size(), f.strides.size(),
                times.empty() ? 0.0 : times[times.size() / 2], times.empty() ? 0.0 : conf / double(times.size()));
        }
    }
    return 0;
}
