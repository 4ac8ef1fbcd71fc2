#pragma once
// Steady-state gait summary of the stride tables of gait-parameters: per parameter and foot the
// number of strides, mean, standard deviation and coefficient of variation, and between the two feet
// the symmetry index.
//
//  1. Steady-state strides: a stride whose |turning_angle| exceeds `maxTurn` is a turn and left out,
//     and so is one on other terrain than `terrain`: level |stride_height| ≤ `levelHeight`, up
//     stride_height ≥ `stairHeight`, down ≤ −stairHeight (a stride on stairs climbs two steps of
//     0.14–0.19 m, DIN 18065; the strides in between, one step and a landing, are transitions);
//     the remaining strides form runs of adjacent strides (one's end is the next one's start: the
//     same mid-stance), and the first and last `edgeStrides` of every run are left out as gait
//     initiation and termination (acceleration and deceleration; Lindemann et al. 2008, Gait Posture
//     27(1):91–96, measure in the steady state; gaitmap's examples drop the first and last strides).
//  2. Per parameter over those strides: mean x̄, sample standard deviation s (n − 1), and the
//     coefficient of variation CV = 100 s / x̄ (%), the usual stride-to-stride variability measure
//     (Hausdorff 2005, J NeuroEng Rehabil 2:19).
//  3. Two feet: the symmetry index SI = 100 |x̄_L − x̄_R| / (½ (x̄_L + x̄_R)) (%) (Robinson, Herzog &
//     Nigg 1987, J Manipulative Physiol Ther 10(4):172–176); 0 is perfect symmetry.
// CV and SI are ratios to the mean and mean nothing for a quantity that crosses zero (the stride height
// of level walking): they are given only when every value they use has the same sign (|x̄| in the
// denominators: the stride height going down stairs is negative), else NaN.
#include <QString>
#include <QStringList>
#include <limits>
#include <optional>
#include <vector>

namespace athlos::events {

enum class Terrain { All, Level, Up, Down };

struct GaitSummaryParams {
    double maxTurn = 0.3;  // rad: larger |turning_angle| is a turn (this project's "straight" bound, 17°)
    int edgeStrides = 1;   // strides left out at each end of a run of adjacent straight strides
    Terrain terrain = Terrain::All;
    double levelHeight = 0.05;  // m: |stride_height| up to it is level (a third of a step; level drift 0.02–0.03 m)
    double stairHeight = 0.2;   // m: |stride_height| from it is stairs (more than one step of at most 0.19 m)
};

// "all", "level", "up", "down"; nullopt otherwise.
std::optional<Terrain> terrainOf(const QString& name);

// One foot's stride table: times and turning angle per stride, and the parameters to summarise.
struct FootStrides {
    QString foot;                                 // "left", "right" or a table name
    std::vector<double> start, end, turn;         // s, s, rad; one per stride
    std::vector<double> height;                   // m, stride_height (needed unless terrain is All)
    QStringList names, units;                     // the parameters
    std::vector<std::vector<double>> parameters;  // parameters[p][stride]
};

struct ParameterStats {
    int n = 0;
    double mean = std::numeric_limits<double>::quiet_NaN();
    double sd = std::numeric_limits<double>::quiet_NaN();  // NaN for n < 2
    double cv = std::numeric_limits<double>::quiet_NaN();  // %, NaN for n < 2 or values of both signs
    int sign = 0;  // +1 / −1: every value used is > 0 / < 0 (n ≥ 1); 0 otherwise
};

struct FootSummary {
    QString foot;
    // In the table; left out as turns, as other terrain, as run ends; used.
    int strides = 0, turns = 0, terrain = 0, edges = 0, used = 0;
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
