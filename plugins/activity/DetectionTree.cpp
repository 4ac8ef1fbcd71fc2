#include "plugins/activity/DetectionTree.h"

#include <QByteArray>
#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace athlos::activity {

namespace {
using cv::ml::DTrees;

constexpr int kNull = 0, kRelevant = 1;

cv::Mat features(double impact, double swing) {
    cv::Mat row(1, 2, CV_32F);
    row.at<float>(0, 0) = float(impact);
    row.at<float>(0, 1) = float(swing);
    return row;
}

// Fold of each sample: subjects dealt round-robin into at most `folds` folds (leave-one-subject-out
// when there are no more subjects than folds); a single subject: samples dealt round-robin.
std::vector<int> foldsOf(const std::vector<DetectionTree::Sample>& samples, int folds, int& count) {
    std::map<int, int> groupIndex;
    for (const auto& s : samples) groupIndex.emplace(s.group, 0);
    std::vector<int> out(samples.size());
    if (groupIndex.size() >= 2) {
        count = std::min<int>(folds, int(groupIndex.size()));
        int next = 0;
        for (auto& [group, index] : groupIndex) index = next++ % count;
        for (std::size_t i = 0; i < samples.size(); ++i) out[i] = groupIndex[samples[i].group];
    } else {
        count = std::min<int>(folds, std::max<int>(2, int(samples.size())));
        for (std::size_t i = 0; i < samples.size(); ++i) out[i] = int(i % std::size_t(count));
    }
    return out;
}
}  // namespace

cv::Ptr<DTrees> DetectionTree::trainTree(const std::vector<Sample>& samples, const std::vector<std::size_t>& rows,
                                         double costRatio, const Params& params) {
    int relevant = 0, nulls = 0;
    for (std::size_t r : rows) (samples[r].relevant ? relevant : nulls)++;
    // Null (keep everything): one class only, or every candidate relabelled relevant.
    if (relevant == 0 || nulls == 0) return {};
    cv::Mat x(int(rows.size()), 2, CV_32F);
    cv::Mat y(int(rows.size()), 1, CV_32S);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        x.at<float>(int(i), 0) = float(samples[rows[i]].impact);
        x.at<float>(int(i), 1) = float(samples[rows[i]].swing);
        y.at<int>(int(i)) = samples[rows[i]].relevant ? kRelevant : kNull;
    }
    // MetaCost (Domingos 1999), step 1–2: class probabilities of every training candidate from a bagged
    // ensemble of the same trees (OpenCV's RTrees with both features active at every split is plain
    // bagging), averaged over all members.
    // Bootstrap samples the same on every run; the thread's generator is given back as it was.
    const std::uint64_t callerState = cv::theRNG().state;
    cv::theRNG().state = 0x5eed;
    struct Restore {
        std::uint64_t state;
        ~Restore() { cv::theRNG().state = state; }
    } restore{callerState};
    auto bag = cv::ml::RTrees::create();
    bag->setMaxDepth(params.maxDepth);
    bag->setMinSampleCount(params.minSampleCount);
    bag->setActiveVarCount(2);
    bag->setCalculateVarImportance(false);
    bag->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, params.bagSize, 0));
    if (!bag->train(cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, y))) return {};
    cv::Mat votes;
    bag->getVotes(x, votes, 0);  // row 0: the class labels, then one row of vote counts per sample
    int relevantColumn = -1;
    for (int c = 0; c < votes.cols; ++c)
        if (votes.at<int>(0, c) == kRelevant) relevantColumn = c;
    if (relevantColumn < 0) return {};
    // Step 3: relabel each candidate with the class of least expected cost. Keeping a Null candidate
    // costs 1 (a false alarm), dropping a relevant one costRatio: relevant when P(rel|x)·costRatio >
    // P(null|x).
    cv::Mat relabelled = y.clone();
    for (int i = 0; i < x.rows; ++i) {
        double total = 0;
        for (int c = 0; c < votes.cols; ++c) total += votes.at<int>(i + 1, c);
        // Vote share with the Laplace correction (Provost & Domingos 2003): a candidate no member calls
        // relevant keeps a small probability, so a large enough cost keeps it.
        const double pRelevant = (votes.at<int>(i + 1, relevantColumn) + 1.0) / (total + 2.0);
        relabelled.at<int>(i) = pRelevant * costRatio > 1.0 - pRelevant ? kRelevant : kNull;
    }
    if (cv::countNonZero(relabelled == kNull) == 0) return {};  // everything kept: no tree needed
    // Step 4: the tree learnt from the relabelled candidates, with equal costs.
    auto tree = DTrees::create();
    tree->setMaxDepth(params.maxDepth);
    tree->setMinSampleCount(params.minSampleCount);
    tree->setCVFolds(0);
    tree->setUseSurrogates(false);
    if (!tree->train(cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, relabelled))) return {};
    return tree;
}

