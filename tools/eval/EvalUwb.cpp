// Scores tracks of the outdoor UWB dataset (../shared/data/uwb-outdoor, README there) the way its
// authors score theirs: 2D RMSE against the RTK reference (trajectory.csv) linearly interpolated at the
// track's time stamps, over one lap —
//   Trajectory A: from the first reference point with x > 49.3 and y > −5 until x ≤ 12 and y > 3.4;
//   Trajectory B: from x < 8.6 and y < −7 until x > 8.6 and y < −7.
// Usage: athlos-eval-uwb --reference trajectory.csv --lap A|B TRACK.csv…
// Track files: a header with t (s) or timestamp (ns) and x, y (an Athlos export, or the authors' LS.csv /
// ESKF.csv). Prints one line per track: name, samples in the lap, RMSE (m), max error (m).
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace {

struct Track {
    std::vector<double> t, x, y;
};

// t in seconds: a `timestamp` column (ns since the epoch) or `t` (s).
std::optional<Track> readTrack(const QString& path, QString& error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        error = QStringLiteral("%1: cannot open").arg(path);
        return std::nullopt;
    }
    QTextStream in(&file);
    const QStringList header = in.readLine().split(QLatin1Char(','));
    auto column = [&](const QString& name) {
        for (int i = 0; i < header.size(); ++i)
            if (header[i].trimmed().section(QLatin1Char(' '), 0, 0) == name) return i;
        return -1;
    };
    const int ct = column(QStringLiteral("t")) >= 0 ? column(QStringLiteral("t")) : column(QStringLiteral("timestamp"));
    const bool nanoseconds = column(QStringLiteral("t")) < 0;
    const int cx = column(QStringLiteral("x")), cy = column(QStringLiteral("y"));
    if (ct < 0 || cx < 0 || cy < 0) {
        error = QStringLiteral("%1:1: needs columns t (s) or timestamp (ns), x and y").arg(path);
        return std::nullopt;
    }
    Track track;
    long long line = 1;
    while (!in.atEnd()) {
        ++line;
        const QStringList cells = in.readLine().split(QLatin1Char(','));
        if (cells.size() <= std::max({ct, cx, cy})) continue;
        bool ok1 = false, ok2 = false, ok3 = false;
        const double t = cells[ct].toDouble(&ok1), x = cells[cx].toDouble(&ok2), y = cells[cy].toDouble(&ok3);
        if (!ok1 || !ok2 || !ok3) {
            error = QStringLiteral("%1:%2: not a number").arg(path).arg(line);
            return std::nullopt;
        }
        track.t.push_back(nanoseconds ? t * 1e-9 : t);
        track.x.push_back(x);
        track.y.push_back(y);
    }
    return track;
}

// [t_begin, t_end] of the lap on the reference.
std::optional<std::pair<double, double>> lap(const Track& ref, QChar trajectory) {
    const bool a = trajectory == QLatin1Char('A');
    std::size_t k = 0;
    auto starts = [&](std::size_t i) { return a ? ref.x[i] > 49.3 && ref.y[i] > -5 : ref.x[i] < 8.6 && ref.y[i] < -7; };
    auto ends = [&](std::size_t i) { return a ? ref.x[i] <= 12 && ref.y[i] > 3.4 : ref.x[i] > 8.6 && ref.y[i] < -7; };
    while (k < ref.t.size() && !starts(k)) ++k;
    if (k == ref.t.size()) return std::nullopt;
    const double begin = ref.t[k];
    while (k < ref.t.size() && !ends(k)) ++k;
    if (k == ref.t.size()) return std::nullopt;
    return std::make_pair(begin, ref.t[k]);
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    QString reference, lapName;
    QStringList tracks;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--reference") && i + 1 < args.size())
            reference = args[++i];
        else if (args[i] == QLatin1String("--lap") && i + 1 < args.size())
            lapName = args[++i];
        else
            tracks << args[i];
    }
    if (reference.isEmpty() || (lapName != QLatin1String("A") && lapName != QLatin1String("B")) || tracks.isEmpty()) {
        std::fprintf(stderr, "usage: athlos-eval-uwb --reference trajectory.csv --lap A|B TRACK.csv...\n");
        return 2;
    }
    QString error;
    const auto ref = readTrack(reference, error);
    if (!ref) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    const auto window = lap(*ref, lapName[0]);
    if (!window) {
        std::fprintf(stderr, "%s: the lap of trajectory %s is not in the reference\n", qPrintable(reference),
                     qPrintable(lapName));
        return 1;
    }
    int status = 0;
    for (const QString& path : tracks) {
        const auto track = readTrack(path, error);
        if (!track) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            status = 1;
            continue;
        }
        double sum = 0.0, worst = 0.0;
        int n = 0;
        for (std::size_t k = 0; k < track->t.size(); ++k) {
            const double t = track->t[k];
            if (t < window->first || t > window->second) continue;
            const auto hi = std::upper_bound(ref->t.begin(), ref->t.end(), t) - ref->t.begin();
            if (hi == 0 || hi >= std::ptrdiff_t(ref->t.size())) continue;
            const std::size_t j = std::size_t(hi);
            const double w = (t - ref->t[j - 1]) / (ref->t[j] - ref->t[j - 1]);
            const double rx = ref->x[j - 1] + w * (ref->x[j] - ref->x[j - 1]);
            const double ry = ref->y[j - 1] + w * (ref->y[j] - ref->y[j - 1]);
            const double e2 = std::pow(track->x[k] - rx, 2) + std::pow(track->y[k] - ry, 2);
            sum += e2;
            worst = std::max(worst, std::sqrt(e2));
            ++n;
        }
        if (n == 0) {
            std::fprintf(stderr, "%s: no sample inside the lap\n", qPrintable(path));
            status = 1;
            continue;
        }
        std::printf("%-40s %6d samples  RMSE %.3f m  max %.3f m\n", qPrintable(QFileInfo(path).fileName()), n,
                    std::sqrt(sum / n), worst);
    }
    return status;
}
