#pragma once
// The multi-athlete context of one player's IMU stream for the interaction features
// (InteractionFeatures.h, seed 000 §5.1.2), gathered from a project the same way at training
// (`athlos train --interaction k=3`, the Train classifier wizard) and at prediction (classify-actions):
//  - the athletes of a session are the IMU streams (kind `imu`) of the player's recording that carry an
//    `athlete` attribute (else `label`), as simulate-rugby writes them; the player is the athlete of
//    the given stream;
//  - an athlete's positions: the stream of kind `trajectory` (position-filter output, i.e. filtered)
//    with the same athlete, else the one of kind `lps-position`; two streams of the chosen kind for one
//    athlete are refused as ambiguous;
//  - teams: the `team` attribute of the IMU stream, else of its positions stream; the opponents are
//    the athletes of another team (teammates are never interaction candidates);
//  - torso pitch of every athlete from his IMU (TorsoPitch with the stored parameters).
// Whatever is missing (athlete, team, positions) is refused with a message naming the stream.
#include "core/model/Project.h"
#include "core/model/Provenance.h"
#include "core/util/Expected.h"
#include "plugins/activity/InteractionFeatures.h"
#include "plugins/activity/TorsoPitch.h"

#include <QJsonObject>
#include <QStringList>
#include <memory>
#include <vector>

namespace athlos::activity {

// What the interaction features of a model are and how they are gathered (stored in the model).
struct InteractionOptions {
    int neighbours = 3;      // k nearest opponents (thesis: 3)
    double speedSpan = 1.0;  // s before the event over which speeds are taken
    TorsoPitch::Params pitch;

    // The feature names appended after the IMU features (InteractionFeatures::names()).
    QStringList names() const;
    QJsonObject toJson() const;
    static Expected<InteractionOptions> fromJson(const QJsonObject& json);
    // "k=3[,speed_span=1][,reference_start=0][,reference_duration=3][,up_axis=z][,cutoff=0.5]"
    // (the --interaction option); the error names the option and the key.
    static Expected<InteractionOptions> parse(const QString& text);
};

// The athletes of one recording with their positions and torso pitch.
struct InteractionSession {
    QString recording;
    std::vector<InteractionFeatures::Athlete> athletes;
    QStringList imuStreams;                // per athlete: his IMU stream's name
    std::vector<ProvenanceInput> streams;  // every stream read ("rec/stream" and content hash)

    // The athlete whose IMU stream is `stream`, or −1.
    int playerOf(const QString& stream) const { return int(imuStreams.indexOf(stream)); }
};

// One player's IMU stream in its session (what a window's interaction features are computed from).
struct PlayerContext {
    std::shared_ptr<const InteractionSession> session;
    int player = -1;
};

Expected<std::shared_ptr<const InteractionSession>> gatherSession(const Recording& recording,
                                                                  const InteractionOptions& options);
// The session of `stream` in `recording`, refusing when the stream is not one of its athletes.
Expected<PlayerContext> gatherPlayer(const Recording& recording, const QString& stream,
                                     const InteractionOptions& options);

// The interaction features of a window centred at t (window length `window` s; NaN, where an opponent
// or positions are missing at t, becomes 0 so that the classifiers can read every window).
void interactionFeatures(const PlayerContext& player, const InteractionOptions& options, double window, double t,
                         float* out);

}  // namespace athlos::activity
