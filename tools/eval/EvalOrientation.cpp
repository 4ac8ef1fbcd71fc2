// athlos-eval-orientation <broad folder> [--algorithms a,b,...] [--offline] [--ref-shift s]
// --offline: vqf also runs in offline mode (whole-recording smoothing), printed as vqf-offline.
// --ref-shift: diagnostic only, not a result: compares the estimate at t with the reference at t − s
// (slerp between samples), to measure how much of the error a clock offset between the IMU and the
// optical system explains (BROAD: the IMU lags by ≈ 2.6 ms, docs/validation/inertial.md §1b).
// --sync: prints, per trial, that clock offset measured from the accelerometer and the optical
// positions alone (tools/eval/ImuClockOffset.h) and exits.
// Runs every orientation algorithm (6D and 9D) on every BROAD trial (*.hdf5) of a folder and prints
// the benchmark's RMS errors (deg) per trial and the mean over trials, as defined in
// shared/data/README.md: 9D judged on total, 6D on inclination. One parameter set for all trials.
#include "core/io/Importer.h"
#include "core/math/OrientationError.h"
#include "plugins/inertial/OrientationEstimation.h"
#include "tools/eval/ImuClockOffset.h"

#include <QCoreApplication>
#include <QDir>
#include <cstdio>
#include <limits>

using namespace athlos;
using namespace athlos::inertial;

