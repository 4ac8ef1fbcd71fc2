#include "plugins/activity/DetectScrumsProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/activity/ScrumDetector.h"
#include "plugins/activity/TorsoPitch.h"

namespace athlos::activity {

namespace {
constexpr Translator tr{"athlos::activity", "DetectScrumsProcessor"};

QString athleteOf(const StreamInfo& info) {
    const QString athlete = info.attributes.value(QStringLiteral("athlete")).toString();
    return athlete.isEmpty() ? info.attributes.value(QStringLiteral("label")).toString() : athlete;
}

struct Plan {
    TorsoPitch::Params pitch;
    ScrumDetector::Params detector;
    const Recording* recording = nullptr;
    std::vector<const Stream*> imus;       // every IMU stream of the session
    std::vector<const Stream*> positions;  // per IMU: the athlete's positions or nullptr
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    plan.pitch.cutoff = c.number(QStringLiteral("cutoff"));
    plan.pitch.referenceStart = c.number(QStringLiteral("reference_start"));
    plan.pitch.referenceDuration = c.number(QStringLiteral("reference_duration"));
    plan.pitch.upAxis = c.text(QStringLiteral("up_axis"));
    plan.detector.players = c.integer(QStringLiteral("players"));
    plan.detector.threshold = c.number(QStringLiteral("threshold"));
    plan.detector.minDuration = c.number(QStringLiteral("min_duration"));
    plan.detector.maxSpread = c.number(QStringLiteral("max_spread"));
    const QString name = ItemPath::parse(c.inputPath(0)).recording;
    plan.recording = c.project().recording(name);
    if (!plan.recording) return c.inputError(0, QStringLiteral("no recording '%1'").arg(name));
    std::map<QString, const Stream*> byAthlete;
    for (const auto& [n, s] : plan.recording->streams)
        if (s.kind() == u"lps-position" && !athleteOf(s.info()).isEmpty()) byAthlete[athleteOf(s.info())] = &s;
    for (const auto& [n, s] : plan.recording->streams) {
        if (s.kind() != u"imu") continue;
        plan.imus.push_back(&s);
        const auto it = byAthlete.find(athleteOf(s.info()));
        plan.positions.push_back(athleteOf(s.info()).isEmpty() || it == byAthlete.end() ? nullptr : it->second);
    }
    if (int(plan.imus.size()) < plan.detector.players)
        return c.inputError(0, QStringLiteral("recording '%1' has %2 IMU streams, fewer than parameter 'players' (%3)")
                                   .arg(name)
                                   .arg(plan.imus.size())
                                   .arg(plan.detector.players));
    return plan;
}
}  // namespace

QString DetectScrumsProcessor::name() const { return tr("Detect scrums (top-6 torso pitch)"); }

QString DetectScrumsProcessor::description() const {
    return tr(
        "Finds scrums in a team session: the torso pitch of every player from the upper-back accelerometer "
        "(gravity direction against the upright standing posture), sorted at each instant; where the mean of "
        "the six largest stays above the threshold for the minimum duration, with those players close "
        "together, a scrum annotation is written. Uses every IMU stream of the input's recording.");
}

ParameterSpecs DetectScrumsProcessor::parameters() const {
    const TorsoPitch::Params p;
    const ScrumDetector::Params d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("players"), d.players, 1, 30,
                    tr("Largest torso pitches averaged at each instant (seed 000 §5.1.2: the six players of a "
                       "sevens scrum).")),
        PS::number(QStringLiteral("threshold"), d.threshold, 0.1, 1.5, QStringLiteral("rad"),
                   tr("Scrum when the mean of the largest torso pitches exceeds this (0.96 rad = 55°, between "
                      "running < 25° and binding 60–90°; the thesis fits it by grid search so that no scrum "
                      "is missed, seed 000 §5.1.2, Fig. 5.6).")),
        PS::number(QStringLiteral("min_duration"), d.minDuration, 0.0, 60.0, QStringLiteral("s"),
                   tr("Shorter episodes are not scrums (a scrum lasts several seconds; tackles and players "
                      "bending for the ball are brief).")),
        PS::number(QStringLiteral("max_spread"), d.maxSpread, 0.0, 50.0, QStringLiteral("m"),
                   tr("Largest distance of those players from their centroid (bound players are within ~2 m "
                      "of each other); 0 or no position streams: not checked.")),
        PS::number(QStringLiteral("cutoff"), p.cutoff, 0.05, 5.0, QStringLiteral("Hz"),
                   tr("Low-pass of the accelerometer that leaves the direction of gravity (torso pitch).")),
        PS::number(QStringLiteral("reference_start"), p.referenceStart, 0.0, 1e6, QStringLiteral("s"),
                   tr("Start of the standing period whose gravity direction is each player's upright "
                      "reference (sensor alignment correction, seed 000 Fig. 5.5).")),
        PS::number(QStringLiteral("reference_duration"), p.referenceDuration, 0.0, 600.0, QStringLiteral("s"),
                   tr("Length of the standing period; 0: the sensor axis up_axis is upright.")),
        PS::choice(QStringLiteral("up_axis"),
                   {QStringLiteral("x"), QStringLiteral("-x"), QStringLiteral("y"), QStringLiteral("-y"),
                    QStringLiteral("z"), QStringLiteral("-z")},
                   p.upAxis, tr("The sensor axis that points up when the player stands (reference_duration 0).")),
    };
}

