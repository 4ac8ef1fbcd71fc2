#include "plugins/activity/ActivityTraining.h"

#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/Windows.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace athlos::activity {

bool isGroundTruth(const Annotation& annotation) {
    return annotation.source == QLatin1String("manual") || annotation.source == QLatin1String("import") ||
           annotation.source.startsWith(QLatin1String("simulate-"));
}

Expected<std::vector<TrainingSource>> trainingSources(const Project& project, const QString& stream,
                                                      const QStringList& recordings) {
    std::vector<TrainingSource> sources;
    for (const QString& name : recordings)
        if (!project.recording(name)) return makeError(QStringLiteral("--recordings: no recording '%1'").arg(name));
    const bool pattern = stream.contains(QLatin1Char('*')) || stream.contains(QLatin1Char('?'));
    const QRegularExpression glob(QRegularExpression::wildcardToRegularExpression(stream));
    for (const auto& [name, rec] : project.recordings()) {
        if (!recordings.isEmpty() && !recordings.contains(name)) continue;
        Annotations truth;
        for (const Annotation& a : rec.annotations)
            if (isGroundTruth(a) && a.tEnd > a.tStart) truth.push_back(a);
        if (truth.empty()) continue;
        for (const auto& [streamName, s] : rec.streams) {
            if (pattern ? !glob.match(streamName).hasMatch() : streamName != stream) continue;
            auto data = s.data();
            if (!data) return makeError(QStringLiteral("%1/%2: %3").arg(name, streamName, data.message()));
            TrainingSource source;
            source.recording = name;
            source.athlete = s.info().attributes.value(QStringLiteral("athlete")).toString();
            if (source.athlete.isEmpty()) source.athlete = rec.metadata.value(QStringLiteral("athlete")).toString(name);
            if (source.athlete.isEmpty()) source.athlete = name;
            source.info = s.info();
            source.info.name = streamName;
            source.data = *data;
            source.annotations = truth;
            sources.push_back(std::move(source));
        }
    }
    if (sources.empty())
        return makeError(QStringLiteral("no recording has both a stream '%1' and annotations to train on").arg(stream));
    return sources;
}

Expected<std::vector<TrainingSource>> attributeSessionEvents(std::vector<TrainingSource> sources,
                                                             const TrainingOptions& options) {
    const Segmentation& seg = options.segmentation;
    if (!seg.events()) return sources;
    std::map<QString, std::vector<std::size_t>> byRecording;
    for (std::size_t i = 0; i < sources.size(); ++i) byRecording[sources[i].recording].push_back(i);
    for (const auto& [recording, members] : byRecording) {
        if (members.size() < 2 || int(members.size()) <= options.actors) continue;
        // peaks[m][a]: the detector signal's maximum of member m inside annotation a.
        std::vector<std::vector<double>> peaks;
        for (std::size_t m : members) {
            const TrainingSource& s = sources[m];
            auto signal = seg.kind == QLatin1String("events:tackle")
                              ? TackleDetector::signal(s.info, *s.data, seg.tackle)
                              : ImpactDetector::signal(s.info, *s.data, seg.impact);
            if (!signal) return makeError(QStringLiteral("%1/%2: %3").arg(s.recording, s.info.name, signal.message()));
            peaks.push_back(TackleDetector::annotationPeaks(*s.data, *signal, s.annotations));
        }
        const Annotations shared = sources[members.front()].annotations;
        std::vector<Annotations> kept(members.size()), excluded(members.size());
        for (std::size_t a = 0; a < shared.size(); ++a) {
            if (shared[a].label == seg.nullLabel) {
                for (auto& k : kept) k.push_back(shared[a]);
                continue;
            }
            std::vector<std::size_t> order(members.size());
            for (std::size_t m = 0; m < order.size(); ++m) order[m] = m;
            const auto peak = [&](std::size_t m) { return std::isfinite(peaks[m][a]) ? peaks[m][a] : -1.0; };
            std::stable_sort(order.begin(), order.end(),
                             [&](std::size_t x, std::size_t y) { return peak(x) > peak(y); });
            for (std::size_t r = 0; r < order.size(); ++r)
                (int(r) < options.actors ? kept : excluded)[order[r]].push_back(shared[a]);
        }
        for (std::size_t m = 0; m < members.size(); ++m) {
            sources[members[m]].annotations = std::move(kept[m]);
            sources[members[m]].excluded = std::move(excluded[m]);
        }
    }
    return sources;
}

