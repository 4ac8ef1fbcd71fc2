// athlos train: an activity classifier from the annotations of a project's recordings, stored in the
// project (/models/<name>) with its provenance and cross-validated metrics.
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/model/Project.h"
#include "core/processing/ParameterSpec.h"
#include "core/util/Version.h"
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/CnnTraining.h"

#include <QDateTime>
#include <QFile>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonArray>
#include <cstdio>
#include <set>

namespace athlos::cli {

namespace {
Expected<double> positiveSeconds(const QCommandLineParser& parser, const QString& option) {
    bool ok = false;
    const double v = parser.value(option).toDouble(&ok);
    if (!ok || !(v > 0) || v > 3600)
        return makeError(QStringLiteral("--%1 '%2': expected a duration in s, above 0 and at most 3600")
                             .arg(option, parser.value(option)));
    return v;
}

Expected<QByteArray> readSmallFile(const QString& path, qint64 limit, const QString& option) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("--%1 %2: cannot read (%3)").arg(option, path, f.errorString()));
    if (f.size() > limit)
        return makeError(QStringLiteral("--%1 %2: %3 MB, above the limit of %4 MB")
                             .arg(option, path)
                             .arg(double(f.size()) / 1e6, 0, 'f', 1)
                             .arg(double(limit) / 1e6, 0, 'f', 0));
    return f.readAll();
}

// --classifier cnn --onnx FILE: the network trained by scripts/train_cnn.py, checked and evaluated on the
// project's annotated windows, stored like the other models.
int importCnnModel(Project& project, const QCommandLineParser& cl, const QString& modelName, const QString& stream,
                   const std::vector<activity::TrainingSource>& sources, activity::TrainingOptions options,
                   const Progress& progress, TerminalProgress& bar) {
    using namespace activity;
    const QString onnxPath = cl.value(QStringLiteral("onnx"));
    QString descriptionPath = cl.value(QStringLiteral("onnx-description"));
    if (descriptionPath.isEmpty()) {
        const QFileInfo fi(onnxPath);
        descriptionPath = fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".json"));
    }
    auto onnx = readSmallFile(onnxPath, CnnClassifier::kMaxOnnxBytes, QStringLiteral("onnx"));
    if (!onnx) return fail(onnx.message());
    auto descriptionBytes = readSmallFile(descriptionPath, 16LL * 1024 * 1024, QStringLiteral("onnx-description"));
    if (!descriptionBytes) return fail(descriptionBytes.message());
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(*descriptionBytes, &error);
    if (!doc.isObject())
        return fail(
            QStringLiteral("--onnx-description %1: not a JSON object (%2)").arg(descriptionPath, error.errorString()));
    auto model = importCnn(*onnx, doc.object(), onnxPath);
    if (!model) return fail(model.message());
    for (const TrainingSource& s : sources)
        if (Status st = model->checkStream(s.info); !st)
            return fail(QStringLiteral("%1: does not fit %2/%3: %4").arg(onnxPath, s.recording, stream, st.message()));
    // The network's own window, classes and columns; evaluated on every annotated window of the project.
    options.window = model->window;
    options.step = model->step;
    options.sensors = model->sensors;
    options.segmentation = model->segmentation;
    auto raw = buildRawDataset(sources, options, model->classes, model->cnn->length(), progress.sub(0.0, 0.5));
    if (!raw) return fail(raw.message(), raw.message() == u"cancelled" ? Cancelled : Failed);
    cv::Mat p;
    if (Status st = model->cnn->probabilities(raw->windows, p); !st)
        return fail(onnxPath + QStringLiteral(": ") + st.message());
    std::vector<int> predicted(raw->labels.size());
    for (int i = 0; i < p.rows; ++i) {
        const float* row = p.ptr<float>(i);
        predicted[std::size_t(i)] = int(std::max_element(row, row + p.cols) - row);
    }
    const Evaluation evaluation = evaluate(raw->labels, predicted, model->classes);
    bar.finish();
    std::printf("%lld windows of %g s (%d samples × %lld channels) from %lld recordings, classes: %s\n",
                qlonglong(raw->labels.size()), options.window, raw->length, qlonglong(raw->inputColumns.size()),
                qlonglong(sources.size()), qUtf8Printable(model->classes.join(QStringLiteral(", "))));
    std::printf(
        "on the project's annotated windows (not a cross-validation: the network was trained outside "
        "Athlos, on these windows if they were exported):\n%s",
        qUtf8Printable(evaluation.toText()));
    const QJsonObject training = doc.object().value(QStringLiteral("training")).toObject();
    const QJsonObject scriptCv = training.value(QStringLiteral("cross_validation")).toObject();
    if (scriptCv.contains(QStringLiteral("balanced_accuracy")))
        std::printf("cross-validation by train_cnn.py (%s): balanced accuracy %.3f\n",
                    qUtf8Printable(scriptCv.value(QStringLiteral("scheme")).toString()),
                    scriptCv.value(QStringLiteral("balanced_accuracy")).toDouble());
    QJsonArray recordings;
    for (const TrainingSource& s : sources)
        recordings.append(QJsonObject{{QStringLiteral("recording"), s.recording},
                                      {QStringLiteral("stream"), stream},
                                      {QStringLiteral("athlete"), s.athlete},
                                      {QStringLiteral("content_hash"), QString::fromLatin1(s.data->contentHash())}});
    model->provenance[QStringLiteral("input")] = stream;
    model->provenance[QStringLiteral("onnx_file")] = QFileInfo(onnxPath).fileName();
    model->provenance[QStringLiteral("evaluated_on")] = recordings;
    model->provenance[QStringLiteral("project_windows")] = evaluation.toJson();
    model->provenance[QStringLiteral("cross_validation")] =
        scriptCv.isEmpty() ? QJsonObject{{QStringLiteral("scheme"), QStringLiteral("none")}} : scriptCv;
    model->provenance[QStringLiteral("app_version")] = appVersion();
    model->provenance[QStringLiteral("created")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    auto stored = model->toStored(modelName);
    if (!stored) return fail(stored.message());
    const bool replaced = project.models().count(modelName) > 0;
    project.models()[modelName] = std::move(*stored);
    project.setModified();
    if (Status st = project.save(progress.sub(0.95, 1.0)); !st)
        return fail(st.message(), st.message() == u"cancelled" ? Cancelled : Failed);
    std::printf("%s model '%s' (cnn, %lld classes, %.1f kB ONNX)\n", replaced ? "replaced" : "stored",
                qUtf8Printable(modelName), qlonglong(model->classes.size()), double(onnx->size()) / 1e3);
    return Ok;
}
}  // namespace

