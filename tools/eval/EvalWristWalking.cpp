// athlos-eval-wrist-walking: wrist-cadence and the wrist-speed model on the wrist-walking simulator
// (docs/validation/wrist-walking.md). Walkers are split by subject: the speed model is trained on
// the training walkers (seeds 1001…, heights 1.55–1.95 m) and scored on others (seeds 2001…,
// heights in between), as the thesis trains calibration-free models (only the height is given).
//
//   athlos-eval-wrist-walking [--train N] [--test N] [--duration S] [--clusters K]
#include "tools/eval/WristEvaluation.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>
#include <cstdio>

using namespace athlos::events;

namespace {

void print(const char* what, const ErrorSummary& s) {
    std::printf("| %-44s | %5zu | %+6.2f %% | %+6.2f … %+6.2f %% | %5.2f %% |\n", what, s.n, s.median, s.q25, s.q75,
                s.medianAbs);
}

ErrorSummary speedErrors(const WristSpeedModel& model, const std::vector<WristFeatures>& x,
                         const std::vector<double>& v) {
    std::vector<double> e;
    for (std::size_t k = 0; k < x.size(); ++k) e.push_back(100.0 * (model.predict(x[k]) - v[k]) / v[k]);
    return summarize(e);
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int trainCount = 16, testCount = 6, clusters = 16;
    double duration = 600.0;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--train"))
            trainCount = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--test"))
            testCount = args[i + 1].toInt();
        else if (args[i] == QLatin1String("--duration"))
            duration = args[i + 1].toDouble();
        else if (args[i] == QLatin1String("--clusters"))
            clusters = args[i + 1].toInt();
        else {
            std::fprintf(stderr,
                         "usage: athlos-eval-wrist-walking [--train N] [--test N] [--duration S] "
                         "[--clusters K]\n");
            return 2;
        }
    }
    if (trainCount < 1 || testCount < 1 || duration < 60.0 || clusters < 1) {
        std::fprintf(stderr, "athlos-eval-wrist-walking: --train and --test ≥ 1, --duration ≥ 60 s, --clusters ≥ 1\n");
        return 2;
    }
    WristWalkParams base;
    base.duration = duration;
    std::vector<WristTrial> train, test;
    for (int i = 0; i < trainCount; ++i)
        train.push_back(simulateWristTrial({unsigned(1001 + i), 1.55 + 0.4 * i / std::max(1, trainCount - 1)}, base));
    for (int i = 0; i < testCount; ++i)
        test.push_back(simulateWristTrial({unsigned(2001 + i), 1.58 + 0.34 * i / std::max(1, testCount - 1)}, base));

    std::printf("Wrist walking on the simulator: %d training and %d test walkers, %.0f s each\n\n", trainCount,
                testCount, duration);
    std::printf("| %-44s | %5s | %8s | %19s | %7s |\n", "estimate (test walkers)", "n", "median", "IQR", "med |e|");
    std::printf("|%s|%s|%s|%s|%s|\n", std::string(46, '-').c_str(), std::string(7, '-').c_str(),
                std::string(10, '-').c_str(), std::string(21, '-').c_str(), std::string(9, '-').c_str());
    CadenceScore all;
    for (const WristTrial& t : test) scoreCadence(t, all);
    print("cadence, tracked (thesis −0.13 %, −1.72…2.04)", summarize(all.errors));
    // The same windows without tracking: eq. 12.1 alone.
    std::vector<double> raw;
    for (const WristTrial& t : test)
        for (std::size_t k = 0; k < t.windows.size(); ++k)
            if (std::isfinite(t.trueCadence[k]) && t.windows[k].walking)
                raw.push_back(100.0 * (t.windows[k].rawCadence - t.trueCadence[k]) / t.trueCadence[k]);
    print("cadence, eq. 12.1 without tracking", summarize(raw));

    std::vector<WristFeatures> xTrain, xTest;
    std::vector<double> vTrain, vTest;
    speedRows(train, xTrain, vTrain);
    speedRows(test, xTest, vTest);
    WristSpeedModelParams params;
    params.clusters = clusters;
    QString error;
    const WristSpeedModel model = WristSpeedModel::train(xTrain, vTrain, params, &error);
    if (!model.valid()) {
        std::fprintf(stderr, "athlos-eval-wrist-walking: %s\n", qPrintable(error));
        return 1;
    }
    char label[64];
    std::snprintf(label, sizeof label, "speed, %d clusters (thesis −0.67 %%, −6.5…6.2)", clusters);
    print(label, speedErrors(model, xTest, vTest));
    params.clusters = 1;
    print("speed, one global linear model", speedErrors(WristSpeedModel::train(xTrain, vTrain, params), xTest, vTest));
    // Without the barometer (x3 = 0): slopes unexplained.
    auto noBaro = [](std::vector<WristFeatures> x) {
        for (auto& r : x) r[2] = 0.0;
        return x;
    };
    params.clusters = clusters;
    print("speed, clusters, barometer feature zeroed",
          speedErrors(WristSpeedModel::train(noBaro(xTrain), vTrain, params), noBaro(xTest), vTest));
    double mean = 0.0;
    for (double v : vTrain) mean += v;
    mean /= double(vTrain.size());
    std::vector<double> constant;
    for (double v : vTest) constant.push_back(100.0 * (mean - v) / v);
    print("speed, constant (training mean)", summarize(constant));

    std::printf("\nWalking detection (test walkers, windows entirely walking or entirely not):\n");
    std::printf(
        "  walking windows detected %d, missed %d (%.1f %%); pause windows taken as walking %d of %d (%.1f %%)\n",
        all.walkingDetected, all.walkingMissed,
        100.0 * all.walkingMissed / std::max(1, all.walkingDetected + all.walkingMissed), all.pauseAsWalking,
        all.pauseAsWalking + all.pauseRejected,
        100.0 * all.pauseAsWalking / std::max(1, all.pauseAsWalking + all.pauseRejected));
    std::printf("  speed model: %d training windows, training RMSE %.3f m/s\n", model.trainingRows, model.trainingRmse);
    return 0;
}