Status attachInteraction(const Project& project, std::vector<TrainingSource>& sources,
                         const InteractionOptions& options, const Progress& progress) {
    std::map<QString, std::shared_ptr<const InteractionSession>> sessions;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        TrainingSource& s = sources[i];
        const Recording* rec = project.recording(s.recording);
        if (!rec) return makeError(QStringLiteral("no recording '%1'").arg(s.recording));
        auto& session = sessions[s.recording];
        if (!session) {
            auto player = gatherPlayer(*rec, s.info.name, options);
            if (!player) return player.error();
            session = player->session;
        }
        s.interaction.session = session;
        s.interaction.player = session->playerOf(s.info.name);
        if (s.interaction.player < 0)
            return makeError(QStringLiteral("interaction features: stream '%1/%2' has no 'athlete' attribute naming "
                                            "whose IMU it is")
                                 .arg(s.recording, s.info.name));
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        progress.report(double(i + 1) / double(sources.size()), QStringLiteral("interaction"));
    }
    return {};
}

QJsonArray interactionStreams(const std::vector<TrainingSource>& sources) {
    QJsonArray out;
    std::set<const InteractionSession*> seen;
    for (const TrainingSource& s : sources) {
        if (!s.interaction.session || !seen.insert(s.interaction.session.get()).second) continue;
        for (const ProvenanceInput& read : s.interaction.session->streams)
            out.append(QJsonObject{{QStringLiteral("stream"), read.name},
                                   {QStringLiteral("content_hash"), QString::fromLatin1(read.hash)}});
    }
    return out;
}

QStringList trainingClasses(const std::vector<TrainingSource>& sources, const TrainingOptions& options) {
    // As given, else every ground-truth label (sorted, so the order does not depend on the data).
    if (!options.classes.isEmpty()) return options.classes;
    std::set<QString> labels;
    for (const auto& s : sources)
        for (const auto& a : s.annotations) labels.insert(a.label);
    if (options.segmentation.events()) labels.insert(options.segmentation.nullLabel);
    QStringList classes;
    for (const auto& l : labels) classes << l;
    return classes;
}

namespace {
// The impact candidates of every source labelled relevant (inside an annotation of one of `classes`
// other than the null label) or not, grouped by athlete, and the detection tree trained on them.
Expected<Segmentation> fitDetectionTree(const std::vector<TrainingSource>& sources, Segmentation s,
                                        const QStringList& classes) {
    if (!s.useDetectionTree || s.detectionTree) return s;
    std::vector<DetectionTree::Sample> samples;
    std::map<QString, int> athletes;
    for (const TrainingSource& source : sources) {
        auto events = ImpactDetector::detect(source.info, *source.data, s.impact);
        if (!events)
            return makeError(QStringLiteral("%1/%2: %3").arg(source.recording, source.info.name, events.message()));
        const int group = athletes.emplace(source.athlete, int(athletes.size())).first->second;
        for (const DetectedEvent& e : *events) {
            bool relevant = false;
            for (const Annotation& a : source.annotations)
                relevant = relevant || (a.tStart <= e.t && e.t <= a.tEnd && a.label != s.nullLabel &&
                                        (classes.isEmpty() || classes.contains(a.label)));
            samples.push_back({e.impact, e.swing, relevant, group});
        }
    }
    auto tree = DetectionTree::train(samples, s.detection);
    if (!tree) return makeError(QStringLiteral("events:impact: ") + tree.message());
    s.detectionTree = std::move(*tree);
    return s;
}
}  // namespace

Expected<Segmentation> fitSegmentation(const std::vector<TrainingSource>& sources, const TrainingOptions& options,
                                       const QStringList& classes) {
    Segmentation s = options.segmentation;
    if (s.kind == QLatin1String("events:impact")) return fitDetectionTree(sources, std::move(s), classes);
    if (s.kind != QLatin1String("events:tackle") || s.tackle.threshold > 0) return s;
    std::vector<double> peaks;
    for (const TrainingSource& source : sources) {
        auto signal = TackleDetector::signal(source.info, *source.data, s.tackle);
        if (!signal)
            return makeError(QStringLiteral("%1/%2: %3").arg(source.recording, source.info.name, signal.message()));
        Annotations events;
        for (const Annotation& a : source.annotations)
            if (a.label != s.nullLabel && (classes.isEmpty() || classes.contains(a.label))) events.push_back(a);
        const auto p = TackleDetector::annotationPeaks(*source.data, *signal, events);
        peaks.insert(peaks.end(), p.begin(), p.end());
    }
    auto threshold = TackleDetector::fitThreshold(std::move(peaks), s.tackle);
    if (!threshold) return threshold.error();
    s.tackle.threshold = *threshold;
    return s;
}

