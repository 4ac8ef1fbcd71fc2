#include "plugins/activity/CnnTraining.h"

#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/RawWindows.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>
#include <set>

namespace athlos::activity {

namespace {
QStringList strings(const QJsonValue& v) {
    QStringList out;
    for (const auto& x : v.toArray()) out << x.toString();
    return out;
}
}  // namespace

Expected<RawDataset> buildRawDataset(const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                                     const QStringList& classes, int length, const Progress& progress) {
    RawDataset d;
    d.sensors = options.sensors;
    d.classes = classes.isEmpty() ? trainingClasses(sources, options) : classes;
    if (sources.empty()) return makeError(QStringLiteral("no recording to take windows from"));
    auto segmentation = fitSegmentation(sources, options, d.classes);
    if (!segmentation) return segmentation.error();
    d.segmentation = *segmentation;
    d.length = length > 0 ? length : options.rawLength;
    if (d.length <= 0) {
        const double interval = sources.front().data->medianInterval();
        if (!(interval > 0))
            return makeError(QStringLiteral("%1: no sampling interval").arg(sources.front().recording));
        d.length = int(std::lround(options.window / interval)) + 1;
    }
    if (d.length < 8 || d.length > 100000)
        return makeError(QStringLiteral("raw windows of %1 samples: expected 8 to 100000").arg(d.length));
    std::vector<float> rows;
    std::vector<int> columns;
    for (std::size_t si = 0; si < sources.size(); ++si) {
        const TrainingSource& s = sources[si];
        auto extractor = FeatureExtractor::create(s.info, options.sensors);
        if (!extractor)
            return makeError(QStringLiteral("%1/%2: %3").arg(s.recording, s.info.name, extractor.message()));
        if (d.inputColumns.isEmpty()) {
            d.inputColumns = extractor->inputColumns();
            for (const QString& c : d.inputColumns)
                d.units[c] = s.info.columns[std::size_t(s.info.columnIndex(c))].unit;
        }
        columns.clear();
        for (const QString& c : d.inputColumns) {
            const int i = s.info.columnIndex(c);
            if (i < 0) return makeError(QStringLiteral("%1/%2: no column '%3'").arg(s.recording, s.info.name, c));
            const QString unit = s.info.columns[std::size_t(i)].unit;
            if (unit != d.units.value(c).toString())
                return makeError(QStringLiteral("%1/%2: column %3 is in '%4', other recordings in '%5'")
                                     .arg(s.recording, s.info.name, c, unit, d.units.value(c).toString()));
            columns.push_back(i);
        }
        if (!d.subjects.contains(s.athlete)) d.subjects << s.athlete;
        const int group = int(d.subjects.indexOf(s.athlete));
        const std::size_t width = columns.size() * std::size_t(d.length);
        auto windows = labelledWindows(s, options, d.segmentation, d.classes);
        if (!windows) return windows.error();
        for (const LabelledWindow& lw : *windows) {
            rows.resize(rows.size() + width);
            rawWindow(*s.data, columns, lw.window.tStart, lw.window.tEnd, d.length, rows.data() + rows.size() - width);
            d.labels.push_back(lw.label);
            d.source.push_back(int(si));
            d.groups.push_back(group);
        }
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        progress.report(double(si + 1) / double(sources.size()), QStringLiteral("windows"));
    }
    if (d.labels.empty()) return makeError(QStringLiteral("no window is covered by an annotation of the classes"));
    if (classes.isEmpty()) {  // drop classes never seen, as buildDataset does
        std::set<int> present(d.labels.begin(), d.labels.end());
        QStringList seen;
        std::vector<int> remap(std::size_t(d.classes.size()), -1);
        for (int c : present) {
            remap[std::size_t(c)] = int(seen.size());
            seen << d.classes[c];
        }
        for (int& l : d.labels) l = remap[std::size_t(l)];
        d.classes = seen;
    }
    d.windows = cv::Mat(int(d.labels.size()), int(d.inputColumns.size()) * d.length, CV_32F, rows.data()).clone();
    return d;
}

Status exportWindows(const RawDataset& d, const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                     const QString& directory) {
    if (!QDir().mkpath(directory))
        return makeError(QStringLiteral("--export-windows %1: cannot create").arg(directory));
    const QDir dir(directory);
    const auto n = (long long)d.labels.size();
    if (Status s = writeNpy(dir.filePath(QStringLiteral("windows.npy")),
                            {n, (long long)d.inputColumns.size(), (long long)d.length}, d.windows.ptr<float>());
        !s)
        return s;
    if (Status s = writeNpy(dir.filePath(QStringLiteral("labels.npy")), {n}, d.labels.data()); !s) return s;
    if (Status s = writeNpy(dir.filePath(QStringLiteral("groups.npy")), {n}, d.groups.data()); !s) return s;
    QJsonArray recordings;
    for (const auto& s : sources)
        recordings.append(QJsonObject{{QStringLiteral("recording"), s.recording},
                                      {QStringLiteral("athlete"), s.athlete},
                                      {QStringLiteral("content_hash"), QString::fromLatin1(s.data->contentHash())}});
    const QJsonObject meta{{QStringLiteral("format"), QStringLiteral("athlos-windows-1")},
                           {QStringLiteral("classes"), QJsonArray::fromStringList(d.classes)},
                           {QStringLiteral("subjects"), QJsonArray::fromStringList(d.subjects)},
                           {QStringLiteral("recordings"), recordings},
                           {QStringLiteral("input_columns"), QJsonArray::fromStringList(d.inputColumns)},
                           {QStringLiteral("sensors"), QJsonArray::fromStringList(d.sensors)},
                           {QStringLiteral("units"), d.units},
                           {QStringLiteral("window"), options.window},
                           {QStringLiteral("step"), options.step},
                           {QStringLiteral("length"), d.length},
                           {QStringLiteral("windows"), double(n)},
                           {QStringLiteral("segmentation"), d.segmentation.toJson()}};
    QFile f(dir.filePath(QStringLiteral("meta.json")));
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(QJsonDocument(meta).toJson()) < 0)
        return makeError(QStringLiteral("%1: cannot write").arg(f.fileName()));
    return {};
}

