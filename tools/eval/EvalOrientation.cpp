// athlos-eval-orientation <broad folder> [--algorithms a,b,...] [--offline]
// --offline: vqf also runs in offline mode (whole-recording smoothing), printed as vqf-offline.
// Runs every orientation algorithm (6D and 9D) on every BROAD trial (*.hdf5) of a folder and prints
// the benchmark's RMS errors (deg) per trial and the mean over trials, as defined in
// shared/data/README.md: 9D judged on total, 6D on inclination. One parameter set for all trials.
#include "core/io/Importer.h"
#include "core/math/OrientationError.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <QCoreApplication>
#include <QDir>
#include <cstdio>

using namespace athlos;
using namespace athlos::inertial;

namespace {

struct Trial {
    QString name;
    std::shared_ptr<const StreamData> imu, ref;
    int acc = -1, gyr = -1, mag = -1, qw = -1, movement = -1;
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
                     "usage: athlos-eval-orientation <broad folder> [--algorithms vqf,madgwick,...] [--offline]\n");
        return 2;
    }
    QStringList algorithms = orientationAlgorithmNames();
    const int ai = args.indexOf(QStringLiteral("--algorithms"));
    if (ai > 0 && ai + 1 < args.size()) algorithms = args.at(ai + 1).split(QLatin1Char(','));
    if (args.contains(QStringLiteral("--offline")) && algorithms.contains(QStringLiteral("vqf")))
        algorithms.insert(algorithms.indexOf(QStringLiteral("vqf")) + 1, QStringLiteral("vqf-offline"));
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
            for (std::size_t r = 0; r < ref.size(); ++r) {
                ref[r] = math::Quat(trial.ref->at(r, trial.qw), trial.ref->at(r, trial.qw + 1),
                                    trial.ref->at(r, trial.qw + 2), trial.ref->at(r, trial.qw + 3));
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
