#include "plugins/activity/ClassifyActionsProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/activity/ActivityModel.h"

namespace athlos::activity {

namespace {
constexpr Translator tr{"athlos::activity", "ClassifyActionsProcessor"};

Expected<ActivityModel> loadModel(const RunContext& c) {
    const QString name = c.text(QStringLiteral("model"));
    const TrainedModel* stored = c.project().model(name);
    if (!stored) {
        QStringList names;
        for (const auto& [n, m] : c.project().models()) names << n;
        return makeError(QStringLiteral("model: the project has no model '%1' (models: %2; train one with athlos "
                                        "train)")
                             .arg(name, names.isEmpty() ? QStringLiteral("none") : names.join(QStringLiteral(", "))));
    }
    auto model = ActivityModel::fromStored(*stored);
    if (!model) return makeError(QStringLiteral("model: ") + model.message());
    const Stream* stream = c.stream(0);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(c.inputRole(0)));
    if (Status s = model->checkStream(stream->info()); !s)
        return makeError(
            QStringLiteral("model: '%1' does not fit input '%2': %3").arg(name, c.inputPath(0), s.message()));
    return model;
}

// The session of the input stream (the other athletes' positions and torso pitch) for a model with
// interaction features; every stream read is recorded in the run's provenance.
Expected<PlayerContext> gatherFor(const RunContext& c, const ActivityModel& model) {
    const ItemPath path = ItemPath::parse(c.inputPath(0));
    const Recording* rec = c.project().recording(path.recording);
    if (!rec) return c.inputError(0, QStringLiteral("no recording '%1'").arg(path.recording));
    auto player = gatherPlayer(*rec, path.item, *model.interaction);
    if (!player)
        return c.inputError(0, QStringLiteral("model '%1' needs the session's other athletes: %2")
                                   .arg(c.text(QStringLiteral("model")), player.message()));
    for (const ProvenanceInput& read : player->session->streams) c.recordRead(read.name, read.hash);
    return player;
}
}  // namespace

QString ClassifyActionsProcessor::name() const { return tr("Classify actions (trained model)"); }

QString ClassifyActionsProcessor::description() const {
    return tr(
        "Classifies sliding windows of an IMU stream with a model trained in this project (athlos train) and "
        "writes the activities as predicted annotations with confidence: consecutive windows of one class merge "
        "into one interval and the intervals cover the whole stream. A model trained on detected events "
        "(--segmentation events:impact or events:tackle) runs its detector and writes one annotation per "
        "event that is not classified as null. A model with interaction features (athlos train --interaction) also "
        "reads the other athletes' IMU and positions streams of the input's recording (athlete and team "
        "attributes, as simulate-rugby writes them).");
}

ParameterSpecs ClassifyActionsProcessor::parameters() const {
    ParameterSpec model = ParameterSpec::text(QStringLiteral("model"), QString(),
                                              tr("Name of the trained model in the project (athlos train --model)."));
    model.defaultValue = QVariant();  // required
    return {
        model,
        ParameterSpec::integer(QStringLiteral("smoothing"), 1, 0, 50,
                               tr("Windows on each side whose class probabilities are averaged with a window's "
                                  "own before deciding (0: none); activities last longer than a window.")),
    };
}

QList<InputSpec> ClassifyActionsProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("IMU stream with the columns the model was trained on (acc_x..z, gyr_x..z, ...).")}};
}

QList<OutputSpec> ClassifyActionsProcessor::outputs() const {
    return {OutputSpec{QString(), false, QString(), tr("Activities as predicted annotations with confidence."), true}};
}

Status ClassifyActionsProcessor::prepare(const RunContext& context) const {
    auto model = loadModel(context);
    if (!model) return model.error();
    if (model->interaction) return statusOf(gatherFor(context, *model));
    return {};
}

Expected<std::vector<ProcessorOutput>> ClassifyActionsProcessor::run(const RunContext& context) const {
    auto model = loadModel(context);
    if (!model) return model.error();
    auto input = context.samples(0);
    if (!input) return input.error();
    std::optional<PlayerContext> player;
    if (model->interaction) {
        auto gathered = gatherFor(context, *model);
        if (!gathered) return gathered.error();
        player = std::move(*gathered);
    }
    auto annotations = model->classify(input->info(), *input->data, context.integer(QStringLiteral("smoothing")),
                                       context.progress(), player ? &*player : nullptr);
    if (!annotations) {
        if (annotations.message() == u"cancelled") return cancelledError();
        return input->error(annotations.message());
    }
    context.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(*annotations)});
    return outputs;
}

}  // namespace athlos::activity
