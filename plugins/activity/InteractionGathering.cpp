#include "plugins/activity/InteractionGathering.h"

#include <cmath>
#include <map>

namespace athlos::activity {

namespace {
QString athleteOf(const StreamInfo& info) {
    const QString athlete = info.attributes.value(QStringLiteral("athlete")).toString();
    return athlete.isEmpty() ? info.attributes.value(QStringLiteral("label")).toString() : athlete;
}

const QStringList kUpAxes{QStringLiteral("x"),  QStringLiteral("-x"), QStringLiteral("y"),
                          QStringLiteral("-y"), QStringLiteral("z"),  QStringLiteral("-z")};
}  // namespace

QStringList InteractionOptions::names() const {
    InteractionFeatures::Params p;
    p.neighbours = neighbours;
    return InteractionFeatures::names(p);
}

QJsonObject InteractionOptions::toJson() const {
    return {{QStringLiteral("neighbours"), neighbours},
            {QStringLiteral("speed_span"), speedSpan},
            {QStringLiteral("opponents"), QStringLiteral("team attribute differs")},
            {QStringLiteral("positions"), QStringLiteral("trajectory, else lps-position, of the same athlete")},
            {QStringLiteral("pitch"), QJsonObject{{QStringLiteral("cutoff"), pitch.cutoff},
                                                  {QStringLiteral("reference_start"), pitch.referenceStart},
                                                  {QStringLiteral("reference_duration"), pitch.referenceDuration},
                                                  {QStringLiteral("up_axis"), pitch.upAxis},
                                                  {QStringLiteral("stillness"), pitch.stillness}}}};
}

Expected<InteractionOptions> InteractionOptions::fromJson(const QJsonObject& json) {
    InteractionOptions o;
    o.neighbours = json.value(QStringLiteral("neighbours")).toInt(0);
    o.speedSpan = json.value(QStringLiteral("speed_span")).toDouble(0.0);
    const QJsonObject p = json.value(QStringLiteral("pitch")).toObject();
    o.pitch.cutoff = p.value(QStringLiteral("cutoff")).toDouble(o.pitch.cutoff);
    o.pitch.referenceStart = p.value(QStringLiteral("reference_start")).toDouble(o.pitch.referenceStart);
    o.pitch.referenceDuration = p.value(QStringLiteral("reference_duration")).toDouble(o.pitch.referenceDuration);
    o.pitch.upAxis = p.value(QStringLiteral("up_axis")).toString(o.pitch.upAxis);
    o.pitch.stillness = p.value(QStringLiteral("stillness")).toDouble(o.pitch.stillness);
    if (o.neighbours < 1 || o.neighbours > 20 || !(o.speedSpan > 0) || !(o.pitch.cutoff > 0) ||
        !kUpAxes.contains(o.pitch.upAxis))
        return makeError(QStringLiteral("its interaction features are not described completely"));
    return o;
}

Expected<InteractionOptions> InteractionOptions::parse(const QString& text) {
    InteractionOptions o;
    const auto refuse = [&](const QString& why) {
        return makeError(QStringLiteral("--interaction '%1': %2").arg(text, why));
    };
    bool haveK = false;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString key = item.section(QLatin1Char('='), 0, 0).trimmed();
        const QString value = item.section(QLatin1Char('='), 1).trimmed();
        bool ok = false;
        if (key == u"k") {
            o.neighbours = value.toInt(&ok);
            if (!ok || o.neighbours < 1 || o.neighbours > 20)
                return refuse(QStringLiteral("k is the number of nearest opponents, 1 to 20"));
            haveK = true;
        } else if (key == u"speed_span") {
            o.speedSpan = value.toDouble(&ok);
            if (!ok || !(o.speedSpan > 0) || o.speedSpan > 10)
                return refuse(QStringLiteral("speed_span is in s, above 0 and at most 10"));
        } else if (key == u"reference_start") {
            o.pitch.referenceStart = value.toDouble(&ok);
            if (!ok || o.pitch.referenceStart < 0) return refuse(QStringLiteral("reference_start is a time ≥ 0 s"));
        } else if (key == u"reference_duration") {
            o.pitch.referenceDuration = value.toDouble(&ok);
            if (!ok || o.pitch.referenceDuration < 0 || o.pitch.referenceDuration > 600)
                return refuse(QStringLiteral("reference_duration is 0 (use up_axis) to 600 s"));
        } else if (key == u"up_axis") {
            if (!kUpAxes.contains(value)) return refuse(QStringLiteral("up_axis is one of x, -x, y, -y, z, -z"));
            o.pitch.upAxis = value;
        } else if (key == u"cutoff") {
            o.pitch.cutoff = value.toDouble(&ok);
            if (!ok || !(o.pitch.cutoff >= 0.05) || o.pitch.cutoff > 5)
                return refuse(QStringLiteral("cutoff is the torso pitch low-pass, 0.05 to 5 Hz"));
        } else {
            return refuse(QStringLiteral("unknown key '%1' (k, speed_span, reference_start, reference_duration, "
                                         "up_axis, cutoff)")
                              .arg(key));
        }
    }
    if (!haveK) return refuse(QStringLiteral("needs k=N, the number of nearest opponents (the thesis uses 3)"));
    return o;
}

