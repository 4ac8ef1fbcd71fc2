#pragma once
// Steady-state gait summary of the stride tables of gait-parameters: per parameter and foot the
// number of strides, mean, standard deviation and coefficient of variation, and between the two feet
// the symmetry index.
//
//  1. Steady-state strides: a stride whose |turning_angle| exceeds `maxTurn` is a turn and left out;
//     the remaining strides form runs of adjacent strides (one's end is the next one's start: the
//     same mid-stance), and the first and last `edgeStrides` of every run are left out as gait
//     initiation and termination (acceleration and deceleration; Lindemann et al. 2008, Gait Posture
//     27(1):91–96, measure in the steady state; gaitmap's examples drop the first and last strides).
//  2. Per parameter over those strides: mean x̄, sample standard deviation s (n − 1), and the
//     coefficient of variation CV = 100 s / x̄ (%), the usual stride-to-stride variability measure
//     (Hausdorff 2005, J NeuroEng Rehabil 2:19).
//  3. Two feet: the symmetry index SI = 100 |x̄_L − x̄_R| / (½ (x̄_L + x̄_R)) (%) (Robinson, Herzog &
//     Nigg 1987, J Manipulative Physiol Ther 10(4):172–176); 0 is perfect symmetry.
// CV and SI are ratios to the mean and mean nothing for a signed quantity that crosses zero (the stride
// height of level walking): they are given only when every value they use is positive, else NaN.
#include <QString>
#include <QStringList>
#include <limits>
#include <vector>

namespace athlos::events {

struct GaitSummaryParams {
    double maxTurn = 0.3;  // rad: larger |turning_angle| is a turn (this project's "straight" bound, 17°)
    int edgeStrides = 1;   // strides left out at each end of a run of adjacent straight strides
};

// One foot's stride table: times and turning angle per stride, and the parameters to summarise.
struct FootStrides {
    QString foot;                                 // "left", "right" or a table name
    std::vector<double> start, end, turn;         // s, s, rad; one per stride
    QStringList names, units;                     // the parameters
    std::vector<std::vector<double>> parameters;  // parameters[p][stride]
};

struct ParameterStats {
    int n = 0;
    double mean = std::numeric_limits<double>::quiet_NaN();
    double sd = std::numeric_limits<double>::quiet_NaN();  // NaN for n < 2
    double cv = std::numeric_limits<double>::quiet_NaN();  // %, NaN for n < 2 or a value ≤ 0
    bool positive = false;                                 // every value used > 0 (n ≥ 1)
};

struct FootSummary {
    QString foot;
    int strides = 0, turns = 0, edges = 0, used = 0;  // in the table; left out as turns, as run ends; used
    std::vector<ParameterStats> stats;                // one per parameter, in the table's order
};

struct GaitSummary {
    QStringList names, units;       // the parameters (those of the first foot)
    std::vector<FootSummary> feet;  // one or two
    // Two feet only: both feet's steady strides together (foot "both"), and per parameter the symmetry
    // index (%, NaN where a mean is missing).
    FootSummary pooled;
    std::vector<double> symmetry;
};

// Step 1: which strides of `foot` count (true) for the summary.
std::vector<bool> steadyStrides(const GaitSummaryParams& params, const FootStrides& foot);

// Steps 1–3 for one or two feet (two: the second's parameters are matched by name).
GaitSummary summariseGait(const GaitSummaryParams& params, const std::vector<FootStrides>& feet);

}  // namespace athlos::events
