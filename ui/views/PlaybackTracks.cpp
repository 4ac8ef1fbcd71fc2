#include "ui/views/PlaybackTracks.h"

#include "core/geometry/PitchGeometry.h"
#include "core/model/Project.h"
#include "ui/TrajectoryPanel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace athlos::ui {

long AthleteTrack::indexAt(double time) const {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    return long(it - t.begin()) - 1;
}

bool AthleteTrack::positionAt(double time, double maxGap, float& px, float& py) const {
    const long i = indexAt(time);
    if (i < 0) return false;
    const std::size_t k = std::size_t(i);
    if (k + 1 >= t.size()) {
        if (time > t[k] + maxGap) return false;
        px = x[k];
        py = y[k];
        return std::isfinite(px) && std::isfinite(py);
    }
    const double span = t[k + 1] - t[k];
    if (span > maxGap) {
        if (time - t[k] > maxGap) return false;
        px = x[k];
        py = y[k];
    } else {
        const float f = float((time - t[k]) / span);
        px = x[k] + f * (x[k + 1] - x[k]);
        py = y[k] + f * (y[k + 1] - y[k]);
    }
    return std::isfinite(px) && std::isfinite(py);
}

QStringList PlaybackTracks::positionStreams(const Project& project, const QString& recording) {
    QStringList paths;
    const Recording* rec = project.recording(recording);
    if (!rec) return paths;
    for (const auto& [name, stream] : rec->streams)
        if (TrajectoryPanel::isPositionStream(stream.info())) paths << recording + QLatin1Char('/') + name;
    return paths;
}

bool PlaybackTracks::isAthlete(const Stream& stream) {
    if (!TrajectoryPanel::isPositionStream(stream.info())) return false;
    const QJsonObject& a = stream.info().attributes;
    return a.contains(QStringLiteral("team")) || a.contains(QStringLiteral("label")) ||
           a.contains(QStringLiteral("athlete")) ||
           stream.info().provenance.processorId.startsWith(QLatin1String("import:"));
}

QString PlaybackTracks::teamRecording(const Project& project, int minAthletes) {
    QString best;
    std::pair<int, int> bestScore{-1, -1};
    for (const auto& [name, rec] : project.recordings()) {
        int athletes = 0, positions = 0;
        for (const auto& [streamName, stream] : rec.streams) {
            positions += TrajectoryPanel::isPositionStream(stream.info()) ? 1 : 0;
            athletes += isAthlete(stream) ? 1 : 0;
        }
        const std::pair<int, int> score{athletes, positions};
        if (athletes >= minAthletes && positions > 0 && score > bestScore) {
            bestScore = score;
            best = name;
        }
    }
    return best;
}

bool PlaybackTracks::isEnu(const Stream& stream) {
    const StreamInfo& info = stream.info();
    return info.attributes.contains(QStringLiteral("enu_origin")) ||
           info.frame.compare(QLatin1String("enu"), Qt::CaseInsensitive) == 0;
}

bool PlaybackTracks::read(const Stream& stream, const QString& path, AthleteTrack& out, const PitchGeometry* pitch) {
    const StreamInfo& info = stream.info();
    const int cx = info.columnIndex(QStringLiteral("x")), cy = info.columnIndex(QStringLiteral("y"));
    if (cx < 0 || cy < 0) return false;
    auto data = stream.data();
    if (!data) return false;
    const StreamData& d = **data;
    out.path = path;
    out.label = info.attributes.value(QStringLiteral("label")).toString();
    if (out.label.isEmpty()) out.label = stream.name().isEmpty() ? path.section(QLatin1Char('/'), -1) : stream.name();
    out.team = info.attributes.value(QStringLiteral("team")).toString();
    const std::size_t n = d.rows();
    out.t = d.t;
    out.x.resize(n);
    out.y.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        out.x[k] = float(d.at(k, std::size_t(cx)));
        out.y[k] = float(d.at(k, std::size_t(cy)));
    }
    if (pitch && isEnu(stream))
        for (std::size_t k = 0; k < n; ++k) {
            const Eigen::Vector2d q = pitch->toPitch({d.at(k, std::size_t(cx)), d.at(k, std::size_t(cy))});
            out.x[k] = float(q.x());
            out.y[k] = float(q.y());
        }
    computeSpeed(out);
    return true;
}