Expected<std::vector<LabelledWindow>> labelledWindows(const TrainingSource& source, const TrainingOptions& options,
                                                      const Segmentation& segmentation, const QStringList& classes) {
    std::vector<LabelledWindow> out;
    if (!segmentation.events()) {
        for (const Window& w : slidingWindows(*source.data, options.window, options.step)) {
            const QString label = windowLabel(w, source.annotations, classes, options.minLabelFraction);
            if (!label.isEmpty()) out.push_back({w, int(classes.indexOf(label))});
        }
        return out;
    }
    auto windows = segmentation.windows(source.info, *source.data, options.window, options.step);
    if (!windows)
        return makeError(QStringLiteral("%1/%2: %3").arg(source.recording, source.info.name, windows.message()));
    for (const Window& w : *windows) {
        const double t = w.centre();
        if (std::any_of(source.excluded.begin(), source.excluded.end(),
                        [t](const Annotation& a) { return a.tStart <= t && t <= a.tEnd; }))
            continue;  // another athlete's annotated event: this candidate is neither that class nor null
        QString label = segmentation.nullLabel;
        for (const Annotation& a : source.annotations)
            if (a.tStart <= t && t <= a.tEnd && a.label != segmentation.nullLabel &&
                (classes.isEmpty() || classes.contains(a.label))) {
                label = a.label;
                break;
            }
        const int index = int(classes.indexOf(label));
        if (index >= 0) out.push_back({w, index});
    }
    return out;
}

Expected<Dataset> buildDataset(const std::vector<TrainingSource>& given, const TrainingOptions& options,
                               const Progress& progress) {
    if (options.actors < 1) return makeError(QStringLiteral("--actors must be at least 1"));
    auto attributed = attributeSessionEvents(given, options);
    if (!attributed) return attributed.error();
    const std::vector<TrainingSource>& sources = *attributed;
    Dataset d;
    d.sensors = options.sensors;
    if (!(options.window > 0) || !(options.step > 0))
        return makeError(QStringLiteral("--window and --step must be positive (s)"));
    if (options.interaction && !options.segmentation.events())
        return makeError(
            QStringLiteral("--interaction goes with event segmentation (--segmentation events:tackle): "
                           "the features describe the opponents at a detected event"));
    d.classes = trainingClasses(sources, options);
    auto segmentation = fitSegmentation(sources, options, d.classes);
    if (!segmentation) return segmentation.error();
    d.segmentation = *segmentation;
    std::vector<float> rows;
    for (std::size_t si = 0; si < sources.size(); ++si) {
        const TrainingSource& s = sources[si];
        auto extractor = FeatureExtractor::create(s.info, options.sensors);
        if (!extractor)
            return makeError(QStringLiteral("%1/%2: %3").arg(s.recording, s.info.name, extractor.message()));
        if (d.features.isEmpty()) {
            d.features = extractor->names();
            if (options.interaction) d.features << options.interaction->names();
            d.inputColumns = extractor->inputColumns();
            for (const QString& c : d.inputColumns)
                d.units[c] = s.info.columns[std::size_t(s.info.columnIndex(c))].unit;
        } else {
            for (const QString& c : d.inputColumns) {
                const QString unit = s.info.columns[std::size_t(s.info.columnIndex(c))].unit;
                if (unit != d.units.value(c).toString())
                    return makeError(QStringLiteral("%1/%2: column %3 is in '%4', other recordings in '%5'")
                                         .arg(s.recording, s.info.name, c, unit, d.units.value(c).toString()));
            }
        }
        if (options.interaction && !s.interaction.session)
            return makeError(QStringLiteral("%1/%2: the interaction features were not gathered (attachInteraction)")
                                 .arg(s.recording, s.info.name));
        const int imuCount = extractor->size();
        std::vector<float> features(
            std::size_t(imuCount + (options.interaction ? options.interaction->names().size() : 0)));
        auto windows = labelledWindows(s, options, d.segmentation, d.classes);
        if (!windows) return windows.error();
        for (const LabelledWindow& lw : *windows) {
            extractor->compute(*s.data, lw.window.begin, lw.window.end, features.data());
            if (options.interaction)
                interactionFeatures(s.interaction, *options.interaction, options.window, lw.window.centre(),
                                    features.data() + imuCount);
            rows.insert(rows.end(), features.begin(), features.end());
            d.labels.push_back(lw.label);
            d.source.push_back(int(si));
        }
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        progress.report(double(si + 1) / double(sources.size()), QStringLiteral("features"));
    }
    if (d.labels.empty())
        return makeError(QStringLiteral("no window of %1 s is covered by an annotation to at least %2 %")
                             .arg(options.window)
                             .arg(100 * options.minLabelFraction));
    std::set<int> present(d.labels.begin(), d.labels.end());
    if (present.size() < 2)
        return makeError(QStringLiteral("the windows have only one class ('%1'); training needs at least two")
                             .arg(d.classes.value(*present.begin())));
    // Classes given but never seen are dropped, so the model does not predict what it never learnt.
    QStringList seen;
    std::vector<int> remap(std::size_t(d.classes.size()), -1);
    for (int c : present) {
        remap[std::size_t(c)] = int(seen.size());
        seen << d.classes[c];
    }
    for (int& l : d.labels) l = remap[std::size_t(l)];
    d.classes = seen;
    d.samples = cv::Mat(int(d.labels.size()), int(d.features.size()), CV_32F, rows.data()).clone();
    return d;
}