QList<InputSpec> DetectScrumsProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("One upper-back IMU stream of the session; all IMU streams of its recording are used.")}};
}

QList<OutputSpec> DetectScrumsProcessor::outputs() const {
    return {OutputSpec{QString(), false, QString(), tr("Scrums as predicted annotations."), true}};
}

Status DetectScrumsProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> DetectScrumsProcessor::run(const RunContext& c) const {
    auto plan = makePlan(c);
    if (!plan) return plan.error();
    std::vector<ScrumDetector::Player> players;
    for (std::size_t i = 0; i < plan->imus.size(); ++i) {
        if (c.isCancelled()) return cancelledError();
        const Stream& s = *plan->imus[i];
        // Every stream of the session is an input of the result: recorded so provenance lists it and
        // `athlos batch` sees it change (the declared input is one of them; recordRead skips it).
        const QString rec = ItemPath::parse(c.inputPath(0)).recording;
        c.recordRead(rec + u'/' + s.name(), s.info().contentHash);
        if (const Stream* pos = plan->positions[i]) c.recordRead(rec + u'/' + pos->name(), pos->info().contentHash);
        auto data = s.data();
        if (!data) return c.inputError(0, QStringLiteral("stream '%1': %2").arg(s.name(), data.message()));
        auto pitch = TorsoPitch::compute(s.info(), **data, plan->pitch);
        if (!pitch) return c.inputError(0, QStringLiteral("stream '%1': %2").arg(s.name(), pitch.message()));
        ScrumDetector::Player player;
        player.t = (*data)->t;
        player.pitch = std::move(*pitch);
        if (const Stream* pos = plan->positions[i]) {
            auto p = pos->data();
            if (!p) return c.inputError(0, QStringLiteral("stream '%1': %2").arg(pos->name(), p.message()));
            const int x = pos->info().columnIndex(QStringLiteral("x")),
                      y = pos->info().columnIndex(QStringLiteral("y"));
            if (x >= 0 && y >= 0) {
                player.tPos = (*p)->t;
                for (std::size_t k = 0; k < (*p)->rows(); ++k) {
                    player.x.push_back((*p)->at(k, x));
                    player.y.push_back((*p)->at(k, y));
                }
            }
        }
        players.push_back(std::move(player));
        c.report(0.9 * double(i + 1) / double(plan->imus.size()));
    }
    auto result = ScrumDetector::detect(players, plan->detector);
    if (!result) return c.inputError(0, result.message());
    c.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(result->scrums)});
    return outputs;
}

}  // namespace athlos::activity