Expected<std::shared_ptr<const InteractionSession>> gatherSession(const Recording& recording,
                                                                  const InteractionOptions& options) {
    auto session = std::make_shared<InteractionSession>();
    session->recording = recording.name;
    const auto path = [&](const QString& stream) { return recording.name + QLatin1Char('/') + stream; };
    // Positions per athlete and kind (filtered trajectory preferred).
    std::map<QString, std::map<QString, QStringList>> positions;  // athlete → kind → streams
    for (const auto& [name, s] : recording.streams)
        if ((s.kind() == u"trajectory" || s.kind() == u"lps-position") && !athleteOf(s.info()).isEmpty())
            positions[athleteOf(s.info())][s.kind()] << name;
    for (const auto& [name, s] : recording.streams) {
        if (s.kind() != u"imu") continue;
        const QString athlete = athleteOf(s.info());
        if (athlete.isEmpty()) continue;
        const auto& kinds = positions[athlete];
        const QStringList* candidates = nullptr;
        for (const char* kind : {"trajectory", "lps-position"})
            if (const auto it = kinds.find(QLatin1String(kind)); !candidates && it != kinds.end())
                candidates = &it->second;
        if (!candidates)
            return makeError(QStringLiteral("interaction features: recording '%1' has no positions stream (kind "
                                            "trajectory or lps-position) of athlete '%2' (IMU stream '%3')")
                                 .arg(recording.name, athlete, path(name)));
        if (candidates->size() > 1)
            return makeError(QStringLiteral("interaction features: athlete '%1' has several positions streams in "
                                            "recording '%2' (%3); keep one of each kind")
                                 .arg(athlete, recording.name, candidates->join(QStringLiteral(", "))));
        const Stream& pos = recording.streams.at(candidates->front());
        QString team = s.info().attributes.value(QStringLiteral("team")).toString();
        if (team.isEmpty()) team = pos.info().attributes.value(QStringLiteral("team")).toString();
        if (team.isEmpty())
            return makeError(QStringLiteral("interaction features: stream '%1' (athlete '%2') has no 'team' "
                                            "attribute, so teammates and opponents cannot be told apart")
                                 .arg(path(name), athlete));
        auto imu = s.data();
        if (!imu) return makeError(QStringLiteral("%1: %2").arg(path(name), imu.message()));
        auto pitch = TorsoPitch::compute(s.info(), **imu, options.pitch);
        if (!pitch)
            return makeError(
                QStringLiteral("interaction features: torso pitch of '%1': %2").arg(path(name), pitch.message()));
        auto p = pos.data();
        if (!p) return makeError(QStringLiteral("%1: %2").arg(path(candidates->front()), p.message()));
        const int x = pos.info().columnIndex(QStringLiteral("x")), y = pos.info().columnIndex(QStringLiteral("y"));
        if (x < 0 || y < 0)
            return makeError(
                QStringLiteral("interaction features: stream '%1' has no columns x, y").arg(path(candidates->front())));
        InteractionFeatures::Athlete a;
        a.team = team;
        a.tPos = (*p)->t;
        for (std::size_t k = 0; k < (*p)->rows(); ++k) {
            a.x.push_back((*p)->at(k, x));
            a.y.push_back((*p)->at(k, y));
        }
        a.tPitch = (*imu)->t;
        a.pitch = std::move(*pitch);
        session->athletes.push_back(std::move(a));
        session->imuStreams << name;
        session->streams.push_back({path(name), s.info().contentHash});
        session->streams.push_back({path(candidates->front()), pos.info().contentHash});
    }
    return std::shared_ptr<const InteractionSession>(std::move(session));
}

Expected<PlayerContext> gatherPlayer(const Recording& recording, const QString& stream,
                                     const InteractionOptions& options) {
    const auto it = recording.streams.find(stream);
    if (it == recording.streams.end())
        return makeError(QStringLiteral("recording '%1' has no stream '%2'").arg(recording.name, stream));
    if (athleteOf(it->second.info()).isEmpty())
        return makeError(QStringLiteral("interaction features: stream '%1/%2' has no 'athlete' attribute naming "
                                        "whose IMU it is (simulate-rugby writes athlete and team)")
                             .arg(recording.name, stream));
    auto session = gatherSession(recording, options);
    if (!session) return session.error();
    PlayerContext out;
    out.session = *session;
    out.player = (*session)->playerOf(stream);
    if (out.player < 0)
        return makeError(QStringLiteral("interaction features: stream '%1/%2' is not an athlete's IMU stream")
                             .arg(recording.name, stream));
    return out;
}

void interactionFeatures(const PlayerContext& player, const InteractionOptions& options, double window, double t,
                         float* out) {
    InteractionFeatures::Params p;
    p.neighbours = options.neighbours;
    p.window = window;
    p.speedSpan = options.speedSpan;
    const std::vector<double> v = InteractionFeatures::compute(player.session->athletes, player.player, t, p);
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = std::isfinite(v[i]) ? float(v[i]) : 0.0f;
}

}  // namespace athlos::activity