Evaluation evaluate(const std::vector<int>& truth, const std::vector<int>& predicted, const QStringList& classes) {
    Evaluation e;
    e.classes = classes;
    const auto k = std::size_t(classes.size());
    e.confusion.assign(k, std::vector<long long>(k, 0));
    long long correct = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        e.confusion[std::size_t(truth[i])][std::size_t(predicted[i])]++;
        correct += truth[i] == predicted[i];
    }
    e.accuracy = truth.empty() ? 0.0 : double(correct) / double(truth.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double sum = 0;
    int present = 0;
    for (std::size_t c = 0; c < k; ++c) {
        long long row = 0, column = 0;
        for (std::size_t j = 0; j < k; ++j) {
            row += e.confusion[c][j];
            column += e.confusion[j][c];
        }
        e.recall.push_back(row ? double(e.confusion[c][c]) / double(row) : nan);
        e.precision.push_back(column ? double(e.confusion[c][c]) / double(column) : nan);
        if (row) {
            sum += e.recall.back();
            ++present;
        }
    }
    e.balancedAccuracy = present ? sum / present : 0.0;
    return e;
}

QJsonObject Evaluation::toJson() const {
    QJsonArray confusionJson, recallJson, precisionJson;
    for (const auto& row : confusion) {
        QJsonArray r;
        for (long long v : row) r.append(double(v));
        confusionJson.append(r);
    }
    const auto number = [](double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); };
    for (double v : recall) recallJson.append(number(v));
    for (double v : precision) precisionJson.append(number(v));
    return {{QStringLiteral("balanced_accuracy"), balancedAccuracy},
            {QStringLiteral("accuracy"), accuracy},
            {QStringLiteral("recall"), recallJson},
            {QStringLiteral("precision"), precisionJson},
            {QStringLiteral("confusion"), confusionJson}};
}

