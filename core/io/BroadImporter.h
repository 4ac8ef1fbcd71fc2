#pragma once
// Importer for BROAD trials (Laidig et al., Data 2021): HDF5 with imu_acc, imu_gyr, imu_mag (N×3),
// opt_quat (N×4, w x y z), opt_pos (N×3), movement (N, bool) and a root attribute sampling_rate.
//
// Creates two streams with t = i / sampling_rate:
//   imu        kind imu, frame sensor: acc_x..z (m/s^2), gyr_x..z (rad/s), mag_x..z (uT)
//   reference  kind reference, frame ENU: qw, qx, qy, qz (1), movement (0/1), pos_x..z (m)
// Both carry attributes sampling_rate and info (the file's description). NaN quaternions (optical
// dropouts) are kept: evaluation skips them, and inventing values would bias it.
#include "core/io/Importer.h"

namespace athlos {

class BroadImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("broad"); }
    QString description() const override;
    QStringList extensions() const override { return {"hdf5", "h5"}; }
    // HDF5 signature in the head and an imu_acc dataset in the file.
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
