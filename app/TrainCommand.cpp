// athlos train: an activity classifier from the annotations of a project's recordings, stored in the
// project (/models/<name>) with its provenance and cross-validated metrics.
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/model/Project.h"
#include "core/processing/ParameterSpec.h"
#include "core/util/Version.h"
#include "plugins/activity/ActivityTraining.h"

#include <QDateTime>
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
}  // namespace

int cmdTrain(const QStringList& args) {
    using namespace activity;
    CommandParser p(
        QStringLiteral("train <project> --model NAME --input STREAM [--recordings R1,R2…] [--classes C1,C2…] "
                       "[--window S] [--step S] [--classifier C] [--cv SCHEME] [--folds K]"),
        QStringLiteral("Train an activity classifier on sliding windows of STREAM in every recording that has it and "
                       "annotations (manual or imported), print its cross-validated balanced accuracy, per-class "
                       "recall and precision and the confusion matrix, then train on all windows and store the model "
                       "in the project (classify with: athlos run <project> classify-actions --param model=NAME). "
                       "Ctrl-C cancels and leaves the project untouched."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("model"), QStringLiteral("Name of the model to store (replaces one of that name)."),
                 QStringLiteral("NAME")});
    p.addOption({QStringLiteral("input"), QStringLiteral("Stream name inside each recording, e.g. imu."),
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
    p.addOption({QStringLiteral("min-label-fraction"),
                 QStringLiteral("Share of a window its label must cover to be trained on (default 0.5)."),
                 QStringLiteral("F"), QStringLiteral("0.5")});
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
    if (!Classifier::kinds().contains(options.classifier.kind))
        return fail(QStringLiteral("--classifier '%1': use one of %2")
                        .arg(options.classifier.kind, Classifier::kinds().join(QStringLiteral(", "))),
                    Usage);
    options.classifier.trees = cl.value(QStringLiteral("trees")).toInt(&ok);
    if (!ok || options.classifier.trees < 1 || options.classifier.trees > 2000)
        return fail(QStringLiteral("--trees: an integer from 1 to 2000"), Usage);
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
    const bool validate = options.validation != u"none";

    auto project = openForChange(p.positional()[0]);
    if (!project) return fail(project.message());
    auto sources = trainingSources(**project, stream, splitList(cl.value(QStringLiteral("recordings"))));
    if (!sources) return fail(sources.message());

    TerminalProgress bar(QStringLiteral("train"));
    const Progress progress = bar.progress();
    auto dataset = buildDataset(*sources, options, progress.sub(0.0, 0.2));
    if (!dataset) return fail(dataset.message(), dataset.message() == u"cancelled" ? Cancelled : Failed);
    std::printf("%lld windows of %g s (step %g s) from %lld recordings, %lld features, classes: %s\n",
                qlonglong(dataset->labels.size()), options.window, options.step, qlonglong(sources->size()),
                qlonglong(dataset->features.size()), qUtf8Printable(dataset->classes.join(QStringLiteral(", "))));

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
    auto model = trainModel(*dataset, options);
    if (!model) return fail(model.message());
    if (progress.isCancelled()) return fail(QStringLiteral("cancelled"), Cancelled);
    progress.report(0.95, QStringLiteral("storing"));

    QJsonArray training;
    std::vector<long long> windowsPerSource(sources->size(), 0);
    for (int s : dataset->source) windowsPerSource[std::size_t(s)]++;
    for (std::size_t i = 0; i < sources->size(); ++i) {
        const TrainingSource& s = (*sources)[i];
        training.append(QJsonObject{{QStringLiteral("recording"), s.recording},
                                    {QStringLiteral("stream"), stream},
                                    {QStringLiteral("athlete"), s.athlete},
                                    {QStringLiteral("content_hash"), QString::fromLatin1(s.data->contentHash())},
                                    {QStringLiteral("windows"), double(windowsPerSource[i])}});
    }
    QJsonArray members;
    for (qsizetype i = 0; i < options.classifier.voteMembers.size(); ++i)
        members.append(QJsonObject{{QStringLiteral("classifier"), options.classifier.voteMembers[i]},
                                   {QStringLiteral("weight"), std::size_t(i) < options.classifier.voteWeights.size()
                                                                  ? options.classifier.voteWeights[std::size_t(i)]
                                                                  : 1.0}});
    QJsonObject parameters{{QStringLiteral("trees"), options.classifier.trees},
                           {QStringLiteral("max_depth"), options.classifier.maxDepth},
                           {QStringLiteral("neighbours"), options.classifier.neighbours},
                           {QStringLiteral("balanced"), options.classifier.balance},
                           {QStringLiteral("min_label_fraction"), options.minLabelFraction},
                           {QStringLiteral("seed"), double(options.classifier.seed)}};
    if (options.classifier.kind == u"vote") parameters[QStringLiteral("vote")] = members;
    model->provenance[QStringLiteral("input")] = stream;
    model->provenance[QStringLiteral("parameters")] = parameters;
    model->provenance[QStringLiteral("training")] = training;
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
