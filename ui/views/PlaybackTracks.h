#pragma once
// The athletes of a playback, prepared once so that a frame costs a binary search and the trail
// per athlete: time stamps, positions, speed and the speed's colour bin as flat arrays.
#include <QColor>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <vector>

namespace athlos {
class PitchGeometry;
class Project;
class Stream;
}  // namespace athlos

namespace athlos::ui {

struct AthleteTrack {
    QString path;   // "rec/stream"
    QString label;  // short label drawn at the dot ("H7"), else the stream name
    QString team;   // "home", "away" or empty
    std::vector<double> t;
    std::vector<float> x, y;        // m; NaN where the source had no fix
    std::vector<float> speed;       // m/s
    std::vector<std::uint8_t> bin;  // colour bin of the speed (PlaybackTracks::kBins)

    // Index of the last sample at or before t (−1 if none).
    long indexAt(double time) const;
    // Position at time t, linearly interpolated between samples less than maxGap apart; false
    // before the first or after the last sample, and inside gaps.
    bool positionAt(double time, double maxGap, float& px, float& py) const;
};

class PlaybackTracks {
public:
    static constexpr int kBins = 48;
    static constexpr double kSpeedMax = 9.0;  // m/s at the top of the colour scale

    // Position streams (lps-position, trajectory, gnss with x and y) of a recording, in name order.
    static QStringList positionStreams(const Project& project, const QString& recording);
    // A position stream of its own athlete: it names one (attribute team, label or athlete, as
    // simulate-team writes) or was imported. Filter results and simulated truths of the same run are not.
    static bool isAthlete(const Stream& stream);
    // The recording with the most athletes (at least minAthletes; 0 = any recording with a position
    // stream), more position streams breaking ties; empty if none.
    static QString teamRecording(const Project& project, int minAthletes);

    // Reads one stream (loads its samples) into a track; false if it has no x/y. With a pitch,
    // positions in the project's ENU frame (GNSS x, y: attribute enu_origin, or frame "enu") are
    // moved into the pitch frame (centre spot, x along the length); other frames (LPS, a simulated
    // pitch) are taken as they are.
    static bool read(const Stream& stream, const QString& path, AthleteTrack& out,
                     const PitchGeometry* pitch = nullptr);
    // Whether a stream's x, y are in the project's ENU frame.
    static bool isEnu(const Stream& stream);
    // The tracks of every position stream of a recording (in the pitch frame when given, see read()).
    static std::vector<AthleteTrack> readRecording(const Project& project, const QString& recording,
                                                   const PitchGeometry* pitch = nullptr);
    // Speed by central differences over about ±0.2 s (noise of single fixes is not speed), and its bin.
    static void computeSpeed(AthleteTrack& track);

    static int binOf(double speed);
    // Colour of a speed (m/s): blue (standing) over cyan, green, yellow to red (sprinting).
    static QColor colorOf(double speed);
    static QColor binColor(int bin);
    // Data extent over all tracks (finite positions only).
    static QRectF extent(const std::vector<AthleteTrack>& tracks);
};

}  // namespace athlos::ui
