#pragma once
// Mutual-information feature ranking and selection (issue #14 item 2; seed 000 §5.2: a filter approach,
// the features ranked by their MI with the class labels [Peng 05], the best N_feat used). I(X_j; C) between each feature and the class is the plug-in estimate (Cover &
// Thomas, Elements of Information Theory, eq. 2.28) after equal-frequency discretisation of the feature
// into `bins` bins (Dougherty, Kohavi & Sahami, ICML 1995; Battiti, IEEE TNN 5(4), 1994 ranks features
// by I(X; C) this way): invariant to monotone rescaling of the feature, so it can run on unscaled
// features. Tied values fall into one bin (the bin of their first rank), so a feature that equals the
// class gets I = H(C) exactly. The plug-in estimate of an independent feature is biased upwards by
// about (bins − 1)(K − 1) / (2 N ln 2) bits (Miller 1955).
#include "core/util/Expected.h"

#include <opencv2/core.hpp>

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <vector>

namespace athlos::activity {

// I(X_j; C) in bits for every column j of samples (N × F, CV_32F); labels: class 0..classCount−1 per row.
std::vector<double> mutualInformation(const cv::Mat& samples, const std::vector<int>& labels, int classCount, int bins);

// The K features of highest mutual information with the class, in decreasing order of it.
struct FeatureSelection {
    static constexpr int kDefaultBins = 10;  // equal-frequency bins per feature (Dougherty et al. 1995: 10)

    std::vector<int> columns;  // indices into the full feature vector, by decreasing MI
    QStringList names;         // their feature names
    std::vector<double> bits;  // their MI with the class (bits)
    int bins = kDefaultBins;

    // The top `k` of `mi` (ties: the lower column first); k ≤ 0 or ≥ the feature count: every feature.
    static FeatureSelection top(const std::vector<double>& mi, int k, const QStringList& names, int bins);
    // Ranking and selection on training windows in one call.
    static FeatureSelection fit(const cv::Mat& samples, const std::vector<int>& labels, int classCount, int k,
                                const QStringList& names, int bins);
    // The selected columns of samples (N × columns.size()).
    cv::Mat apply(const cv::Mat& samples) const;
    int size() const { return int(columns.size()); }

    QJsonObject toJson() const;
    // From a model description's "feature_selection", the columns found by name among `features`.
    static Expected<FeatureSelection> fromJson(const QJsonObject& json, const QStringList& features);
    // "  1  acc_norm_sd  0.912 bits" lines of the first `count` entries.
    QString toText(int count) const;
};

}  // namespace athlos::activity
