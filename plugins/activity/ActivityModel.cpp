#include "plugins/activity/ActivityModel.h"

#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/RawWindows.h"
#include "plugins/activity/Windows.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace athlos::activity {

namespace {
QJsonArray floats(const std::vector<float>& v) {
    QJsonArray a;
    for (float x : v) a.append(double(x));
    return a;
}

QStringList strings(const QJsonValue& v) {
    QStringList out;
    for (const auto& x : v.toArray()) out << x.toString();
    return out;
}
}  // namespace

RobustScaling RobustScaling::fit(const cv::Mat& samples) {
    RobustScaling s;
    std::vector<float> column(std::size_t(samples.rows));
    for (int j = 0; j < samples.cols; ++j) {
        for (int i = 0; i < samples.rows; ++i) column[std::size_t(i)] = samples.at<float>(i, j);
        std::sort(column.begin(), column.end());
        const auto quantile = [&](double q) {
            if (column.empty()) return 0.0f;
            const double pos = q * double(column.size() - 1);
            const auto lo = std::size_t(std::floor(pos));
            const auto hi = std::min(lo + 1, column.size() - 1);
            return float(column[lo] + (pos - double(lo)) * (column[hi] - column[lo]));
        };
        const float iqr = quantile(0.75) - quantile(0.25);
        s.centre.push_back(quantile(0.5));
        s.scale.push_back(iqr > 1e-12f ? iqr : 1.0f);
    }
    return s;
}

void RobustScaling::apply(cv::Mat& samples) const {
    for (int i = 0; i < samples.rows; ++i) {
        float* row = samples.ptr<float>(i);
        for (int j = 0; j < samples.cols && std::size_t(j) < centre.size(); ++j)
            row[j] = (row[j] - centre[std::size_t(j)]) / scale[std::size_t(j)];
    }
}

QJsonObject RobustScaling::toJson() const {
    return {{QStringLiteral("method"), QStringLiteral("median-iqr")},
            {QStringLiteral("centre"), floats(centre)},
            {QStringLiteral("scale"), floats(scale)}};
}

std::optional<RobustScaling> RobustScaling::fromJson(const QJsonObject& json, int features) {
    RobustScaling s;
    for (const auto& v : json.value(QStringLiteral("centre")).toArray()) s.centre.push_back(float(v.toDouble()));
    for (const auto& v : json.value(QStringLiteral("scale")).toArray()) s.scale.push_back(float(v.toDouble()));
    if (int(s.centre.size()) != features || int(s.scale.size()) != features) return std::nullopt;
    for (float x : s.scale)
        if (!(std::isfinite(x) && x != 0.0f)) return std::nullopt;
    return s;
}

