#pragma once
// Features of one window of an IMU stream (seed 000, thesis §5.2, Table 5.1; digest §8): for every
// channel the median, mean, SD, skewness, kurtosis, dominant frequency and its amplitude, max, min,
// argmax, argmin and energy; per sensor the correlations between its axes; from the accelerometer
// the direction of gravity (window mean) with the pitch and roll of the sensor.
//
// Channels per sensor triple (acc, gyr, mag): x, y, z and the norm; acc and gyr also the component
// along gravity ("vert") and acc the norm across it ("horiz") — the last three do not depend on how
// the sensor sits on the wrist, which is what generalises across people.
#include "core/model/Stream.h"
#include "core/util/Expected.h"

#include <opencv2/core.hpp>

#include <QStringList>
#include <array>
#include <vector>

namespace athlos::activity {

class FeatureExtractor {
public:
    // sensors: any of "acc", "gyr", "mag" (acc is required: gravity comes from it). Finds the
    // columns <sensor>_x.._z in info; the error names the missing column.
    static Expected<FeatureExtractor> create(const StreamInfo& info, const QStringList& sensors);

    const QStringList& names() const { return names_; }
    int size() const { return int(names_.size()); }
    const QStringList& sensors() const { return sensors_; }
    // The stream columns the features read, in order (for a model's compatibility check).
    QStringList inputColumns() const;

    // Features of rows [begin, end) of data into out (size() floats). Fewer than 2 rows give zeros.
    void compute(const StreamData& data, std::size_t begin, std::size_t end, float* out);

private:
    struct Sensor {
        QString name;
        int column = -1;  // first of x, y, z
    };
    void addNames();

    QStringList sensors_;
    std::vector<Sensor> columns_;
    QStringList names_;
    // Scratch, reused between windows (no allocation once the window length settles).
    std::vector<double> channels_;  // channel-major, channelCount × n
    std::vector<double> scratch_;
    cv::Mat padded_, spectrum_;
    std::vector<double> magnitude_;
};

}  // namespace athlos::activity
