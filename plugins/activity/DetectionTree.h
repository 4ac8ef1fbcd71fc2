#pragma once
// The impact detector's second stage (seed 000 §5.2, digest §8): a decision tree on the two detection
// features of each candidate — the impact indicator (the detector signal at the peak) and the swing
// indicator (mean |a| over the 200 ms before it) — that tells relevant actions (classes 1–9) from the
// Null class, trained cost-sensitively so that few relevant actions are lost: a missed action cannot
// be recovered later, a false alarm is corrected by the classifier that follows.
//
// The thesis trains a C4.5 tree with MetaCost (Domingos 1999) and picks the FN:FP cost ratio in a
// leave-one-subject-out grid search as the one reaching 99 % recall (it found 150). Here likewise, with
// OpenCV's trees (CART, Gini impurity, instead of C4.5's gain ratio): MetaCost estimates each training
// candidate's class probabilities with a bagged ensemble of trees, relabels it with the class of least
// expected cost (a missed action costs `costRatio` false alarms) and trains one tree on the relabelled
// candidates. The grid search is the thesis's: for each ratio, ascending, the relevant candidates'
// recall with each subject left out in turn; the smallest ratio whose pooled recall reaches the target
// is used for the tree trained on every subject.
#include "core/util/Expected.h"

#include <QJsonObject>
#include <opencv2/ml.hpp>
#include <vector>

namespace athlos::activity {

class DetectionTree {
public:
    struct Params {
        double targetRecall = 0.99;  // §5.2: "designed … to reach a recall of 99 %"
        // FN:FP cost ratios searched, ascending (§5.2: 150 was chosen on the thesis's data).
        std::vector<double> costRatios{1, 2, 5, 10, 20, 50, 100, 150, 200, 500, 1000};
        int maxDepth = 4;        // a few threshold comparisons, small enough for the sensor's MCU (§5.2)
        int minSampleCount = 5;  // candidates a node needs to be split
        int folds = 10;          // subjects dealt into at most this many folds in the grid search
        int bagSize = 30;        // MetaCost: bagged trees estimating each candidate's class probabilities
    };
    struct Sample {
        double impact = 0;  // m/s², impact indicator
        double swing = 0;   // m/s², swing indicator
        bool relevant = false;
        int group = 0;  // subject (athlete) the candidate comes from
    };
    // The outcome of the grid search.
    struct Fit {
        double costRatio = 0;         // chosen FN:FP ratio
        double recall = 0;            // relevant candidates kept, left-out subjects, at that ratio
        double nullRejected = 0;      // Null candidates dropped, left-out subjects, at that ratio
        int relevant = 0, nulls = 0;  // candidates trained on
        int groups = 0;               // subjects in the grid search
        bool targetReached = false;   // false: even the largest ratio stays below the target (no tree)
    };

    // Grid search and the final tree. Fails without relevant candidates. Without Null candidates there
    // is nothing to learn, and when no cost ratio reaches the target recall a tree would drop too many
    // actions: in both cases the result keeps every candidate (fit().targetReached tells which).
    static Expected<DetectionTree> train(const std::vector<Sample>& samples, const Params& params);

    bool keep(double impact, double swing) const;
    const Fit& fit() const { return fit_; }
    // One line, as `athlos train` and the Train classifier wizard show it.
    QString summary() const;

    QJsonObject toJson() const;
    // The error names what is wrong; nothing in it is executed (the tree is data read by OpenCV).
    static Expected<DetectionTree> fromJson(const QJsonObject& json);

private:
    static cv::Ptr<cv::ml::DTrees> trainTree(const std::vector<Sample>& samples, const std::vector<std::size_t>& rows,
                                             double costRatio, const Params& params);
    cv::Ptr<cv::ml::DTrees> tree_;  // null: keep everything (no Null candidates to learn from)
    Fit fit_;
};

}  // namespace athlos::activity