Expected<ActivityModel> ActivityModel::fromStored(const TrainedModel& stored) {
    const auto refuse = [&](const QString& why) {
        return makeError(QStringLiteral("model '%1': %2").arg(stored.name, why));
    };
    const bool isCnn = stored.format == QLatin1String(kOnnxFormat);
    if (stored.format != QLatin1String(kFormat) && !isCnn)
        return refuse(QStringLiteral("format '%1' is not an activity classifier (%2 or %3)")
                          .arg(stored.format, kFormat, kOnnxFormat));
    const QJsonObject& d = stored.description;
    ActivityModel m;
    m.classes = strings(d.value(QStringLiteral("classes")));
    m.sensors = strings(d.value(QStringLiteral("sensors")));
    m.features = strings(d.value(QStringLiteral("features")));
    m.inputColumns = strings(d.value(QStringLiteral("input_columns")));
    m.window = d.value(QStringLiteral("window")).toDouble();
    m.step = d.value(QStringLiteral("step")).toDouble();
    m.provenance = d;
    if (m.classes.size() < 2) return refuse(QStringLiteral("it lists fewer than two classes"));
    if (!(m.window > 0) || !(m.step > 0)) return refuse(QStringLiteral("its window or step is not positive"));
    auto segmentation = Segmentation::fromJson(d.value(QStringLiteral("segmentation")));
    if (!segmentation) return refuse(segmentation.message());
    m.segmentation = *segmentation;
    if (isCnn) {
        if (m.inputColumns.isEmpty()) return refuse(QStringLiteral("it lists no input columns"));
        const auto bytes = QByteArray::fromBase64Encoding(stored.definition, QByteArray::AbortOnBase64DecodingErrors);
        if (!bytes) return refuse(QStringLiteral("its definition is not base64 text"));
        auto cnn = CnnClassifier::fromJson(*bytes, d.value(QStringLiteral("cnn")).toObject(),
                                           int(m.inputColumns.size()), int(m.classes.size()));
        if (!cnn) return refuse(cnn.message());
        m.cnn = std::move(*cnn);
        return m;
    }
    if (m.features.isEmpty()) return refuse(QStringLiteral("it lists no features"));
    if (d.contains(QStringLiteral("interaction"))) {
        auto interaction = InteractionOptions::fromJson(d.value(QStringLiteral("interaction")).toObject());
        if (!interaction) return refuse(interaction.message());
        const QStringList names = interaction->names();
        if (m.features.size() <= names.size() || m.features.mid(m.features.size() - names.size()) != names)
            return refuse(QStringLiteral("its features do not end with its interaction features"));
        m.interaction = std::move(*interaction);
    }
    if (!(m.window > 0) || !(m.step > 0)) return refuse(QStringLiteral("its window or step is not positive"));
    if (d.contains(QStringLiteral("feature_selection"))) {
        auto selection =
            FeatureSelection::fromJson(d.value(QStringLiteral("feature_selection")).toObject(), m.features);
        if (!selection) return refuse(selection.message());
        m.selection = std::move(*selection);
    }
    const int used = m.selection ? m.selection->size() : int(m.features.size());
    auto scaling = RobustScaling::fromJson(d.value(QStringLiteral("scaling")).toObject(), used);
    if (!scaling) return refuse(QStringLiteral("its scaling does not match its %1 features").arg(used));
    m.scaling = std::move(*scaling);
    try {
        cv::FileStorage fs(stored.definition.toStdString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
        if (!fs.isOpened()) return refuse(QStringLiteral("its definition is not OpenCV YAML"));
        auto classifier = Classifier::read(fs["classifier"], int(m.classes.size()));
        if (!classifier) return refuse(classifier.message());
        m.classifier = std::move(*classifier);
    } catch (const cv::Exception& e) {
        return refuse(QStringLiteral("its definition cannot be parsed: %1").arg(QString::fromStdString(e.err)));
    }
    return m;
}

Expected<TrainedModel> ActivityModel::toStored(const QString& name) const {
    if (cnn) {
        TrainedModel t;
        t.name = name;
        t.format = QString::fromLatin1(kOnnxFormat);
        t.definition = cnn->onnx().toBase64();
        QJsonObject d = provenance;
        d[QStringLiteral("classes")] = QJsonArray::fromStringList(classes);
        d[QStringLiteral("sensors")] = QJsonArray::fromStringList(sensors);
        d[QStringLiteral("features")] = QJsonArray();
        d[QStringLiteral("input_columns")] = QJsonArray::fromStringList(inputColumns);
        d[QStringLiteral("window")] = window;
        d[QStringLiteral("step")] = step;
        d[QStringLiteral("cnn")] = cnn->toJson();
        d[QStringLiteral("segmentation")] = segmentation.toJson();
        d[QStringLiteral("classifier")] = QStringLiteral("cnn");
        t.description = d;
        return t;
    }
    if (!classifier) return makeError(QStringLiteral("model '%1' has no trained classifier").arg(name));
    TrainedModel t;
    t.name = name;
    t.format = QString::fromLatin1(kFormat);
    try {
        cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
        fs << "classifier"
           << "{";
        classifier->write(fs);
        fs << "}";
        t.definition = QByteArray::fromStdString(fs.releaseAndGetString());
    } catch (const cv::Exception& e) {
        return makeError(
            QStringLiteral("model '%1' cannot be serialized: %2").arg(name, QString::fromStdString(e.err)));
    }
    if (t.definition.size() > TrainedModel::kMaxDefinitionBytes)
        return makeError(QStringLiteral("model '%1' is %2 MB, above the limit of %3 MB (fewer trees or a smaller "
                                        "max depth)")
                             .arg(name)
                             .arg(double(t.definition.size()) / 1e6, 0, 'f', 1)
                             .arg(double(TrainedModel::kMaxDefinitionBytes) / 1e6, 0, 'f', 0));
    QJsonObject d = provenance;
    d[QStringLiteral("classes")] = QJsonArray::fromStringList(classes);
    d[QStringLiteral("sensors")] = QJsonArray::fromStringList(sensors);
    d[QStringLiteral("features")] = QJsonArray::fromStringList(features);
    d[QStringLiteral("input_columns")] = QJsonArray::fromStringList(inputColumns);
    d[QStringLiteral("window")] = window;
    d[QStringLiteral("step")] = step;
    d[QStringLiteral("scaling")] = scaling.toJson();
    if (selection)
        d[QStringLiteral("feature_selection")] = selection->toJson();
    else
        d.remove(QStringLiteral("feature_selection"));
    if (interaction)
        d[QStringLiteral("interaction")] = interaction->toJson();
    else
        d.remove(QStringLiteral("interaction"));
    d[QStringLiteral("segmentation")] = segmentation.toJson();
    d[QStringLiteral("classifier")] = classifier->kind();
    t.description = d;
    return t;
}

void ActivityModel::probabilities(cv::Mat samples, cv::Mat& out) const {
    // A cv::Mat passed by value shares the caller's rows: scale a copy, never the caller's features.
    samples = selection ? selection->apply(samples) : samples.clone();
    scaling.apply(samples);
    classifier->probabilities(samples, out);
}

Status ActivityModel::checkStream(const StreamInfo& info) const {
    auto extractor = FeatureExtractor::create(info, sensors);
    if (!extractor) return extractor.error();
    const QStringList own = interaction ? features.mid(0, features.size() - interaction->names().size()) : features;
    if (extractor->inputColumns() != inputColumns || (!cnn && extractor->names() != own))
        return makeError(QStringLiteral("the model reads columns %1 with %2 features; this stream gives %3 with %4")
                             .arg(inputColumns.join(QStringLiteral(", ")))
                             .arg(own.size())
                             .arg(extractor->inputColumns().join(QStringLiteral(", ")))
                             .arg(extractor->size()));
    for (const QString& column : inputColumns) {
        const int i = info.columnIndex(column);
        const QString unit = info.columns[std::size_t(i)].unit;
        const QString trained = provenance.value(QStringLiteral("units")).toObject().value(column).toString();
        if (!unit.isEmpty() && !trained.isEmpty() && unit != trained)
            return makeError(
                QStringLiteral("column %1 is in '%2'; the model was trained on '%3'").arg(column, unit, trained));
    }
    return {};
}

Status ActivityModel::windowProbabilities(const StreamInfo& info, const StreamData& data,
                                          const std::vector<Window>& windows, cv::Mat& out, const Progress& progress,
                                          const PlayerContext* player) const {
    if (cnn) {
        std::vector<int> columns;
        for (const QString& c : inputColumns) {
            const int i = info.columnIndex(c);
            if (i < 0) return makeError(QStringLiteral("the stream has no column '%1'").arg(c));
            columns.push_back(i);
        }
        cv::Mat raw(int(windows.size()), cnn->channels() * cnn->length(), CV_32F);
        for (std::size_t i = 0; i < windows.size(); ++i)
            rawWindow(data, columns, windows[i].tStart, windows[i].tEnd, cnn->length(), raw.ptr<float>(int(i)));
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        progress.report(0.3, QStringLiteral("windows"));
        return cnn->probabilities(raw, out);
    }
    auto extractor = FeatureExtractor::create(info, sensors);
    if (!extractor) return extractor.error();
    if (interaction && !(player && player->session && player->player >= 0))
        return makeError(
            QStringLiteral("the model uses interaction features; the other athletes' streams of the "
                           "session were not gathered"));
    const int own = extractor->size();
    cv::Mat samples(int(windows.size()), own + (interaction ? int(interaction->names().size()) : 0), CV_32F);
    for (std::size_t i = 0; i < windows.size(); ++i) {
        extractor->compute(data, windows[i].begin, windows[i].end, samples.ptr<float>(int(i)));
        if (interaction)
            interactionFeatures(*player, *interaction, window, windows[i].centre(), samples.ptr<float>(int(i)) + own);
        if (i % 2000 == 1999) {
            if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
            progress.report(0.8 * double(i) / double(windows.size()), QStringLiteral("features"));
        }
    }
    probabilities(samples, out);
    return {};
}

Annotations intervalsFromWindows(const std::vector<double>& centres, const cv::Mat& probabilities,
                                 const QStringList& classes, double tBegin, double tEnd, int smoothing) {
    Annotations out;
    const int n = int(centres.size());
    if (n == 0 || probabilities.rows != n) return out;
    const int k = probabilities.cols;
    // Moving average of the class probabilities over 2·smoothing + 1 windows (truncated at the ends).
    std::vector<int> best(std::size_t(n), 0);
    std::vector<float> confidence(std::size_t(n), 0.0f);
    std::vector<float> sum(static_cast<std::size_t>(k));
    for (int i = 0; i < n; ++i) {
        std::fill(sum.begin(), sum.end(), 0.0f);
        const int lo = std::max(0, i - smoothing), hi = std::min(n - 1, i + smoothing);
        for (int j = lo; j <= hi; ++j)
            for (int c = 0; c < k; ++c) sum[std::size_t(c)] += probabilities.at<float>(j, c);
        const auto top = std::max_element(sum.begin(), sum.end());
        best[std::size_t(i)] = int(top - sum.begin());
        confidence[std::size_t(i)] = *top / float(hi - lo + 1);
    }
    const auto boundary = [&](int i) {  // start of window i's share
        return i == 0 ? std::min(tBegin, centres.front())
                      : 0.5 * (centres[std::size_t(i - 1)] + centres[std::size_t(i)]);
    };
    int start = 0;
    for (int i = 1; i <= n; ++i) {
        if (i < n && best[std::size_t(i)] == best[std::size_t(start)]) continue;
        Annotation a;
        a.label = classes.value(best[std::size_t(start)]);
        a.tStart = boundary(start);
        a.tEnd = i == n ? std::max(tEnd, centres.back()) : boundary(i);
        double c = 0;
        for (int j = start; j < i; ++j) c += confidence[std::size_t(j)];
        a.confidence = std::clamp(c / double(i - start), 0.0, 1.0);
        out.push_back(std::move(a));
        start = i;
    }
    return out;
}

Expected<Annotations> ActivityModel::classify(const StreamInfo& info, const StreamData& data, int smoothing,
                                              const Progress& progress, const PlayerContext* player) const {
    if (Status s = checkStream(info); !s) return s.error();
    if (segmentation.events()) {
        auto windows = segmentation.windows(info, data, window, step);
        if (!windows) return windows.error();
        Annotations out;
        if (windows->empty()) return out;
        cv::Mat p;
        if (Status s = windowProbabilities(info, data, *windows, p, progress, player); !s) return s.error();
        for (int i = 0; i < p.rows; ++i) {
            const float* row = p.ptr<float>(i);
            const auto best = int(std::max_element(row, row + p.cols) - row);
            if (classes.value(best) == segmentation.nullLabel) continue;
            Annotation a;
            a.label = classes.value(best);
            const double t = (*windows)[std::size_t(i)].centre();
            a.tStart = t - 0.5 * kEventSpan;
            a.tEnd = t + 0.5 * kEventSpan;
            a.confidence = std::clamp(double(row[best]), 0.0, 1.0);
            out.push_back(std::move(a));
        }
        return out;
    }
    const std::vector<Window> windows = slidingWindows(data, window, step);
    if (windows.empty()) return makeError(QStringLiteral("the stream has fewer than 2 samples to classify"));
    std::vector<double> centres;
    centres.reserve(windows.size());
    for (const Window& w : windows) centres.push_back(w.centre());
    cv::Mat p;
    if (Status s = windowProbabilities(info, data, windows, p, progress, player); !s) return s.error();
    progress.report(0.95, QStringLiteral("classified"));
    return intervalsFromWindows(centres, p, classes, data.t.front(), data.t.back(), std::max(0, smoothing));
}

}  // namespace athlos::activity