int cmdTrain(const QStringList& args) {
    using namespace activity;
    CommandParser p(
        QStringLiteral("train <project> --model NAME --input STREAM [--recordings R1,R2…] [--classes C1,C2…] "
                       "[--window S] [--step S] [--classifier C] [--cv SCHEME] [--folds K] [--export-windows DIR] "
                       "[--segmentation events:tackle --interaction k=3] [--classifier cnn --onnx FILE]"),
        QStringLiteral("Train an activity classifier on sliding windows of STREAM in every recording that has it and "
                       "annotations (manual or imported), print its cross-validated balanced accuracy, per-class "
                       "recall and precision and the confusion matrix, then train on all windows and store the model "
                       "in the project (classify with: athlos run <project> classify-actions --param model=NAME). "
                       "Ctrl-C cancels and leaves the project untouched."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("model"), QStringLiteral("Name of the model to store (replaces one of that name)."),
                 QStringLiteral("NAME")});
    p.addOption({QStringLiteral("input"),
                 QStringLiteral("Stream name inside each recording, e.g. imu, or a wildcard pattern (e.g. 'sim-imu-*': "
                                "every matching stream of a recording is trained on, one per player of a team "
                                "session, with the recording's annotations)."),
                 QStringLiteral("STREAM")});
    p.addOption({QStringLiteral("recordings"), QStringLiteral("Only these recordings (default: every one)."),
                 QStringLiteral("R1,R2")});
    p.addOption({QStringLiteral("classes"), QStringLiteral("Only these labels (default: every annotated label)."),
                 QStringLiteral("C1,C2")});
    p.addOption({QStringLiteral("window"), QStringLiteral("Window length in s (default 3)."), QStringLiteral("S"),
                 QStringLiteral("3")});
    p.addOption({QStringLiteral("step"), QStringLiteral("Window step in s (default 1.5)."), QStringLiteral("S"),
                 QStringLiteral("1.5")});
    p.addOption({QStringLiteral("classifier"),
                 QStringLiteral("One of: ") + Classifier::kinds().join(QStringLiteral(", ")), QStringLiteral("C"),
                 QStringLiteral("random-forest")});
    p.addOption({QStringLiteral("vote"),
                 QStringLiteral("--classifier vote: members and weights (default "
                                "random-forest,svm,knn, equal weights)."),
                 QStringLiteral("C[:W],…")});
    p.addOption(
        {QStringLiteral("cv"),
         QStringLiteral(
             "Cross-validation: leave-one-athlete-out (default; athlete from the recording's "
             "metadata, else its name), leave-one-recording-out (more than 10 subjects: dealt into 10 folds, a subject "
             "never in its own training fold), k-fold or none."),
         QStringLiteral("SCHEME"), QStringLiteral("leave-one-athlete-out")});
    p.addOption({QStringLiteral("folds"), QStringLiteral("Folds of --cv k-fold (default 5)."), QStringLiteral("K"),
                 QStringLiteral("5")});
    p.addOption({QStringLiteral("sensors"), QStringLiteral("Sensors the features use (default acc,gyr; acc needed)."),
                 QStringLiteral("acc,gyr,mag"), QStringLiteral("acc,gyr")});
    p.addOption({QStringLiteral("trees"), QStringLiteral("Trees of the random forest (default 100)."),
                 QStringLiteral("N"), QStringLiteral("100")});
    p.addOption(
        {QStringLiteral("forest-rows"),
         QStringLiteral("Random forest: windows each part of 10 trees trains on at most, a stratified subsample "
                        "of the class-balanced windows when there are more (subbagging, Bühlmann & Yu 2002; "
                        "default 15000; 0: every window). The parts train in parallel."),
         QStringLiteral("N"), QStringLiteral("15000")});
    p.addOption({QStringLiteral("balance"),
                 QStringLiteral("Class balancing of the training windows: oversample (default: smaller classes drawn "
                                "with replacement), smote (their missing windows synthesised by SMOTE, Chawla et al. "
                                "2002, k = 5) or none."),
                 QStringLiteral("METHOD"), QStringLiteral("oversample")});
    p.addOption({QStringLiteral("select-features"),
                 QStringLiteral("Keep the K features of highest mutual information with the class (equal-frequency "
                                "bins, seed 000 §5.2), ranked inside each cross-validation training fold and on all "
                                "windows for the stored model (default 0: every feature)."),
                 QStringLiteral("K"), QStringLiteral("0")});
    p.addOption({QStringLiteral("mi-bins"),
                 QStringLiteral("Equal-frequency bins per feature of the mutual-information estimate (default 10)."),
                 QStringLiteral("B"), QStringLiteral("10")});
    p.addOption({QStringLiteral("min-label-fraction"),
                 QStringLiteral("Share of a window its label must cover to be trained on (default 0.5)."),
                 QStringLiteral("F"), QStringLiteral("0.5")});
    p.addOption({QStringLiteral("segmentation"),
                 QStringLiteral("sliding (default: windows every --step s), events:impact (beach-volleyball impact "
                                "detector, a --window s window centred on each impact) or events:tackle (rugby tackle "
                                "candidates, threshold fitted on the annotations to reach --tackle-recall). Events "
                                "outside every annotation are trained as class 'null'."),
                 QStringLiteral("KIND"), QStringLiteral("sliding")});
    p.addOption({QStringLiteral("impact-threshold"),
                 QStringLiteral("events:impact: ε_impact in m/s² (default 5.1, seed 000 §5.2)."), QStringLiteral("A"),
                 QStringLiteral("5.1")});
    p.addOption({QStringLiteral("detection-recall"),
                 QStringLiteral("events:impact: recall of the annotated actions the cost-sensitive detection tree on "
                                "the impact and swing indicators must keep, chosen by a leave-one-athlete-out grid "
                                "search over the FN:FP cost ratio (default 0.99, seed 000 §5.2); 0: no tree, every "
                                "candidate goes to the classifier."),
                 QStringLiteral("R"), QStringLiteral("0.99")});
    p.addOption({QStringLiteral("tackle-recall"),
                 QStringLiteral("events:tackle: share of the annotated events the fitted threshold detects "
                                "(default 1: all, seed 000 §5.1)."),
                 QStringLiteral("R"), QStringLiteral("1")});
    p.addOption({QStringLiteral("interaction"),
                 QStringLiteral("Multi-athlete interaction features (seed 000 §5.1.2) added to each event window: the "
                                "player's torso pitch and speed and the distance, speed and torso pitch of the k "
                                "nearest opponents. The session is the input stream's recording: athletes are its IMU "
                                "streams with an 'athlete' attribute, their positions the 'trajectory' (else "
                                "'lps-position') stream of the same athlete, opponents those of another 'team' "
                                "attribute (as simulate-rugby writes them). classify-actions gathers the same. "
                                "Optional keys: speed_span (s), reference_start, reference_duration (s, the standing "
                                "period of the torso pitch), up_axis, cutoff (Hz)."),
                 QStringLiteral("k=N[,KEY=V…]")});
    p.addOption({QStringLiteral("actors"),
                 QStringLiteral("Event segmentation in a team session (several --input streams of one recording share "
                                "its annotations, which do not say whose action it was): an annotated event is the "
                                "action of the N streams whose detector signal peaks highest inside it; the other "
                                "athletes' candidates inside it are not trained on (default 2: a tackle's carrier "
                                "and tackler)."),
                 QStringLiteral("N"), QStringLiteral("2")});
    p.addOption({QStringLiteral("export-windows"),
                 QStringLiteral("Write the labelled raw windows (windows.npy N×C×L float32, labels.npy, groups.npy, "
                                "meta.json) into DIR for scripts/train_cnn.py, and stop (nothing is trained or "
                                "stored)."),
                 QStringLiteral("DIR")});
    p.addOption({QStringLiteral("window-samples"),
                 QStringLiteral("--export-windows: samples per raw window (default: the window at the first "
                                "recording's rate)."),
                 QStringLiteral("N"), QStringLiteral("0")});
    p.addOption({QStringLiteral("onnx"),
                 QStringLiteral("--classifier cnn: the network written by scripts/train_cnn.py (at most 32 MB)."),
                 QStringLiteral("FILE")});
    p.addOption({QStringLiteral("onnx-description"),
                 QStringLiteral("--classifier cnn: its JSON description (default: FILE with .json)."),
                 QStringLiteral("FILE")});
    if (auto code = p.parse(args, 1, 1)) return *code;
    const QCommandLineParser& cl = p.parser();

    const QString modelName = cl.value(QStringLiteral("model")).trimmed();
    const QString stream = cl.value(QStringLiteral("input")).trimmed();
    if (modelName.isEmpty()) return fail(QStringLiteral("train needs --model NAME"), Usage);
    if (modelName.contains(QLatin1Char('/')) || modelName == u"." || modelName == u"..")
        return fail(QStringLiteral("--model '%1': a name without '/'").arg(modelName), Usage);
    if (stream.isEmpty()) return fail(QStringLiteral("train needs --input STREAM (e.g. imu)"), Usage);

    TrainingOptions options;
    auto window = positiveSeconds(cl, QStringLiteral("window"));
    if (!window) return fail(window.message(), Usage);
    auto step = positiveSeconds(cl, QStringLiteral("step"));
    if (!step) return fail(step.message(), Usage);
    options.window = *window;
    options.step = *step;
    options.classes = splitList(cl.value(QStringLiteral("classes")));
    options.sensors = splitList(cl.value(QStringLiteral("sensors")));
    options.validation = cl.value(QStringLiteral("cv"));
    bool ok = false;
    options.folds = cl.value(QStringLiteral("folds")).toInt(&ok);
    if (!ok || options.folds < 2) return fail(QStringLiteral("--folds: an integer of at least 2"), Usage);
    options.classifier.kind = cl.value(QStringLiteral("classifier"));
    const bool cnn = options.classifier.kind == u"cnn";
    if (!Classifier::kinds().contains(options.classifier.kind) && !cnn)
        return fail(QStringLiteral("--classifier '%1': use one of %2, cnn")
                        .arg(options.classifier.kind, Classifier::kinds().join(QStringLiteral(", "))),
                    Usage);
    const QString exportDir = cl.value(QStringLiteral("export-windows"));
    if (cnn && exportDir.isEmpty() && !cl.isSet(QStringLiteral("onnx")))
        return fail(QStringLiteral("--classifier cnn: the network is trained outside Athlos. Export the windows with "
                                   "--export-windows DIR, train with 'python3 scripts/train_cnn.py DIR --out m.onnx', "
                                   "then import it with --classifier cnn --onnx m.onnx"),
                    Usage);
    if (cl.isSet(QStringLiteral("onnx")) && !cnn)
        return fail(QStringLiteral("--onnx goes with --classifier cnn"), Usage);
    auto segmentation = Segmentation::parse(cl.value(QStringLiteral("segmentation")));
    if (!segmentation) return fail(segmentation.message(), Usage);
    options.segmentation = *segmentation;
    options.segmentation.impact.threshold = cl.value(QStringLiteral("impact-threshold")).toDouble(&ok);
    if (!ok || !(options.segmentation.impact.threshold > 0))
        return fail(QStringLiteral("--impact-threshold: a positive acceleration in m/s²"), Usage);
    options.segmentation.tackle.targetRecall = cl.value(QStringLiteral("tackle-recall")).toDouble(&ok);
    if (!ok || !(options.segmentation.tackle.targetRecall > 0) || options.segmentation.tackle.targetRecall > 1)
        return fail(QStringLiteral("--tackle-recall: a share above 0, at most 1"), Usage);
    const double detectionRecall = cl.value(QStringLiteral("detection-recall")).toDouble(&ok);
    if (!ok || detectionRecall < 0 || detectionRecall > 1)
        return fail(QStringLiteral("--detection-recall: a share from 0 (no detection tree) to 1"), Usage);
    options.segmentation.useDetectionTree = detectionRecall > 0;
    if (detectionRecall > 0) options.segmentation.detection.targetRecall = detectionRecall;
    options.rawLength = cl.value(QStringLiteral("window-samples")).toInt(&ok);
    if (!ok || options.rawLength < 0 || options.rawLength > 100000)
        return fail(QStringLiteral("--window-samples: an integer from 0 to 100000"), Usage);
    const QString balance = cl.value(QStringLiteral("balance"));
    if (balance != u"oversample" && balance != u"smote" && balance != u"none")
        return fail(QStringLiteral("--balance '%1': use oversample, smote or none").arg(balance), Usage);
    options.classifier.balance = balance != u"none";
    options.classifier.smote = balance == u"smote";
    options.classifier.trees = cl.value(QStringLiteral("trees")).toInt(&ok);
    if (!ok || options.classifier.trees < 1 || options.classifier.trees > 2000)
        return fail(QStringLiteral("--trees: an integer from 1 to 2000"), Usage);
    options.classifier.forestMaxRows = cl.value(QStringLiteral("forest-rows")).toInt(&ok);
    if (!ok || options.classifier.forestMaxRows < 0)
        return fail(QStringLiteral("--forest-rows: an integer of at least 0 (0: every window)"), Usage);
    options.selectFeatures = cl.value(QStringLiteral("select-features")).toInt(&ok);
    if (!ok || options.selectFeatures < 0 || options.selectFeatures > 100000)
        return fail(QStringLiteral("--select-features: an integer from 0 (every feature) to 100000"), Usage);
    if (options.selectFeatures > 0 && cnn)
        return fail(QStringLiteral("--select-features goes with the feature classifiers; the cnn reads raw windows"),
                    Usage);
    options.miBins = cl.value(QStringLiteral("mi-bins")).toInt(&ok);
    if (!ok || options.miBins < 2 || options.miBins > 1000)
        return fail(QStringLiteral("--mi-bins: an integer from 2 to 1000"), Usage);
    options.minLabelFraction = cl.value(QStringLiteral("min-label-fraction")).toDouble(&ok);
    if (!ok || options.minLabelFraction < 0 || options.minLabelFraction > 1)
        return fail(QStringLiteral("--min-label-fraction: a number from 0 to 1"), Usage);
    if (cl.isSet(QStringLiteral("vote"))) {
        options.classifier.voteMembers.clear();
        for (const QString& item : splitList(cl.value(QStringLiteral("vote")))) {
            const QStringList parts = item.split(QLatin1Char(':'));
            const double weight = parts.size() > 1 ? parts[1].toDouble(&ok) : 1.0;
            if (!Classifier::kinds().contains(parts[0]) || parts[0] == u"vote" || (parts.size() > 1 && !ok) ||
                weight < 0)
                return fail(QStringLiteral("--vote '%1': expected CLASSIFIER[:WEIGHT]").arg(item), Usage);
            options.classifier.voteMembers << parts[0];
            options.classifier.voteWeights.push_back(weight);
        }
    }
    if (cl.isSet(QStringLiteral("interaction"))) {
        auto interaction = InteractionOptions::parse(cl.value(QStringLiteral("interaction")));
        if (!interaction) return fail(interaction.message(), Usage);
        if (!options.segmentation.events())
            return fail(QStringLiteral("--interaction goes with event segmentation (--segmentation events:tackle)"),
                        Usage);
        if (cnn) return fail(QStringLiteral("--interaction goes with the feature classifiers, not the cnn"), Usage);
        options.interaction = *interaction;
    }
    options.actors = cl.value(QStringLiteral("actors")).toInt(&ok);
    if (!ok || options.actors < 1 || options.actors > 100)
        return fail(QStringLiteral("--actors: an integer from 1 to 100"), Usage);
    const bool validate = options.validation != u"none";

    auto project = openForChange(p.positional()[0]);
    if (!project) return fail(project.message());
    auto sources = trainingSources(**project, stream, splitList(cl.value(QStringLiteral("recordings"))));
    if (!sources) return fail(sources.message());

    TerminalProgress bar(QStringLiteral("train"));
    const Progress progress = bar.progress();
    if (!exportDir.isEmpty()) {
        auto raw = buildRawDataset(*sources, options, {}, 0, progress);
        if (!raw) return fail(raw.message(), raw.message() == u"cancelled" ? Cancelled : Failed);
        if (Status s = exportWindows(*raw, *sources, options, exportDir); !s) return fail(s.message());
        bar.finish();
        std::printf(
            "exported %lld windows (%lld channels × %d samples, %g s, step %g s) of %lld subjects to %s, "
            "classes: %s\n",
            qlonglong(raw->labels.size()), qlonglong(raw->inputColumns.size()), raw->length, options.window,
            options.step, qlonglong(raw->subjects.size()), qUtf8Printable(exportDir),
            qUtf8Printable(raw->classes.join(QStringLiteral(", "))));
        return Ok;
    }
    if (cnn) return importCnnModel(**project, cl, modelName, stream, *sources, options, progress, bar);
    if (options.interaction)
        if (Status s = attachInteraction(**project, *sources, *options.interaction, progress.sub(0.0, 0.05)); !s)
            return fail(s.message(), s.message() == u"cancelled" ? Cancelled : Failed);
    auto dataset = buildDataset(*sources, options, progress.sub(0.05, 0.2));
    if (!dataset) return fail(dataset.message(), dataset.message() == u"cancelled" ? Cancelled : Failed);
    if (options.interaction)
        std::printf(
            "interaction features: torso pitch and speed of the player, distance, speed and torso pitch of "
            "the %d nearest opponents\n",
            options.interaction->neighbours);
    std::set<QString> recordingNames;
    for (const TrainingSource& s : *sources) recordingNames.insert(s.recording);
    const QString from =
        recordingNames.size() == sources->size()
            ? QStringLiteral("%1 recordings").arg(sources->size())
            : QStringLiteral("%1 streams of %2 recordings").arg(sources->size()).arg(recordingNames.size());
    std::printf("%lld windows of %g s (step %g s) from %s, %lld features, classes: %s\n",
                qlonglong(dataset->labels.size()), options.window, options.step, qUtf8Printable(from),
                qlonglong(dataset->features.size()), qUtf8Printable(dataset->classes.join(QStringLiteral(", "))));
    if (dataset->segmentation.events())
        std::printf("segmentation %s: windows of %g s centred on detected events (threshold %.3g m/s²)\n",
                    qUtf8Printable(dataset->segmentation.kind), options.window,
                    dataset->segmentation.kind == u"events:tackle" ? dataset->segmentation.tackle.threshold
                                                                   : dataset->segmentation.impact.threshold);
    if (const auto& tree = dataset->segmentation.detectionTree; tree)
        std::printf("%s", qUtf8Printable(tree->summary()));

    QJsonObject validation{{QStringLiteral("scheme"), options.validation}};
    if (validate) {
        auto groups = foldGroups(*dataset, *sources, options);
        if (!groups) return fail(groups.message(), Usage);
        auto evaluation = crossValidate(*dataset, *groups, options, progress.sub(0.2, 0.85));
        if (!evaluation) return fail(evaluation.message(), evaluation.message() == u"cancelled" ? Cancelled : Failed);
        bar.finish();
        const auto folds = std::set<int>(groups->begin(), groups->end()).size();
        std::printf("cross-validation (%s, %s, %zu folds):\n%s", qUtf8Printable(options.validation),
                    qUtf8Printable(options.classifier.kind), folds, qUtf8Printable(evaluation->toText()));
        validation = evaluation->toJson();
        validation[QStringLiteral("scheme")] = options.validation;
        if (options.validation == u"k-fold") validation[QStringLiteral("folds")] = options.folds;
    }
    auto model = trainModel(*dataset, options, progress.sub(0.85, 1.0));
    if (!model) return fail(model.message());
    if (progress.isCancelled()) return fail(QStringLiteral("cancelled"), Cancelled);
    bar.finish();
    if (model->selection) {
        std::printf(
            "selected the %d of %lld features of highest mutual information with the class (all windows, "
            "%d equal-frequency bins):\n%s",
            model->selection->size(), qlonglong(dataset->features.size()), options.miBins,
            qUtf8Printable(model->selection->toText(20)));
        if (model->selection->size() > 20)
            std::printf("  … (all %d in the model's description)\n", model->selection->size());
    } else {
        std::printf(
            "features of highest mutual information with the class (all windows, %d equal-frequency bins; "
            "--select-features K keeps the top K):\n%s",
            options.miBins, qUtf8Printable(rankFeatures(*dataset, options).toText(10)));
    }
    progress.report(0.95, QStringLiteral("storing"));

    QJsonArray training;
    std::vector<long long> windowsPerSource(sources->size(), 0);
    for (int s : dataset->source) windowsPerSource[std::size_t(s)]++;
    for (std::size_t i = 0; i < sources->size(); ++i) {
        const TrainingSource& s = (*sources)[i];
        training.append(QJsonObject{{QStringLiteral("recording"), s.recording},
                                    {QStringLiteral("stream"), s.info.name},
                                    {QStringLiteral("athlete"), s.athlete},
                                    {QStringLiteral("content_hash"), QString::fromLatin1(s.data->contentHash())},
                                    {QStringLiteral("windows"), double(windowsPerSource[i])}});
    }
    const QJsonObject parameters = trainingParameters(options);
    model->provenance[QStringLiteral("input")] = stream;
    model->provenance[QStringLiteral("parameters")] = parameters;
    model->provenance[QStringLiteral("training")] = training;
    if (options.interaction)
        model->provenance[QStringLiteral("interaction_streams")] = interactionStreams(*sources);
    else
        model->provenance.remove(QStringLiteral("interaction_streams"));
    model->provenance[QStringLiteral("windows")] = double(dataset->labels.size());
    model->provenance[QStringLiteral("cross_validation")] = validation;
    model->provenance[QStringLiteral("app_version")] = appVersion();
    model->provenance[QStringLiteral("created")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    auto stored = model->toStored(modelName);
    if (!stored) return fail(stored.message());
    const bool replaced = (*project)->models().count(modelName) > 0;
    (*project)->models()[modelName] = std::move(*stored);
    (*project)->setModified();
    if (Status s = (*project)->save(progress.sub(0.95, 1.0)); !s)
        return fail(s.message(), s.message() == u"cancelled" ? Cancelled : Failed);
    bar.finish();
    std::printf("%s model '%s' (%s, %lld classes, %.1f kB)\n", replaced ? "replaced" : "stored",
                qUtf8Printable(modelName), qUtf8Printable(options.classifier.kind), qlonglong(dataset->classes.size()),
                double((*project)->models()[modelName].definition.size()) / 1e3);
    return Ok;
}

}  // namespace athlos::cli
