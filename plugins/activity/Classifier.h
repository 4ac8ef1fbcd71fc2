#pragma once
// The window classifiers of the activity family, all through OpenCV ml (seed 000 §5.3, Table 5.2):
// random forest (default), SVM (RBF kernel, parameters by trainAuto's cross-validated grid search),
// boosted trees (one-vs-rest: OpenCV's Boost is binary), kNN, normal Bayes, decision tree, MLP,
// logistic regression and a weighted vote of several of them. Serialized as cv::FileStorage text
// (YAML) only: a stored model is data that OpenCV parses, never code.
#include "core/util/Expected.h"
#include "core/util/Progress.h"

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
    // With balance: the added minority rows are SMOTE samples (Chawla et al. 2002: a random point on the
    // segment from a minority window to one of its `smoteNeighbours` nearest windows of the same class,
    // in the scaled feature space) instead of repeated windows.
    bool smote = false;
    int smoteNeighbours = 5;  // k of SMOTE (Chawla et al. 2002 use 5)
    QStringList voteMembers{QStringLiteral("random-forest"), QStringLiteral("svm"), QStringLiteral("knn")};
    std::vector<double> voteWeights;  // empty: equal weights
    unsigned seed = 1;
    // Random forest as parallel sub-forests (ParallelForest.h): trees per part, rows a part trains on at
    // most (stratified subsample; 0: all), worker threads (0: one per core; the forest does not depend on it).
    int forestTreesPerPart = 10;
    int forestMaxRows = 15000;
    int threads = 0;
};

// SMOTE (Chawla, Bowyer, Hall & Kegelmeyer, JAIR 16:321, 2002): `count` synthetic rows of the class
// whose rows in `samples` are `members`, each x_i + u (x_nn − x_i) with x_i a random member, x_nn one
// of its k nearest members (cv::flann k-d tree, Euclidean) and u ~ U(0, 1). A class with one member
// gets copies of it.
cv::Mat smoteSamples(const cv::Mat& samples, const std::vector<int>& members, int count, int neighbours, unsigned seed);

class Classifier {
public:
    static QStringList kinds();

    // samples: N × F CV_32F (scaled features); labels: class index 0..classCount−1 per row.
    // progress: the random forest's parts report and stop on cancel (the other classifiers only at the end).
    static Expected<Classifier> train(const cv::Mat& samples, const std::vector<int>& labels, int classCount,
                                      const ClassifierOptions& options, const Progress& progress = {});
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
    // one; one per class (boosted trees); one per part (random forest: models stored before the parts
    // have one RTrees with every tree)
    std::vector<cv::Ptr<cv::ml::StatModel>> models_;
    std::vector<Classifier> members_;  // vote
    std::vector<double> weights_;
    int neighbours_ = 7;
    cv::Mat knnSamples_, knnResponses_;  // kNN: its training windows (scaled) and classes
};

}  // namespace athlos::activity
