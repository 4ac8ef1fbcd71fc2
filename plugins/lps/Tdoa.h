#pragma once
// Shared vocabulary of the LPS family: the TDoA measurement model of thesis Eqn. 2.5/3.1 and the
// containers the solvers, the calibration and the simulator pass around.
//
// Model (per instant, beacon i):  c(Δt_i + t_off) = |m − b_i| − |r − b_i|
// with the tag position m, beacon position b_i, reference node r and the offset t_off common to
// all beacons of one instant. Internally the offset is carried as the length o (m) so that every
// unknown of a fix has the unit metre (better conditioned normal equations), with the residual
// e_i = |m − b_i| − |r − b_i| − c·Δt_i − o exactly as Eqn. 3.1 writes it. The thesis simulates
// Δt_i = (|m − b_i| − |r − b_i|)/c + t_off (Eqn. 3.5), so o = −c·t_off: outputs report
// t_off = −o/c, the offset contained in the readings.
#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <vector>

namespace athlos::lps {

inline constexpr double kSpeedOfLight = 299792458.0;  // m/s

using Vector3 = Eigen::Vector3d;
using Vector2 = Eigen::Vector2d;

// One TDoA reading: the beacon's index into a BeaconLayout and its time difference (s).
struct TdoaReading {
    int beacon = 0;
    double dt = 0.0;
};

// All readings of one instant (one row group of the long `t,beacon,dt` stream).
struct TdoaEpoch {
    double t = 0.0;
    std::vector<TdoaReading> readings;
};

// Beacon positions in the LPS frame plus the reference node (the origin unless a table says
// otherwise, see BeaconTable.h).
struct BeaconLayout {
    QStringList ids;
    std::vector<Vector3> positions;
    Vector3 reference = Vector3::Zero();

    int size() const { return static_cast<int>(positions.size()); }
    int indexOf(const QString& id) const { return ids.indexOf(id); }
};

// One solved instant: tag position, offset, quality (thesis Eqn. 3.1 residuals).
struct TagFix {
    double t = 0.0;
    Vector3 position = Vector3::Zero();
    double offset = 0.0;       // o = −c·t_off (m), see above
    double rmsResidual = 0.0;  // sqrt(Σ w e_i² / Σ w) over the beacons used (m)
    int beaconsUsed = 0;
    bool valid = false;
};

}  // namespace athlos::lps
