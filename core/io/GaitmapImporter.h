#pragma once
// Importer for gaitmap example recordings (MaD Lab, FAU): CSV with two header rows, sensor
// ("left_sensor", "right_sensor") and axis ("acc_x" ... "gyr_z"), acc in m/s^2, gyr in deg/s.
//
// Columns are found by their header names, never by position (the files differ: interleaved
// left/right columns in imu_sample_ic_stride.csv, grouped in the stair files). One imu stream per
// sensor, frame sensor: left_sensor → left-foot, right_sensor → right-foot; in a file with one sensor
// of each side by another name (l_lateral / r_lateral, left_foot / right_foot, …) those two are the
// feet too; any other "<name>_sensor" → <name>, "l_ankle" → l-ankle (the name is kept in attribute
// "sensor"). gyr is converted to rad/s; an axis cell may name another unit.
//
// The first column (empty header, or "sensor"/"axis": the level names pandas writes for a
// MultiIndex; a third header row with only the index name is skipped) is either a sample index or time in seconds, and the file does
// not say which: consecutive integers (step 1) are a sample index, anything else is time in seconds.
// A sample index has no rate in the file, and gaitmap's recordings differ (the walk with mocap strides
// at 102.4 Hz, the stair files and imu_sample.csv at 204.8 Hz): the rate is ImportOptions::rate
// (`--rate`) when given, else the one of kIndexRates (51.2 · 2^k Hz, the NilsPod rates) at which the
// gyroscope and the accelerometer agree (ImuSamplingRate), said in a warning with the scores; 102.4 Hz
// with a warning when the motion cannot tell. t = index / rate, so sample k of a companion stride file
// is at t = k / rate. attributes["sampling_rate"] holds that rate or 1 / (median interval).
#include "core/io/Importer.h"

namespace athlos {

class GaitmapImporter final : public Importer {
public:
    static constexpr double kIndexRate = 102.4;  // Hz, when an index-only file's motion cannot tell
    static constexpr double kIndexRates[] = {51.2, 102.4, 204.8, 409.6, 819.2};  // Hz, the candidates

    QString format() const override { return QStringLiteral("gaitmap"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv"}; }
    // A first header row naming left_sensor/right_sensor and a second with acc_/gyr_ axes.
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

}  // namespace athlos
