#include "plugins/activity/Classifier.h"

#include "plugins/activity/ParallelForest.h"

#include <opencv2/flann.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace athlos::activity {

namespace {
using namespace cv::ml;

// Row indices with every class resampled to one size: the largest class's, but at most 2N/K (so a
// dominant class does not multiply the training set): smaller classes are oversampled (drawn with
// replacement), larger ones subsampled.
std::vector<int> balancedRows(const std::vector<int>& labels, int classCount, unsigned seed) {
    std::vector<std::vector<int>> byClass(std::size_t(std::max(classCount, 1)));
    for (std::size_t i = 0; i < labels.size(); ++i) byClass[std::size_t(labels[i])].push_back(int(i));
    std::size_t largest = 0, present = 0;
    for (const auto& rows : byClass) {
        largest = std::max(largest, rows.size());
        present += !rows.empty();
    }
    largest = std::min(largest, std::max<std::size_t>(1, 2 * labels.size() / std::max<std::size_t>(present, 1)));
    std::mt19937 rng(seed);
    std::vector<int> rows;
    for (auto members : byClass) {
        if (members.empty()) continue;
        if (members.size() > largest) {
            std::shuffle(members.begin(), members.end(), rng);
            members.resize(largest);
        }
        rows.insert(rows.end(), members.begin(), members.end());
        std::uniform_int_distribution<std::size_t> pick(0, members.size() - 1);
        for (std::size_t k = members.size(); k < largest; ++k) rows.push_back(members[pick(rng)]);
    }
    return rows;
}

cv::Mat selectRows(const cv::Mat& samples, const std::vector<int>& rows) {
    cv::Mat out(int(rows.size()), samples.cols, samples.type());
    for (std::size_t i = 0; i < rows.size(); ++i) samples.row(rows[i]).copyTo(out.row(int(i)));
    return out;
}

}  // namespace