Expected<ActivityModel> importCnn(const QByteArray& onnx, const QJsonObject& d, const QString& what) {
    const auto refuse = [&](const QString& why) { return makeError(QStringLiteral("%1: %2").arg(what, why)); };
    ActivityModel m;
    m.classes = strings(d.value(QStringLiteral("classes")));
    m.inputColumns = strings(d.value(QStringLiteral("input_columns")));
    m.sensors = strings(d.value(QStringLiteral("sensors")));
    m.window = d.value(QStringLiteral("window")).toDouble();
    m.step = d.value(QStringLiteral("step")).toDouble();
    if (m.classes.size() < 2) return refuse(QStringLiteral("the description lists fewer than two classes"));
    if (QSet<QString>(m.classes.begin(), m.classes.end()).size() != m.classes.size())
        return refuse(QStringLiteral("the description lists a class twice"));
    if (m.inputColumns.isEmpty()) return refuse(QStringLiteral("the description lists no input_columns"));
    if (!m.sensors.contains(QStringLiteral("acc"))) return refuse(QStringLiteral("the sensors must include acc"));
    if (!(m.window > 0) || !(m.step > 0)) return refuse(QStringLiteral("window and step must be positive (s)"));
    auto cnn = CnnClassifier::fromJson(onnx, d.value(QStringLiteral("cnn")).toObject(), int(m.inputColumns.size()),
                                       int(m.classes.size()));
    if (!cnn) return refuse(cnn.message());
    m.cnn = std::move(*cnn);
    auto segmentation = Segmentation::fromJson(d.value(QStringLiteral("segmentation")));
    if (!segmentation) return refuse(segmentation.message());
    m.segmentation = *segmentation;
    m.provenance[QStringLiteral("units")] = d.value(QStringLiteral("units")).toObject();
    if (d.contains(QStringLiteral("training")))
        m.provenance[QStringLiteral("cnn_training")] = d.value(QStringLiteral("training")).toObject();
    return m;
}

}  // namespace athlos::activity
