#include "tools/eval/TackleEvaluation.h"

#include "plugins/activity/Classifier.h"
#include "plugins/activity/EventDetectors.h"
#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/InteractionFeatures.h"
#include "plugins/activity/RugbySimulator.h"
#include "plugins/activity/TorsoPitch.h"

#include "core/processing/OutputStreams.h"

#include <algorithm>
#include <cmath>

namespace athlos::activity {

namespace {
struct Candidate {
    bool train = false, tackle = false;
    std::vector<float> imu;
    std::vector<double> interaction;
};

StreamInfo imuInfo() {
    StreamInfo info;
    info.name = info.kind = QStringLiteral("imu");
    info.columns = columnsOf(RugbySimulator::imuColumns(),
                             {QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2"),
                              QStringLiteral("rad/s"), QStringLiteral("rad/s"), QStringLiteral("rad/s")});
    return info;
}

// The annotated tackles of one player: [t − 1, t + 1] around the collisions he is part of.
Annotations tacklesOf(const RugbySimulator::Result& sim, int player) {
    Annotations out;
    for (const auto& k : sim.tackles)
        if (k.carrier == player || k.tackler == player) {
            Annotation a;
            a.label = QStringLiteral("tackle");
            a.tStart = k.t - 1.0;
            a.tEnd = k.t + 1.0;
            out.push_back(a);
        }
    return out;
}
}  // namespace

TackleComparison compareTackleFeatures(int trainMatches, int testMatches, double duration, int trees) {
    TackleComparison out;
    const StreamInfo info = imuInfo();
    const InteractionFeatures::Params ip;
    TackleDetector::Params dp;
    std::vector<RugbySimulator::Result> sims;
    for (int m = 0; m < trainMatches + testMatches; ++m) {
        RugbySimulator::Params sp;
        sp.seed = std::uint64_t(100 + m);
        sp.duration = duration;
        sims.push_back(RugbySimulator::simulate(sp));
    }
    // Threshold: every tackle of the training matches detected (seed 000 §5.1.2).
    std::vector<double> peaks;
    for (int m = 0; m < trainMatches; ++m)
        for (int p = 0; p < RugbySimulator::kPlayers; ++p) {
            const auto& imu = sims[std::size_t(m)].tracks[std::size_t(p)].imu;
            auto signal = TackleDetector::signal(info, imu, dp);
            if (!signal) return out;
            for (double v : TackleDetector::annotationPeaks(imu, *signal, tacklesOf(sims[std::size_t(m)], p)))
                peaks.push_back(v);
        }
    auto threshold = TackleDetector::fitThreshold(peaks, dp);
    if (!threshold) return out;
    dp.threshold = out.threshold = *threshold;

    std::vector<Candidate> candidates;
    for (int m = 0; m < trainMatches + testMatches; ++m) {
        const auto& sim = sims[std::size_t(m)];
        const bool train = m < trainMatches;
        std::vector<InteractionFeatures::Athlete> athletes;
        for (std::size_t p = 0; p < sim.tracks.size(); ++p) {
            const auto& track = sim.tracks[p];
            auto pitch = TorsoPitch::compute(info, track.imu, TorsoPitch::Params{});
            if (!pitch) return out;
            athletes.push_back({sim.players[p].team, sim.tPosition, track.x, track.y, track.imu.t, std::move(*pitch)});
        }
        for (int p = 0; p < RugbySimulator::kPlayers; ++p) {
            const auto& imu = sim.tracks[std::size_t(p)].imu;
            auto events = TackleDetector::detect(info, imu, dp);
            if (!events) return out;
            auto extractor = FeatureExtractor::create(info, {QStringLiteral("acc"), QStringLiteral("gyr")});
            if (!extractor) return out;
            const Annotations mine = tacklesOf(sim, p);
            if (!train) {
                out.testPlayerTackles += int(mine.size());
                for (const Annotation& a : mine)
                    out.testFound += std::any_of(events->begin(), events->end(), [&](const DetectedEvent& e) {
                        return e.t >= a.tStart && e.t <= a.tEnd;
                    });
            }
            for (const DetectedEvent& e : *events) {
                const auto begin = std::lower_bound(imu.t.begin(), imu.t.end(), e.t - 0.5 * ip.window);
                const auto end = std::upper_bound(imu.t.begin(), imu.t.end(), e.t + 0.5 * ip.window);
                Candidate c;
                c.train = train;
                c.tackle = std::any_of(mine.begin(), mine.end(),
                                       [&](const Annotation& a) { return e.t >= a.tStart && e.t <= a.tEnd; });
                c.imu.resize(std::size_t(extractor->size()));
                extractor->compute(imu, std::size_t(begin - imu.t.begin()), std::size_t(end - imu.t.begin()),
                                   c.imu.data());
                c.interaction = InteractionFeatures::compute(athletes, p, e.t, ip);
                candidates.push_back(std::move(c));
            }
        }
    }
    for (const Candidate& c : candidates) {
        if (c.train) {
            ++out.trainCandidates;
            out.trainTackles += c.tackle;
        } else {
            ++out.testCandidates;
            out.testPositives += c.tackle;
        }
    }

    // The IMU features: all of FeatureExtractor's, or the thesis's statistics (mean, SD, skewness,
    // kurtosis of each acc and gyr axis, §5.1.2).
    auto extractor = FeatureExtractor::create(info, {QStringLiteral("acc"), QStringLiteral("gyr")});
    if (!extractor) return out;
    std::vector<int> all, thesis;
    for (int j = 0; j < extractor->size(); ++j) {
        all.push_back(j);
        const QString& name = extractor->names()[j];
        for (const char* sensor : {"acc_", "gyr_"})
            for (const char* axis : {"x.", "y.", "z."})
                for (const char* stat : {"mean", "sd", "skewness", "kurtosis"})
                    if (name == QLatin1String(sensor) + QLatin1String(axis) + QLatin1String(stat)) thesis.push_back(j);
    }
    const int nInteraction = int(InteractionFeatures::names(ip).size());
    struct Set {
        const char* name;
        const std::vector<int>* imu;
        bool interaction;
    };
    const std::vector<int> none;
    for (const Set& set : {Set{"IMU (all)", &all, false}, Set{"IMU (all) + interaction", &all, true},
                           Set{"IMU (thesis)", &thesis, false}, Set{"IMU (thesis) + interaction", &thesis, true},
                           Set{"interaction only", &none, true}}) {
        const int cols = int(set.imu->size()) + (set.interaction ? nInteraction : 0);
        auto matrix = [&](bool train, std::vector<int>& labels) {
            cv::Mat x(0, cols, CV_32F);
            for (const Candidate& c : candidates) {
                if (c.train != train) continue;
                cv::Mat row(1, cols, CV_32F);
                int j = 0;
                for (int k : *set.imu) {
                    const float v = c.imu[std::size_t(k)];
                    row.at<float>(0, j++) = std::isfinite(v) ? v : 0.0f;
                }
                if (set.interaction)
                    for (double v : c.interaction) row.at<float>(0, j++) = std::isfinite(v) ? float(v) : 0.0f;
                x.push_back(row);
                labels.push_back(c.tackle ? 1 : 0);
            }
            return x;
        };
        std::vector<int> yTrain, yTest;
        const cv::Mat xTrain = matrix(true, yTrain), xTest = matrix(false, yTest);
        ClassifierOptions options;
        options.trees = trees;
        auto classifier = Classifier::train(xTrain, yTrain, 2, options);
        if (!classifier) return out;
        cv::Mat prob;
        classifier->probabilities(xTest, prob);
        int tp = 0, fn = 0, tn = 0, fp = 0;
        for (int i = 0; i < prob.rows; ++i) {
            const bool predicted = prob.at<float>(i, 1) > prob.at<float>(i, 0);
            if (yTest[std::size_t(i)])
                predicted ? ++tp : ++fn;
            else
                predicted ? ++fp : ++tn;
        }
        TackleComparison::Row row;
        row.features = QString::fromLatin1(set.name);
        row.featureCount = cols;
        row.sensitivity = double(tp) / std::max(tp + fn, 1);
        row.specificity = double(tn) / std::max(tn + fp, 1);
        row.balancedAccuracy = 0.5 * (row.sensitivity + row.specificity);
        out.rows.push_back(row);
    }
    return out;
}

}  // namespace athlos::activity
