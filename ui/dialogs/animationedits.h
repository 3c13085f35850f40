#pragma once

#include "document/animation.h"
#include "speech/lipsync.h"
#include "timeline/audioclipedits.h"

#include <QString>

namespace toonface {

// Where a lip-sync result goes in the animation: the sound it was made from, where it is wanted
// on the timeline, the script it speaks and what to do when recordings already play there.
struct SpeechPlacement
{
    QString audioPath; // absolute
    double offset = 0; // seconds into the animation where the sound is wanted, >= 0
    QString script; // the script text as the user wrote it
    ClipOverlap overlap = ClipOverlap::PlaceAfter;
};

// `before` with `result` as a new clip on the audio track, placed by placeAudioClip (the clips
// it replaces go with their syllables and mouth keys; the others stay): the clip holds the
// script and its language ("cmn" or "en"), and the mouth keys and syllables inside its span
// are replaced by the result's (moved to where it starts). Every other track is kept. nullopt
// when it would end past Timeline::kMaxSeconds. *placed (when given) says where it went.
std::optional<Animation> withSpeech(const Animation &before, const LipsyncResult &result,
    const SpeechPlacement &placement, ClipPlace *placed = nullptr);

// What a status line says of a new recording placed at `placed` on `before`'s track (e.g. "placed
// after speech.wav at 6.0 s"), empty when it went where it was wanted and replaced nothing.
QString placementNote(const Timeline &before, const ClipPlace &placed, double wanted);

// `before` with its blinks in [start, end) replaced by Timeline::randomBlinks(seed, end - start)
// moved to start. requires: start < end
Animation withBlinks(const Animation &before, quint32 seed, double start, double end);

// `before` with `clip` on the emotion track. With `replace`, the emotion clips under the new
// clip give way: a clip inside it is removed, one that overlaps an edge is cut back to that
// edge, and one that holds it is cut in two around it (fades shortened to fit).
Animation withEmotion(const Animation &before, const EmotionClip &clip, bool replace);

} // namespace toonface
