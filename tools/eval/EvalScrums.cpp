// Scrum detection by the top-6 torso pitch on simulated rugby sevens matches (seed 000 §5.1; digest
// §7): per seed the torso-pitch RMSE of all 14 players against the simulator's truth, the top-6
// mean inside scrums and elsewhere, and the recall and precision of the detected scrums.
// Figures: docs/validation/activity.md.
//
//   build/bin/athlos-eval-scrums [--seeds N] [--duration S] [--scrums K] [--tackles T] [--contacts C] [--falls F]
#include "tools/eval/ScrumEvaluation.h"

#include <QCoreApplication>
#include <QStringList>
#include <cstdio>
#include <numbers>

using namespace athlos;
using namespace athlos::activity;

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    auto option = [&](const char* name, double fallback) {
        const int i = int(args.indexOf(QLatin1String(name)));
        return i >= 0 && i + 1 < args.size() ? args[i + 1].toDouble() : fallback;
    };
    const int seeds = int(option("--seeds", 10));
    RugbySimulator::Params sp;
    sp.duration = option("--duration", 600.0);
    sp.scrums = int(option("--scrums", 4));
    sp.tackles = int(option("--tackles", 8));
    sp.contacts = int(option("--contacts", 8));
    sp.falls = int(option("--falls", 4));
    const TorsoPitch::Params pitch;
    const ScrumDetector::Params detector;
    constexpr double deg = 180.0 / std::numbers::pi;
    std::printf(
        "seed  scrums found detections correct  pitchRMSE  (running)  minTopInScrum  maxTopOutside  "
        "|dStart|  |dEnd|\n");
    int scrums = 0, found = 0, detections = 0, correct = 0;
    double rmse = 0.0, rmseRun = 0.0, minIn = 1e9, maxOut = 0.0;
    for (int s = 1; s <= seeds; ++s) {
        sp.seed = std::uint64_t(s);
        const auto sim = RugbySimulator::simulate(sp);
        const ScrumScore r = evaluateScrums(sim, pitch, detector);
        std::printf("%4d  %6d %5d %10d %7d  %7.2f°  %7.2f°  %12.1f°  %12.1f°  %6.2f s  %5.2f s\n", s, r.scrums, r.found,
                    r.detections, r.correct, r.pitchRmse * deg, r.pitchRmseRunning * deg, r.minTopInScrum * deg,
                    r.maxTopOutside * deg, r.startError, r.endError);
        scrums += r.scrums, found += r.found, detections += r.detections, correct += r.correct;
        rmse += r.pitchRmse / seeds, rmseRun += r.pitchRmseRunning / seeds;
        minIn = std::min(minIn, r.minTopInScrum), maxOut = std::max(maxOut, r.maxTopOutside);
    }
    std::printf(
        "all   scrums %d, recall %.1f %% (%d/%d), precision %.1f %% (%d/%d), torso pitch RMSE %.2f° "
        "(running %.2f°), top-6 mean: ≥ %.1f° in scrums, ≤ %.1f° elsewhere, threshold %.1f°\n",
        scrums, 100.0 * found / std::max(scrums, 1), found, scrums, 100.0 * correct / std::max(detections, 1), correct,
        detections, rmse * deg, rmseRun * deg, minIn * deg, maxOut * deg, detector.threshold * deg);
    return found == scrums && correct == detections ? 0 : 1;
}
