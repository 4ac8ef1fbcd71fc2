#pragma once
// The window classifiers of the activity family, all through OpenCV ml (seed 000 §5.3, Table 5.2):
// random forest (default), SVM (RBF kernel, parameters by trainAuto's cross-validated grid search),
// boosted trees (one-vs-rest: OpenCV's Boost is binary), kNN, normal Bayes, decision tree, MLP,
// logistic regression and a weighted vote of several of them. Serialized as cv::FileStorage text
// (YAML) only: a stored model is data that OpenCV parses, never code.
#include "core/util/Expected.h"

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include <QString>
#include <QStringList>
#include <memory>
#include <vector>

namespace athlos::activity {

struct ClassifierOptions {
    QString kind = QStringLiteral("random-forest");
    int trees = 150;      // random forest, boosted trees: number of trees (Breiman 2001: 100s suffice)
    int maxDepth = 20;    // tree depth limit
    int neighbours = 7;   // kNN
    bool balance = true;  // oversample minority classes to the size of the largest (class-balanced training)
    QStringList voteMembers{QStringLiteral("random-forest"), QStringLiteral("svm"), QStringLiteral("knn")};
    std::vector<double> voteWeights;  // empty: equal weights
    unsigned seed = 1;
};

class Classifier {
public:
    static QStringList kinds();

    // samples: N × F CV_32F (scaled features); labels: class index 0..classCount−1 per row.
    static Expected<Classifier> train(const cv::Mat& samples, const std::vector<int>& labels, int classCount,
                                      const ClassifierOptions& options);
    static Expected<Classifier> read(const cv::FileNode& node, int classCount);
    void write(cv::FileStorage& fs) const;

    // Class probabilities (rows × classCount, CV_32F, rows sum to 1; classifiers without
    // probabilities give their vote as 1).
    void probabilities(const cv::Mat& samples, cv::Mat& out) const;
    const QString& kind() const { return kind_; }
    int classCount() const { return classCount_; }

private:
    QString kind_;
    int classCount_ = 0;
    std::vector<cv::Ptr<cv::ml::StatModel>> models_;  // one, or one per class (boosted trees)
    std::vector<Classifier> members_;                 // vote
    std::vector<double> weights_;
    int neighbours_ = 7;
    cv::Mat knnSamples_, knnResponses_;  // kNN: its training windows (scaled) and classes
};

}  // namespace athlos::activity