QString Evaluation::toText() const {
    QString out;
    out +=
        QStringLiteral("balanced accuracy %1, accuracy %2\n").arg(balancedAccuracy, 0, 'f', 3).arg(accuracy, 0, 'f', 3);
    int width = 9;
    for (const QString& c : classes) width = std::max(width, int(c.size()) + 4);
    out += QStringLiteral("%1 %2 %3\n")
               .arg(QStringLiteral("class"), -width)
               .arg(QStringLiteral("recall"), 7)
               .arg(QStringLiteral("precision"), 10);
    const auto cell = [](double v) { return std::isfinite(v) ? QString::number(v, 'f', 3) : QStringLiteral("-"); };
    for (qsizetype c = 0; c < classes.size(); ++c)
        out += QStringLiteral("%1 %2 %3\n")
                   .arg(classes[c], -width)
                   .arg(cell(recall[std::size_t(c)]), 7)
                   .arg(cell(precision[std::size_t(c)]), 10);
    out += QStringLiteral("confusion (rows: annotated, columns: predicted)\n%1").arg(QString(), width);
    for (qsizetype c = 0; c < classes.size(); ++c) out += QStringLiteral(" %1").arg(QString::number(c), 7);
    out += QLatin1Char('\n');
    for (qsizetype c = 0; c < classes.size(); ++c) {
        out += QStringLiteral("%1").arg(QString::number(c) + QLatin1Char(' ') + classes[c], -width);
        for (long long v : confusion[std::size_t(c)]) out += QStringLiteral(" %1").arg(v, 7);
        out += QLatin1Char('\n');
    }
    return out;
}

Expected<std::vector<int>> foldGroups(const Dataset& dataset, const std::vector<TrainingSource>& sources,
                                      const TrainingOptions& options) {
    std::vector<int> groups(dataset.source.size());
    const QString& scheme = options.validation;
    if (scheme == QLatin1String("leave-one-recording-out")) {
        for (std::size_t i = 0; i < groups.size(); ++i) groups[i] = dataset.source[i];
    } else if (scheme == QLatin1String("leave-one-athlete-out")) {
        QStringList athletes;
        for (const auto& s : sources)
            if (!athletes.contains(s.athlete)) athletes << s.athlete;
        for (std::size_t i = 0; i < groups.size(); ++i)
            groups[i] = int(athletes.indexOf(sources[std::size_t(dataset.source[i])].athlete));
    } else if (scheme == QLatin1String("k-fold")) {
        if (options.folds < 2) return makeError(QStringLiteral("--folds must be at least 2"));
        for (std::size_t i = 0; i < groups.size(); ++i) groups[i] = dataset.source[i] % options.folds;
        return groups;
    } else {
        return makeError(
            QStringLiteral("--cv '%1': use leave-one-athlete-out, leave-one-recording-out or k-fold").arg(scheme));
    }
    // More subjects than maxGroups: whole subjects (recordings) dealt into maxGroups folds, so that
    // 50 people do not mean 50 trainings; a subject is still never in its own training fold.
    if (options.maxGroups > 1)
        for (int& g : groups) g %= options.maxGroups;
    return groups;
}

Expected<Evaluation> crossValidate(const Dataset& dataset, const std::vector<int>& groups,
                                   const TrainingOptions& options, const Progress& progress) {
    std::set<int> ids(groups.begin(), groups.end());
    if (ids.size() < 2)
        return makeError(QStringLiteral("cross-validation (%1) needs at least two groups; there is one "
                                        "(use --cv k-fold with several recordings, or --cv none)")
                             .arg(options.validation));
    std::vector<int> predicted(dataset.labels.size(), 0);
    int done = 0;
    for (int id : ids) {
        std::vector<int> trainRows, testRows;
        for (std::size_t i = 0; i < groups.size(); ++i) (groups[i] == id ? testRows : trainRows).push_back(int(i));
        cv::Mat train(int(trainRows.size()), dataset.samples.cols, CV_32F);
        std::vector<int> trainLabels;
        for (std::size_t i = 0; i < trainRows.size(); ++i) {
            dataset.samples.row(trainRows[i]).copyTo(train.row(int(i)));
            trainLabels.push_back(dataset.labels[std::size_t(trainRows[i])]);
        }
        cv::Mat test(int(testRows.size()), dataset.samples.cols, CV_32F);
        for (std::size_t i = 0; i < testRows.size(); ++i) dataset.samples.row(testRows[i]).copyTo(test.row(int(i)));
        if (options.selectFeatures > 0 && options.selectFeatures < train.cols) {
            // Ranked on this fold's training windows only: selecting on all windows would let the test
            // fold pick the features it is scored with.
            const FeatureSelection selection =
                FeatureSelection::fit(train, trainLabels, int(dataset.classes.size()), options.selectFeatures,
                                      dataset.features, options.miBins);
            train = selection.apply(train);
            test = selection.apply(test);
        }
        const RobustScaling scaling = RobustScaling::fit(train);
        scaling.apply(train);
        scaling.apply(test);
        // The fold's classifier reports inside this fold's share of the progress.
        const double begin = double(done) / double(ids.size()), end = double(done + 1) / double(ids.size());
        const Progress fold(
            [&progress, begin, end](double f, const QString&) {
                progress.report(begin + (end - begin) * f, QStringLiteral("cross-validation"));
            },
            progress.token());
        auto classifier = Classifier::train(train, trainLabels, int(dataset.classes.size()), options.classifier, fold);
        if (!classifier) return classifier.error();
        cv::Mat p;
        classifier->probabilities(test, p);
        for (int i = 0; i < p.rows; ++i) {
            const float* row = p.ptr<float>(i);
            predicted[std::size_t(testRows[std::size_t(i)])] = int(std::max_element(row, row + p.cols) - row);
        }
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        progress.report(double(++done) / double(ids.size()), QStringLiteral("cross-validation"));
    }
    return evaluate(dataset.labels, predicted, dataset.classes);
}

