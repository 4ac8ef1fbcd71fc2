#pragma once
// The random forest of the activity family as sub-forests: `trees` trees split into parts of
// `treesPerPart` OpenCV RTrees, each part trained on its own thread on its own stratified subsample
// ("subbagging", Bühlmann & Yu, Ann. Stat. 30:927, 2002; Breiman, Mach. Learn. 45:5, 2001, §2: any
// independent random draw per tree keeps the forest's guarantees) of at most `maxRows` training rows,
// and the forest's class probabilities are the votes of all trees of all parts (each part weighted by
// its trees). OpenCV's RTrees is single-threaded and seeds its own RNG with a constant, so the parts
// differ by their rows: each part's subsample and row order come from a seed of its own (the forest
// seed and the part's index), never from the thread that runs it: the same data and parameters give
// the same model with any number of threads.
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include <vector>

namespace athlos::activity {

class ParallelForest {
public:
    struct Params {
        int trees = 100;        // trees of the whole forest
        int maxDepth = 20;      // tree depth limit
        int treesPerPart = 10;  // trees per RTrees part: the unit of parallel work, cancellation and subsample
        // Rows (windows) a part trains on at most: a stratified subsample (every class keeps its share)
        // of the training rows when there are more. 0: every row. 15 000: on 100 000 simulated windows
        // (200 000 class-balanced rows) the held-out balanced accuracy is that of 20 000 and 30 000 rows
        // within 0.001 and training takes 17 s CPU instead of 23 s / 40 s (docs/PERFORMANCE.md, Training100k).
        int maxRows = 15000;
        unsigned seed = 1;
        int threads = 0;  // 0: QThread::idealThreadCount(); any count gives the same forest
    };

    // The rows (indices into `labels`) part `part` trains on, in its training order: every row when
    // there are at most maxRows, else round(maxRows · n_c / N) rows of each class c drawn without
    // replacement (at least one of each class present); shuffled with the part's seed.
    static std::vector<int> partRows(const std::vector<int>& labels, int classCount, int part, const Params& params);
    static int partCount(const Params& params);

    // samples: N × F CV_32F; labels: class 0..classCount−1 per row. Returns the trained parts in order.
    static Expected<std::vector<cv::Ptr<cv::ml::RTrees>>> train(const cv::Mat& samples, const std::vector<int>& labels,
                                                                int classCount, const Params& params,
                                                                const Progress& progress = {});

    // Fraction of all trees of all parts voting for each class (rows × classCount, CV_32F).
    static void probabilities(const std::vector<cv::Ptr<cv::ml::StatModel>>& parts, const cv::Mat& samples,
                              int classCount, cv::Mat& out);
};

}  // namespace athlos::activity
