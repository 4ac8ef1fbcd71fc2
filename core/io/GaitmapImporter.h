#pragma once
// Importer for gaitmap example recordings (MaD Lab, FAU): CSV with two header rows, sensor
// ("left_sensor", "right_sensor") and axis ("acc_x" ... "gyr_z"), acc in m/s^2, gyr in deg/s.
//
// Columns are found by their header names, never by position (the files differ: interleaved
// left/right columns in imu_sample_ic_stride.csv, grouped in the stair files). One imu stream per
// sensor, frame sensor: left_sensor → left-foot, right_sensor → right-foot, any other
// "<name>_sensor" → <name>. gyr is converted to rad/s; an axis cell may name another unit.
//
// The first column (empty header, or "sensor"/"axis": the level names pandas writes for a
// MultiIndex; a third header row with only the index name is skipped) is either a sample index or time in seconds, and the file does
// not say which: consecutive integers (step 1) are a sample index at gaitmap's 102.4 Hz, so
// t = index / 102.4 (sample k of a companion stride file stays at t = k / 102.4); anything else is
// time in seconds. attributes["sampling_rate"] holds 102.4 or 1 / (median interval).
#include "core/io/Importer.h"

namespace athlos {

class GaitmapImporter final : public Importer {
public:
    static constexpr double kIndexRate = 102.4;  // Hz, rate of gaitmap's index-based example data

    QString format() const override { return QStringLiteral("gaitmap"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv"}; }
    // A first header row naming left_sensor/right_sensor and a second with acc_/gyr_ axes.
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