Expected<ActivityModel> trainModel(const Dataset& dataset, const TrainingOptions& options, const Progress& progress) {
    ActivityModel m;
    m.classes = dataset.classes;
    m.sensors = dataset.sensors;
    m.features = dataset.features;
    m.inputColumns = dataset.inputColumns;
    m.window = options.window;
    m.step = options.step;
    cv::Mat samples = dataset.samples.clone();
    if (options.selectFeatures > 0 && options.selectFeatures < samples.cols) {
        m.selection = FeatureSelection::fit(samples, dataset.labels, int(dataset.classes.size()),
                                            options.selectFeatures, dataset.features, options.miBins);
        samples = m.selection->apply(samples);
    }
    m.scaling = RobustScaling::fit(samples);
    m.scaling.apply(samples);
    auto classifier =
        Classifier::train(samples, dataset.labels, int(dataset.classes.size()), options.classifier, progress);
    if (!classifier) return classifier.error();
    m.classifier = std::move(*classifier);
    m.segmentation = dataset.segmentation;
    m.interaction = options.interaction;
    m.provenance[QStringLiteral("units")] = dataset.units;
    return m;
}

FeatureSelection rankFeatures(const Dataset& dataset, const TrainingOptions& options) {
    return FeatureSelection::fit(dataset.samples, dataset.labels, int(dataset.classes.size()), 0, dataset.features,
                                 options.miBins);
}

QJsonObject trainingParameters(const TrainingOptions& options) {
    const ClassifierOptions& c = options.classifier;
    QJsonObject parameters{
        {QStringLiteral("trees"), c.trees},
        {QStringLiteral("max_depth"), c.maxDepth},
        {QStringLiteral("neighbours"), c.neighbours},
        {QStringLiteral("balanced"), c.balance},
        {QStringLiteral("balancing"),
         c.balance ? (c.smote ? QStringLiteral("smote") : QStringLiteral("oversample")) : QStringLiteral("none")},
        {QStringLiteral("min_label_fraction"), options.minLabelFraction},
        {QStringLiteral("select_features"), options.selectFeatures},
        {QStringLiteral("mi_bins"), options.miBins},
        {QStringLiteral("seed"), double(c.seed)}};
    if (options.interaction) parameters[QStringLiteral("interaction")] = options.interaction->toJson();
    if (options.segmentation.events()) parameters[QStringLiteral("actors")] = options.actors;
    if (c.kind == QLatin1String("random-forest") ||
        (c.kind == QLatin1String("vote") && c.voteMembers.contains(QStringLiteral("random-forest")))) {
        parameters[QStringLiteral("forest_trees_per_part")] = c.forestTreesPerPart;
        parameters[QStringLiteral("forest_max_rows")] = c.forestMaxRows;
    }
    if (c.kind == QLatin1String("vote")) {
        QJsonArray members;
        for (qsizetype i = 0; i < c.voteMembers.size(); ++i)
            members.append(QJsonObject{{QStringLiteral("classifier"), c.voteMembers[i]},
                                       {QStringLiteral("weight"),
                                        std::size_t(i) < c.voteWeights.size() ? c.voteWeights[std::size_t(i)] : 1.0}});
        parameters[QStringLiteral("vote")] = members;
    }
    return parameters;
}

}  // namespace athlos::activity