std::vector<AthleteTrack> PlaybackTracks::readRecording(const Project& project, const QString& recording,
                                                        const PitchGeometry* pitch) {
    std::vector<AthleteTrack> tracks;
    for (const QString& path : positionStreams(project, recording)) {
        AthleteTrack track;
        if (const Stream* s = project.stream(path); s && read(*s, path, track, pitch))
            tracks.push_back(std::move(track));
    }
    return tracks;
}

void PlaybackTracks::computeSpeed(AthleteTrack& track) {
    const std::size_t n = track.t.size();
    track.speed.assign(n, 0.0f);
    track.bin.assign(n, 0);
    if (n < 2) return;
    // Half-window in samples from the median interval: ±0.2 s, at least one sample.
    std::vector<double> dts;
    for (std::size_t k = 1; k < n; k += std::max<std::size_t>(1, n / 1000)) dts.push_back(track.t[k] - track.t[k - 1]);
    std::nth_element(dts.begin(), dts.begin() + long(dts.size() / 2), dts.end());
    const double dt = dts[dts.size() / 2];
    const std::size_t h = dt > 0 ? std::max<std::size_t>(1, std::size_t(std::lround(0.2 / dt))) : 1;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k >= h ? k - h : 0, b = std::min(n - 1, k + h);
        const double span = track.t[b] - track.t[a];
        float v = 0.0f;
        if (span > 0 && span < 4.0 * double(h) * dt + 1e-9) {
            const double dx = double(track.x[b]) - track.x[a], dy = double(track.y[b]) - track.y[a];
            v = float(std::sqrt(dx * dx + dy * dy) / span);
        }
        if (!std::isfinite(v)) v = 0.0f;
        track.speed[k] = v;
        track.bin[k] = std::uint8_t(binOf(v));
    }
}

int PlaybackTracks::binOf(double speed) { return std::clamp(int(speed / kSpeedMax * kBins), 0, kBins - 1); }

QColor PlaybackTracks::colorOf(double speed) {
    // Piecewise linear through blue, cyan, green, yellow, orange, red: each speed zone its own hue.
    static const std::array<QColor, 6> stops{QColor(40, 70, 200),  QColor(0, 190, 230),  QColor(40, 200, 70),
                                             QColor(250, 225, 30), QColor(250, 130, 20), QColor(215, 25, 30)};
    const double u = std::clamp(speed / kSpeedMax, 0.0, 1.0) * double(stops.size() - 1);
    const int i = std::min(int(u), int(stops.size()) - 2);
    const double f = u - i;
    const QColor& a = stops[std::size_t(i)];
    const QColor& b = stops[std::size_t(i) + 1];
    return QColor(int(std::lround(a.red() + f * (b.red() - a.red()))),
                  int(std::lround(a.green() + f * (b.green() - a.green()))),
                  int(std::lround(a.blue() + f * (b.blue() - a.blue()))));
}

QColor PlaybackTracks::binColor(int bin) { return colorOf((bin + 0.5) * kSpeedMax / kBins); }

QRectF PlaybackTracks::extent(const std::vector<AthleteTrack>& tracks) {
    float x0 = std::numeric_limits<float>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const AthleteTrack& tr : tracks)
        for (std::size_t k = 0; k < tr.x.size(); ++k) {
            if (!std::isfinite(tr.x[k]) || !std::isfinite(tr.y[k])) continue;
            x0 = std::min(x0, tr.x[k]);
            x1 = std::max(x1, tr.x[k]);
            y0 = std::min(y0, tr.y[k]);
            y1 = std::max(y1, tr.y[k]);
        }
    if (!(x0 <= x1)) return {};
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

}  // namespace athlos::ui