cv::Mat smoteSamples(const cv::Mat& samples, const std::vector<int>& members, int count, int neighbours,
                     unsigned seed) {
    cv::Mat out(std::max(count, 0), samples.cols, CV_32F);
    if (count <= 0 || members.empty()) return out;
    const cv::Mat own = selectRows(samples, members);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pickMember(0, members.size() - 1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int k = std::min(neighbours, int(members.size()) - 1);
    if (k < 1) {
        for (int i = 0; i < count; ++i) own.row(0).copyTo(out.row(i));
        return out;
    }
    cv::flann::Index index(own, cv::flann::KDTreeIndexParams(4));
    cv::Mat indices, distances;
    index.knnSearch(own, indices, distances, k + 1, cv::flann::SearchParams(64));  // k + 1: itself first
    std::uniform_int_distribution<int> pickNeighbour(1, k);
    for (int i = 0; i < count; ++i) {
        const int a = int(pickMember(rng));
        int b = indices.at<int>(a, pickNeighbour(rng));
        if (b < 0 || b >= own.rows || b == a) b = indices.at<int>(a, 1) >= 0 ? indices.at<int>(a, 1) : a;
        const float t = u(rng);
        cv::Mat row = out.row(i);
        cv::addWeighted(own.row(a), 1.0 - t, own.row(b), t, 0.0, row);
    }
    return out;
}

namespace {

// Class-balanced training set like balancedRows, with the missing rows of each smaller class made by SMOTE.
void smoteBalanced(const cv::Mat& samples, const std::vector<int>& labels, int classCount,
                   const ClassifierOptions& options, cv::Mat& x, cv::Mat& y) {
    std::vector<std::vector<int>> byClass(std::size_t(std::max(classCount, 1)));
    for (std::size_t i = 0; i < labels.size(); ++i) byClass[std::size_t(labels[i])].push_back(int(i));
    std::size_t largest = 0, present = 0;
    for (const auto& rows : byClass) {
        largest = std::max(largest, rows.size());
        present += !rows.empty();
    }
    largest = std::min(largest, std::max<std::size_t>(1, 2 * labels.size() / std::max<std::size_t>(present, 1)));
    std::mt19937 rng(options.seed);
    std::vector<cv::Mat> parts;
    std::vector<int> classOf;
    for (std::size_t c = 0; c < byClass.size(); ++c) {
        auto members = byClass[c];
        if (members.empty()) continue;
        if (members.size() > largest) {
            std::shuffle(members.begin(), members.end(), rng);
            members.resize(largest);
        }
        parts.push_back(selectRows(samples, members));
        if (members.size() < largest)
            parts.push_back(smoteSamples(samples, members, int(largest - members.size()), options.smoteNeighbours,
                                         options.seed + unsigned(c)));
        classOf.insert(classOf.end(), largest, int(c));
    }
    cv::vconcat(parts, x);
    y = cv::Mat(int(classOf.size()), 1, CV_32S);
    for (std::size_t i = 0; i < classOf.size(); ++i) y.at<int>(int(i)) = classOf[i];
}

cv::Mat labelColumn(const std::vector<int>& labels, const std::vector<int>& rows) {
    cv::Mat out(int(rows.size()), 1, CV_32S);
    for (std::size_t i = 0; i < rows.size(); ++i) out.at<int>(int(i)) = labels[std::size_t(rows[i])];
    return out;
}

cv::Ptr<StatModel> makeModel(const QString& kind, const ClassifierOptions& o, int samples) {
    if (kind == QLatin1String("decision-tree")) {
        auto m = DTrees::create();
        m->setMaxDepth(o.maxDepth);
        m->setMinSampleCount(5);
        m->setCVFolds(0);
        return m;
    }
    if (kind == QLatin1String("boosted-trees")) {
        auto m = Boost::create();
        m->setBoostType(Boost::REAL);
        m->setWeakCount(std::max(10, o.trees / 2));
        m->setMaxDepth(3);
        return m;
    }
    if (kind == QLatin1String("svm")) {
        auto m = SVM::create();
        m->setType(SVM::C_SVC);
        m->setKernel(SVM::RBF);
        return m;
    }
    if (kind == QLatin1String("knn")) {
        auto m = KNearest::create();
        m->setDefaultK(o.neighbours);
        m->setIsClassifier(true);
        return m;
    }
    if (kind == QLatin1String("normal-bayes")) return NormalBayesClassifier::create();
    if (kind == QLatin1String("mlp")) {
        auto m = ANN_MLP::create();
        return m;
    }
    if (kind == QLatin1String("logistic-regression")) {
        auto m = LogisticRegression::create();
        m->setLearningRate(0.1);
        m->setIterations(std::clamp(200000 / std::max(samples, 1), 100, 1000));
        m->setRegularization(LogisticRegression::REG_L2);
        m->setTrainMethod(LogisticRegression::MINI_BATCH);
        m->setMiniBatchSize(64);
        return m;
    }
    return {};
}

cv::Ptr<StatModel> readModel(const QString& kind, const cv::FileNode& node) {
    cv::Ptr<StatModel> m;
    if (kind == QLatin1String("random-forest")) m = RTrees::create();
    if (kind == QLatin1String("decision-tree")) m = DTrees::create();
    if (kind == QLatin1String("boosted-trees")) m = Boost::create();
    if (kind == QLatin1String("svm")) m = SVM::create();
    if (kind == QLatin1String("knn")) m = KNearest::create();
    if (kind == QLatin1String("normal-bayes")) m = NormalBayesClassifier::create();
    if (kind == QLatin1String("mlp")) m = ANN_MLP::create();
    if (kind == QLatin1String("logistic-regression")) m = LogisticRegression::create();
    if (!m) return {};
    m->read(node);
    return m->isTrained() ? m : cv::Ptr<StatModel>();
}

void oneHot(const cv::Mat& predicted, int classCount, cv::Mat& out) {
    out = cv::Mat::zeros(predicted.rows, classCount, CV_32F);
    for (int i = 0; i < predicted.rows; ++i) {
        const int c = cvRound(predicted.at<float>(i));
        if (c >= 0 && c < classCount) out.at<float>(i, c) = 1.0f;
    }
}

void normaliseRows(cv::Mat& p) {
    for (int i = 0; i < p.rows; ++i) {
        float* row = p.ptr<float>(i);
        float sum = 0;
        for (int c = 0; c < p.cols; ++c) sum += row[c] = std::max(row[c], 0.0f);
        if (sum > 0)
            for (int c = 0; c < p.cols; ++c) row[c] /= sum;
        else
            for (int c = 0; c < p.cols; ++c) row[c] = 1.0f / float(p.cols);
    }
}
}  // namespace

QStringList Classifier::kinds() {
    return {QStringLiteral("random-forest"), QStringLiteral("svm"),
            QStringLiteral("boosted-trees"), QStringLiteral("knn"),
            QStringLiteral("normal-bayes"),  QStringLiteral("decision-tree"),
            QStringLiteral("mlp"),           QStringLiteral("logistic-regression"),
            QStringLiteral("vote")};
}

Expected<Classifier> Classifier::train(const cv::Mat& samples, const std::vector<int>& labels, int classCount,
                                       const ClassifierOptions& options, const Progress& progress) {
    Classifier c;
    c.kind_ = options.kind;
    c.classCount_ = classCount;
    c.neighbours_ = options.neighbours;
    if (!kinds().contains(options.kind))
        return makeError(QStringLiteral("classifier: unknown classifier '%1' (use %2)")
                             .arg(options.kind, kinds().join(QStringLiteral(", "))));
    if (samples.rows == 0 || samples.rows != int(labels.size()))
        return makeError(QStringLiteral("no labelled windows to train on"));
    if (classCount < 2) return makeError(QStringLiteral("training needs at least two classes"));
    try {
        if (options.kind == QLatin1String("vote")) {
            for (qsizetype i = 0; i < options.voteMembers.size(); ++i) {
                ClassifierOptions member = options;
                member.kind = options.voteMembers[i];
                if (member.kind == QLatin1String("vote")) return makeError(QStringLiteral("a vote cannot hold a vote"));
                auto trained = train(samples, labels, classCount, member, progress);
                if (!trained) return trained.error();
                c.members_.push_back(std::move(*trained));
                c.weights_.push_back(std::size_t(i) < options.voteWeights.size() ? options.voteWeights[std::size_t(i)]
                                                                                 : 1.0);
            }
            return c;
        }
        std::vector<int> rows(labels.size());
        std::iota(rows.begin(), rows.end(), 0);
        if (options.balance) rows = balancedRows(labels, classCount, options.seed);
        cv::Mat x, y;
        if (options.balance && options.smote) {
            smoteBalanced(samples, labels, classCount, options, x, y);
        } else {
            x = selectRows(samples, rows);
            y = labelColumn(labels, rows);
        }
        cv::theRNG().state = options.seed;
        if (options.kind == QLatin1String("random-forest")) {
            ParallelForest::Params params;
            params.trees = options.trees;
            params.maxDepth = options.maxDepth;
            params.treesPerPart = options.forestTreesPerPart;
            params.maxRows = options.forestMaxRows;
            params.seed = options.seed;
            params.threads = options.threads;
            auto parts =
                ParallelForest::train(x, std::vector<int>(y.begin<int>(), y.end<int>()), classCount, params, progress);
            if (!parts) return parts.error();
            for (auto& part : *parts) c.models_.push_back(part);
            return c;
        }
        if (options.kind == QLatin1String("boosted-trees")) {
            for (int k = 0; k < classCount; ++k) {
                cv::Mat binary(y.rows, 1, CV_32S);
                for (int i = 0; i < y.rows; ++i) binary.at<int>(i) = y.at<int>(i) == k ? 1 : 0;
                auto m = makeModel(options.kind, options, x.rows);
                m->train(TrainData::create(x, ROW_SAMPLE, binary));
                c.models_.push_back(m);
            }
            return c;
        }
        auto model = makeModel(options.kind, options, x.rows);
        if (options.kind == QLatin1String("svm")) {
            // Grid search (C, gamma) by 3-fold cross-validation on at most 1000 windows, then the
            // chosen parameters on all of them (trainAuto on everything is quadratic and slow).
            auto svm = model.dynamicCast<SVM>();
            std::vector<int> subset(std::size_t(x.rows));
            std::iota(subset.begin(), subset.end(), 0);
            std::shuffle(subset.begin(), subset.end(), std::mt19937(options.seed));
            subset.resize(std::min<std::size_t>(subset.size(), 1000));
            svm->trainAuto(TrainData::create(selectRows(x, subset), ROW_SAMPLE, labelColumn(y, subset)), 3);
            svm->train(TrainData::create(x, ROW_SAMPLE, y));
        } else if (options.kind == QLatin1String("mlp")) {
            auto mlp = model.dynamicCast<ANN_MLP>();
            const int hidden = std::clamp(x.cols / 2, 16, 64);
            mlp->setLayerSizes(std::vector<int>{x.cols, hidden, classCount});
            mlp->setActivationFunction(ANN_MLP::SIGMOID_SYM, 1, 1);
            mlp->setTrainMethod(ANN_MLP::RPROP);
            mlp->setTermCriteria({cv::TermCriteria::MAX_ITER | cv::TermCriteria::EPS, 300, 1e-4});
            cv::Mat targets = cv::Mat::zeros(y.rows, classCount, CV_32F);
            for (int i = 0; i < y.rows; ++i) targets.at<float>(i, y.at<int>(i)) = 1.0f;
            mlp->train(TrainData::create(x, ROW_SAMPLE, targets));
        } else if (options.kind == QLatin1String("logistic-regression")) {
            cv::Mat yf;
            y.convertTo(yf, CV_32F);
            model->train(TrainData::create(x, ROW_SAMPLE, yf));
        } else {
            model->train(TrainData::create(x, ROW_SAMPLE, y));
            if (options.kind == QLatin1String("knn")) {
                c.knnSamples_ = x;
                c.knnResponses_ = y;
            }
        }
        if (!model->isTrained()) return makeError(QStringLiteral("classifier '%1' did not train").arg(options.kind));
        c.models_.push_back(model);
        return c;
    } catch (const cv::Exception& e) {
        return makeError(QStringLiteral("classifier '%1': OpenCV refused the training data: %2")
                             .arg(options.kind, QString::fromStdString(e.err)));
    }
}

void Classifier::probabilities(const cv::Mat& samples, cv::Mat& out) const {
    if (kind_ == QLatin1String("vote")) {
        out = cv::Mat::zeros(samples.rows, classCount_, CV_32F);
        cv::Mat member;
        for (std::size_t i = 0; i < members_.size(); ++i) {
            members_[i].probabilities(samples, member);
            out += member * weights_[i];
        }
        normaliseRows(out);
        return;
    }
    if (kind_ == QLatin1String("random-forest")) {
        // Fraction of the trees of all parts voting for each class.
        ParallelForest::probabilities(models_, samples, classCount_, out);
        return;
    }
    if (kind_ == QLatin1String("boosted-trees")) {
        // Softmax of the one-vs-rest real-boost scores.
        out.create(samples.rows, classCount_, CV_32F);
        cv::Mat raw;
        for (int k = 0; k < classCount_; ++k) {
            models_[std::size_t(k)]->predict(samples, raw, StatModel::RAW_OUTPUT);
            for (int i = 0; i < samples.rows; ++i) out.at<float>(i, k) = raw.at<float>(i);
        }
        for (int i = 0; i < out.rows; ++i) {
            float* row = out.ptr<float>(i);
            const float top = *std::max_element(row, row + classCount_);
            for (int k = 0; k < classCount_; ++k) row[k] = std::exp(row[k] - top);
        }
        normaliseRows(out);
        return;
    }
    if (kind_ == QLatin1String("knn")) {
        cv::Mat results, neighbours;
        models_.front().dynamicCast<KNearest>()->findNearest(samples, neighbours_, results, neighbours);
        out = cv::Mat::zeros(samples.rows, classCount_, CV_32F);
        for (int i = 0; i < neighbours.rows; ++i)
            for (int j = 0; j < neighbours.cols; ++j) {
                const int c = cvRound(neighbours.at<float>(i, j));
                if (c >= 0 && c < classCount_) out.at<float>(i, c) += 1.0f;
            }
        normaliseRows(out);
        return;
    }
    if (kind_ == QLatin1String("mlp")) {
        models_.front()->predict(samples, out);
        normaliseRows(out);
        return;
    }
    cv::Mat predicted;
    models_.front()->predict(samples, predicted);
    if (predicted.type() != CV_32F) predicted.convertTo(predicted, CV_32F);
    oneHot(predicted.reshape(1, samples.rows), classCount_, out);
}

void Classifier::write(cv::FileStorage& fs) const {
    fs << "kind" << kind_.toStdString();
    fs << "class_count" << classCount_;
    fs << "neighbours" << neighbours_;
    if (kind_ == QLatin1String("vote")) {
        fs << "members"
           << "[";
        for (std::size_t i = 0; i < members_.size(); ++i) {
            fs << "{"
               << "weight" << weights_[i];
            members_[i].write(fs);
            fs << "}";
        }
        fs << "]";
        return;
    }
    fs << "models"
       << "[";
    for (const auto& m : models_) {
        fs << "{";
        if (kind_ == QLatin1String("knn")) {
            // kNN is its training windows; stored as two matrices and rebuilt on reading (OpenCV
            // 4.6 cannot read its own KNearest YAML back from memory).
            fs << "samples" << knnSamples_ << "responses" << knnResponses_;
        } else {
            m->write(fs);
        }
        fs << "}";
    }
    fs << "]";
}

Expected<Classifier> Classifier::read(const cv::FileNode& node, int classCount) {
    Classifier c;
    try {
        c.kind_ = QString::fromStdString(static_cast<std::string>(node["kind"]));
        c.classCount_ = static_cast<int>(node["class_count"]);
        c.neighbours_ = std::clamp(static_cast<int>(node["neighbours"]), 1, 1000);
        if (!kinds().contains(c.kind_)) return makeError(QStringLiteral("unknown classifier '%1'").arg(c.kind_));
        if (c.classCount_ != classCount)
            return makeError(
                QStringLiteral("the classifier has %1 classes, the model lists %2").arg(c.classCount_).arg(classCount));
        if (c.kind_ == QLatin1String("vote")) {
            for (const cv::FileNode& member : node["members"]) {
                auto m = read(member, classCount);
                if (!m) return m.error();
                c.members_.push_back(std::move(*m));
                c.weights_.push_back(static_cast<double>(member["weight"]));
            }
            if (c.members_.empty()) return makeError(QStringLiteral("a vote without members"));
            return c;
        }
        for (const cv::FileNode& m : node["models"]) {
            if (c.kind_ == QLatin1String("knn")) {
                m["samples"] >> c.knnSamples_;
                m["responses"] >> c.knnResponses_;
                if (c.knnSamples_.empty() || c.knnSamples_.type() != CV_32F || c.knnResponses_.type() != CV_32S ||
                    c.knnResponses_.total() != std::size_t(c.knnSamples_.rows))
                    return makeError(QStringLiteral("the knn model does not hold its windows and classes"));
                auto knn = KNearest::create();
                knn->setDefaultK(c.neighbours_);
                knn->setIsClassifier(true);
                knn->train(TrainData::create(c.knnSamples_, ROW_SAMPLE, c.knnResponses_));
                c.models_.push_back(knn);
                continue;
            }
            auto model = readModel(c.kind_, m);
            if (!model) return makeError(QStringLiteral("the %1 model is not a trained OpenCV model").arg(c.kind_));
            c.models_.push_back(model);
        }
        const std::size_t expected = c.kind_ == QLatin1String("boosted-trees") ? std::size_t(classCount) : 1;
        const bool forest = c.kind_ == QLatin1String("random-forest");  // one part or more
        if (forest ? c.models_.empty() : c.models_.size() != expected)
            return makeError(QStringLiteral("the %1 model has %2 parts, expected %3")
                                 .arg(c.kind_)
                                 .arg(c.models_.size())
                                 .arg(expected));
        return c;
    } catch (const cv::Exception& e) {
        return makeError(QStringLiteral("cannot read the classifier: %1").arg(QString::fromStdString(e.err)));
    }
}

}  // namespace athlos::activity