namespace {

struct Trial {
    QString name;
    std::shared_ptr<const StreamData> imu, ref;
    int acc = -1, gyr = -1, mag = -1, qw = -1, movement = -1, pos = -1;
    double ts = 0.0;
};

Expected<Trial> loadTrial(const QString& file) {
    ImportOptions options;
    options.format = QStringLiteral("broad");
    options.target = QStringLiteral("t");
    auto result = importFile(file, options);
    if (!result) return result.error();
    Trial trial;
    trial.name = QFileInfo(file).completeBaseName();
    for (const ImportedItem& item : result->items) {
        const Stream* s = std::get_if<Stream>(&item.item);
        if (!s) continue;
        auto data = s->data();
        if (!data) return data.error();
        if (s->kind() == QLatin1String("imu")) {
            trial.imu = *data;
            trial.acc = s->info().columnIndex(QStringLiteral("acc_x"));
            trial.gyr = s->info().columnIndex(QStringLiteral("gyr_x"));
            trial.mag = s->info().columnIndex(QStringLiteral("mag_x"));
        } else {
            trial.ref = *data;
            trial.qw = s->info().columnIndex(QStringLiteral("qw"));
            trial.movement = s->info().columnIndex(QStringLiteral("movement"));
            trial.pos = s->info().columnIndex(QStringLiteral("pos_x"));
        }
    }
    if (!trial.imu || !trial.ref || trial.acc < 0 || trial.gyr < 0 || trial.mag < 0 || trial.qw < 0 ||
        trial.movement < 0)
        return makeError(QStringLiteral("%1: not a BROAD trial (imu/reference streams missing)").arg(file));
    trial.ts = trial.imu->medianInterval();
    return trial;
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr,
                     "usage: athlos-eval-orientation <broad folder> [--algorithms vqf,madgwick,...] [--offline] "
                     "[--ref-shift s]\n");
        return 2;
    }
    QStringList algorithms = orientationAlgorithmNames();
    const int ai = args.indexOf(QStringLiteral("--algorithms"));
    if (ai > 0 && ai + 1 < args.size()) algorithms = args.at(ai + 1).split(QLatin1Char(','));
    if (args.contains(QStringLiteral("--offline")) && algorithms.contains(QStringLiteral("vqf")))
        algorithms.insert(algorithms.indexOf(QStringLiteral("vqf")) + 1, QStringLiteral("vqf-offline"));
    double refShift = 0.0;
    const int si = args.indexOf(QStringLiteral("--ref-shift"));
    if (si > 0 && si + 1 < args.size()) refShift = args.at(si + 1).toDouble();
    if (refShift != 0.0) std::printf("DIAGNOSTIC: reference shifted by %g s (not a result)\n", refShift);
    QDir dir(args.at(1));
    const QStringList files =
        dir.entryList({QStringLiteral("*.hdf5"), QStringLiteral("*.h5")}, QDir::Files, QDir::Name);
    if (files.isEmpty()) {
        std::fprintf(stderr, "no *.hdf5 trials in %s\n", qPrintable(args.at(1)));
        return 1;
    }
    std::vector<Trial> trials;
    for (const QString& f : files) {
        auto t = loadTrial(dir.filePath(f));
        if (!t) {
            std::fprintf(stderr, "%s\n", qPrintable(t.message()));
            return 1;
        }
        trials.push_back(std::move(*t));
    }
    if (args.contains(QStringLiteral("--sync"))) {
        std::printf("%-38s %14s %10s %12s\n", "trial", "acc lag (smp)", "(ms)", "rms (m/s^2)");
        double sum = 0.0;
        for (const Trial& trial : trials) {
            if (trial.pos < 0) continue;
            const auto& imu = *trial.imu;
            const auto& ref = *trial.ref;
            std::vector<math::Vec3> acc(imu.rows()), pos(ref.rows());
            std::vector<math::Quat> q(ref.rows());
            for (std::size_t r = 0; r < imu.rows(); ++r)
                acc[r] = math::Vec3(imu.at(r, trial.acc), imu.at(r, trial.acc + 1), imu.at(r, trial.acc + 2));
            for (std::size_t r = 0; r < ref.rows(); ++r) {
                q[r] = math::Quat(ref.at(r, trial.qw), ref.at(r, trial.qw + 1), ref.at(r, trial.qw + 2),
                                  ref.at(r, trial.qw + 3));
                pos[r] = math::Vec3(ref.at(r, trial.pos), ref.at(r, trial.pos + 1), ref.at(r, trial.pos + 2));
            }
            const eval::ClockOffset c = eval::imuClockOffset(acc, q, pos, trial.ts);
            std::printf("%-38s %14.2f %10.2f %12.3f\n", qPrintable(trial.name), c.samples,
                        1000.0 * c.samples * trial.ts, c.rms);
            sum += c.samples * trial.ts;
        }
        std::printf("%-38s %14s %10.2f\n", "MEAN", "", 1000.0 * sum / static_cast<double>(trials.size()));
        return 0;
    }
    std::printf("%-38s %-10s %8s %8s %8s | %8s\n", "trial", "algorithm", "9D tot", "9D head", "9D incl", "6D incl");
    for (const QString& name : algorithms) {
        const bool offline = name == QLatin1String("vqf-offline");
        auto algorithm = parseOrientationAlgorithm(offline ? QStringLiteral("vqf") : name);
        if (!algorithm) {
            std::fprintf(stderr, "%s\n", qPrintable(algorithm.message()));
            return 2;
        }
        double sumTot = 0, sumHead = 0, sumIncl = 0, sumIncl6 = 0;
        for (const Trial& trial : trials) {
            const auto& imu = *trial.imu;
            ImuBatch batch{imu.values.data() + trial.gyr, imu.values.data() + trial.acc, imu.values.data() + trial.mag,
                           imu.rows(), static_cast<std::size_t>(imu.columns)};
            std::vector<math::Quat> ref(trial.ref->rows());
            std::vector<bool> maskVec(trial.ref->rows());
            const auto refAt = [&](std::size_t r) {
                return math::Quat(trial.ref->at(r, trial.qw), trial.ref->at(r, trial.qw + 1),
                                  trial.ref->at(r, trial.qw + 2), trial.ref->at(r, trial.qw + 3));
            };
            for (std::size_t r = 0; r < ref.size(); ++r) {
                ref[r] = refAt(r);
                if (refShift != 0.0) {
                    const double t = static_cast<double>(r) - refShift / trial.ts;
                    if (t < 0.0 || t > static_cast<double>(ref.size() - 1)) {
                        ref[r].coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());
                    } else {
                        const auto r0 = static_cast<std::size_t>(t);
                        const std::size_t r1 = std::min(r0 + 1, ref.size() - 1);
                        ref[r] = math::slerp(refAt(r0), refAt(r1), t - static_cast<double>(r0));
                    }
                }
                maskVec[r] = trial.ref->at(r, trial.movement) != 0.0;
            }
            std::unique_ptr<bool[]> mask(new bool[ref.size()]);
            for (std::size_t r = 0; r < ref.size(); ++r) mask[r] = maskVec[r];
            OrientationOptions options;
            options.algorithm = *algorithm;
            options.offline = offline;
            options.useMagnetometer = true;
            const auto r9 = estimateOrientation(options, batch, trial.ts);
            options.useMagnetometer = false;
            const auto r6 = estimateOrientation(options, batch, trial.ts);
            const auto e9 = math::orientationErrorRms(r9.track.q, ref, {mask.get(), ref.size()});
            const auto e6 = math::orientationErrorRms(r6.track.q, ref, {mask.get(), ref.size()});
            std::printf("%-38s %-10s %8.2f %8.2f %8.2f | %8.2f\n", qPrintable(trial.name), qPrintable(name), e9.total,
                        e9.heading, e9.inclination, e6.inclination);
            sumTot += e9.total;
            sumHead += e9.heading;
            sumIncl += e9.inclination;
            sumIncl6 += e6.inclination;
        }
        const double n = static_cast<double>(trials.size());
        std::printf("%-38s %-10s %8.2f %8.2f %8.2f | %8.2f\n\n", "MEAN", qPrintable(name), sumTot / n, sumHead / n,
                    sumIncl / n, sumIncl6 / n);
        std::fflush(stdout);
    }
    return 0;
}
