#include "plugins/activity/ParallelForest.h"

#include <QString>
#include <QThread>
#include <QThreadPool>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <random>

namespace athlos::activity {

namespace {

std::mt19937 partRng(unsigned seed, int part) {
    std::seed_seq sequence{seed, unsigned(part), 0x5eedf0e5u};
    return std::mt19937(sequence);
}

}  // namespace

int ParallelForest::partCount(const Params& params) {
    const int perPart = std::max(params.treesPerPart, 1);
    return (std::max(params.trees, 1) + perPart - 1) / perPart;
}

std::vector<int> ParallelForest::partRows(const std::vector<int>& labels, int classCount, int part,
                                          const Params& params) {
    std::mt19937 rng = partRng(params.seed, part);
    const std::size_t n = labels.size();
    std::vector<int> rows;
    if (params.maxRows <= 0 || n <= std::size_t(params.maxRows)) {
        rows.resize(n);
        for (std::size_t i = 0; i < n; ++i) rows[i] = int(i);
    } else {
        std::vector<std::vector<int>> byClass(std::size_t(std::max(classCount, 1)));
        for (std::size_t i = 0; i < n; ++i) byClass[std::size_t(labels[i])].push_back(int(i));
        for (auto& members : byClass) {
            if (members.empty()) continue;
            const double share = double(params.maxRows) * double(members.size()) / double(n);
            const std::size_t take = std::clamp<std::size_t>(std::size_t(std::lround(share)), 1, members.size());
            // Partial Fisher-Yates: the first `take` of a uniform random permutation.
            for (std::size_t k = 0; k < take; ++k) {
                std::uniform_int_distribution<std::size_t> pick(k, members.size() - 1);
                std::swap(members[k], members[pick(rng)]);
            }
            rows.insert(rows.end(), members.begin(), members.begin() + std::ptrdiff_t(take));
        }
    }
    // The order matters: RTrees draws its bootstrap by position with a fixed RNG, so a shuffle per part
    // is what makes parts on the same rows grow different trees.
    std::shuffle(rows.begin(), rows.end(), rng);
    return rows;
}

Expected<std::vector<cv::Ptr<cv::ml::RTrees>>> ParallelForest::train(const cv::Mat& samples,
                                                                     const std::vector<int>& labels, int classCount,
                                                                     const Params& params, const Progress& progress) {
    if (samples.rows == 0 || samples.rows != int(labels.size()) || samples.type() != CV_32F)
        return makeError(QStringLiteral("random forest: no labelled windows to train on"));
    const int parts = partCount(params);
    std::vector<cv::Ptr<cv::ml::RTrees>> trained(static_cast<std::size_t>(parts));
    std::atomic_int done{0};
    std::atomic_bool stop{false};
    std::mutex errorMutex;
    QString error;

    auto trainPart = [&](int part) {
        if (stop.load() || progress.isCancelled()) return;
        try {
            const std::vector<int> rows = partRows(labels, classCount, part, params);
            cv::Mat x(int(rows.size()), samples.cols, CV_32F);
            cv::Mat y(int(rows.size()), 1, CV_32S);
            for (std::size_t i = 0; i < rows.size(); ++i) {
                samples.row(rows[i]).copyTo(x.row(int(i)));
                y.at<int>(int(i)) = labels[std::size_t(rows[i])];
            }
            const int first = part * std::max(params.treesPerPart, 1);
            const int trees = std::min(std::max(params.treesPerPart, 1), std::max(params.trees, 1) - first);
            // OpenCV ml draws from the thread's cv::theRNG() besides the forest's own RNG: set it per part,
            // so the part does not depend on the thread (or on what that thread ran before).
            cv::theRNG().state = partRng(params.seed, part)();
            auto m = cv::ml::RTrees::create();
            m->setMaxDepth(params.maxDepth);
            m->setMinSampleCount(2);
            m->setActiveVarCount(0);  // √F variables per split (Breiman's default)
            m->setCalculateVarImportance(false);
            m->setTermCriteria({cv::TermCriteria::MAX_ITER, trees, 0});
            m->train(cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, y));
            if (!m->isTrained()) throw std::runtime_error("the part did not train");
            trained[std::size_t(part)] = m;
        } catch (const cv::Exception& e) {
            std::lock_guard lock(errorMutex);
            if (error.isEmpty()) error = QString::fromStdString(e.err);
            stop.store(true);
        } catch (const std::exception& e) {
            std::lock_guard lock(errorMutex);
            if (error.isEmpty()) error = QString::fromUtf8(e.what());
            stop.store(true);
        }
        done.fetch_add(1);
    };

    const int threads = std::clamp(params.threads > 0 ? params.threads : QThread::idealThreadCount(), 1, parts);
    if (threads == 1) {
        for (int part = 0; part < parts && !stop.load() && !progress.isCancelled(); ++part) {
            trainPart(part);
            progress.report(double(done.load()) / double(parts), QStringLiteral("random forest"));
        }
    } else {
        QThreadPool pool;
        pool.setMaxThreadCount(threads);
        for (int part = 0; part < parts; ++part) pool.start([&trainPart, part] { trainPart(part); });
        // Progress and cancellation from the calling thread: the callback may not be thread-safe.
        while (!pool.waitForDone(100)) {
            progress.report(double(done.load()) / double(parts), QStringLiteral("random forest"));
            if (progress.isCancelled()) stop.store(true);
        }
    }
    if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
    if (!error.isEmpty())
        return makeError(QStringLiteral("random forest: OpenCV refused the training data: %1").arg(error));
    for (const auto& m : trained)
        if (!m) return makeError(QStringLiteral("random forest: a part did not train"));
    progress.report(1.0, QStringLiteral("random forest"));
    return trained;
}

void ParallelForest::probabilities(const std::vector<cv::Ptr<cv::ml::StatModel>>& parts, const cv::Mat& samples,
                                   int classCount, cv::Mat& out) {
    // Sum of every part's tree votes (first row of getVotes: the class labels), then divided by the
    // trees that voted: the average of the parts' vote fractions weighted by their trees.
    out = cv::Mat::zeros(samples.rows, classCount, CV_32F);
    cv::Mat votes;
    for (const auto& part : parts) {
        auto forest = part.dynamicCast<cv::ml::RTrees>();
        if (!forest) continue;
        forest->getVotes(samples, votes, 0);
        for (int j = 0; j < votes.cols; ++j) {
            const int c = votes.at<int>(0, j);
            if (c < 0 || c >= classCount) continue;
            for (int i = 0; i < samples.rows; ++i) out.at<float>(i, c) += float(votes.at<int>(i + 1, j));
        }
    }
    for (int i = 0; i < out.rows; ++i) {
        float* row = out.ptr<float>(i);
        float sum = 0;
        for (int c = 0; c < classCount; ++c) sum += row[c];
        if (sum > 0)
            for (int c = 0; c < classCount; ++c) row[c] /= sum;
        else
            for (int c = 0; c < classCount; ++c) row[c] = 1.0f / float(classCount);
    }
}

}  // namespace athlos::activity