Expected<DetectionTree> DetectionTree::train(const std::vector<Sample>& samples, const Params& params) {
    if (!(params.targetRecall > 0 && params.targetRecall <= 1))
        return makeError(QStringLiteral("detection tree: target recall %1 is not a share above 0, at most 1")
                             .arg(params.targetRecall));
    if (params.costRatios.empty() || !std::is_sorted(params.costRatios.begin(), params.costRatios.end()) ||
        !(params.costRatios.front() > 0))
        return makeError(QStringLiteral("detection tree: the cost ratios must be positive and ascending"));
    DetectionTree t;
    for (const Sample& s : samples) {
        if (!std::isfinite(s.impact) || !std::isfinite(s.swing))
            return makeError(QStringLiteral("detection tree: a candidate has no finite impact or swing indicator"));
        (s.relevant ? t.fit_.relevant : t.fit_.nulls)++;
    }
    if (t.fit_.relevant == 0)
        return makeError(QStringLiteral("detection tree: no detected candidate lies inside an annotated action"));
    if (t.fit_.nulls == 0) {  // nothing to reject
        t.fit_.costRatio = params.costRatios.front();
        t.fit_.recall = 1.0;
        t.fit_.targetReached = true;
        return t;
    }
    int folds = 0;
    const std::vector<int> fold = foldsOf(samples, params.folds, folds);
    t.fit_.groups = folds;

    // Grid search (§5.2): the smallest cost ratio whose held-out recall reaches the target.
    bool chosen = false;
    for (double ratio : params.costRatios) {
        int kept = 0, nullsDropped = 0;
        for (int f = 0; f < folds; ++f) {
            std::vector<std::size_t> trainRows, testRows;
            for (std::size_t i = 0; i < samples.size(); ++i) (fold[i] == f ? testRows : trainRows).push_back(i);
            if (testRows.empty()) continue;
            DetectionTree foldTree;
            foldTree.tree_ = trainTree(samples, trainRows, ratio, params);
            const bool anyRelevant =
                std::any_of(trainRows.begin(), trainRows.end(), [&](std::size_t r) { return samples[r].relevant; });
            for (std::size_t r : testRows) {
                // A training fold without relevant candidates cannot tell them: it rejects nothing.
                const bool keep = !anyRelevant || foldTree.keep(samples[r].impact, samples[r].swing);
                if (samples[r].relevant)
                    kept += keep;
                else
                    nullsDropped += !keep;
            }
        }
        t.fit_.costRatio = ratio;
        t.fit_.recall = double(kept) / double(t.fit_.relevant);
        t.fit_.nullRejected = double(nullsDropped) / double(t.fit_.nulls);
        if (t.fit_.recall >= params.targetRecall - 1e-12) {
            chosen = true;
            break;
        }
    }
    t.fit_.targetReached = chosen;
    // No cost reaches the target: a tree would lose more actions than allowed, so there is none and every
    // candidate goes on to the classifier (the detector's own recall).
    if (!chosen) return t;
    std::vector<std::size_t> all(samples.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    t.tree_ = trainTree(samples, all, t.fit_.costRatio, params);  // null: every candidate relabelled relevant
    return t;
}

bool DetectionTree::keep(double impact, double swing) const {
    if (!tree_) return true;
    return int(std::lround(tree_->predict(features(impact, swing)))) == kRelevant;
}

QString DetectionTree::summary() const {
    return QStringLiteral(
               "detection tree (impact, swing): FN:FP cost %1, %2 folds by athlete: keeps %3 % of %4 "
               "annotated candidates, drops %5 % of %6 null candidates%7\n")
        .arg(fit_.costRatio)
        .arg(fit_.groups)
        .arg(100.0 * fit_.recall, 0, 'f', 1)
        .arg(fit_.relevant)
        .arg(100.0 * fit_.nullRejected, 0, 'f', 1)
        .arg(fit_.nulls)
        .arg(fit_.targetReached ? QString()
                                : QStringLiteral(" at the largest cost, below the target recall: no tree, every "
                                                 "candidate kept"));
}

QJsonObject DetectionTree::toJson() const {
    QJsonObject o{{QStringLiteral("cost_ratio"), fit_.costRatio},
                  {QStringLiteral("cv_recall"), fit_.recall},
                  {QStringLiteral("cv_null_rejected"), fit_.nullRejected},
                  {QStringLiteral("relevant"), fit_.relevant},
                  {QStringLiteral("null"), fit_.nulls},
                  {QStringLiteral("folds"), fit_.groups},
                  {QStringLiteral("target_reached"), fit_.targetReached}};
    if (tree_) {
        cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
        fs << "tree"
           << "{";
        tree_->write(fs);
        fs << "}";
        o[QStringLiteral("opencv_dtrees")] = QString::fromStdString(fs.releaseAndGetString());
    }
    return o;
}

Expected<DetectionTree> DetectionTree::fromJson(const QJsonObject& json) {
    DetectionTree t;
    t.fit_.costRatio = json.value(QStringLiteral("cost_ratio")).toDouble();
    t.fit_.recall = json.value(QStringLiteral("cv_recall")).toDouble();
    t.fit_.nullRejected = json.value(QStringLiteral("cv_null_rejected")).toDouble();
    t.fit_.relevant = json.value(QStringLiteral("relevant")).toInt();
    t.fit_.nulls = json.value(QStringLiteral("null")).toInt();
    t.fit_.groups = json.value(QStringLiteral("folds")).toInt();
    t.fit_.targetReached = json.value(QStringLiteral("target_reached")).toBool();
    const QString yaml = json.value(QStringLiteral("opencv_dtrees")).toString();
    if (yaml.isEmpty()) return t;  // trained without Null candidates: keeps everything
    try {
        cv::FileStorage fs(yaml.toStdString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
        auto tree = DTrees::create();
        tree->read(fs["tree"]);
        if (!tree->isTrained() || tree->getVarCount() != 2 || !tree->isClassifier())
            return makeError(QStringLiteral("detection tree: not a trained two-feature OpenCV classification tree"));
        t.tree_ = tree;
    } catch (const cv::Exception& e) {
        return makeError(QStringLiteral("detection tree: %1").arg(QString::fromStdString(e.err)));
    }
    return t;
}

}  // namespace athlos::activity
