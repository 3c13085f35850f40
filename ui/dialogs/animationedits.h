#pragma once

#include "document/animation.h"
#include "speech/lipsync.h"

#include <QString>

namespace toonface {

// Where a lip-sync result goes in the animation: the sound it was made from, when that sound
// starts, and the script it speaks.
struct SpeechPlacement
{
    QString audioPath; // absolute
    double offset = 0; // seconds into the animation where the sound starts, >= 0
    QString script; // the script text as the user wrote it
};

// `before` with `result` laid in at placement.offset: the mouth keys and the script row's
// syllables inside [offset, offset + result.duration] are replaced by the result's (moved by
// the offset); everything outside that range and every other track is kept. The timeline's
// audio clip becomes the sound (its duration the result's), and the script and its language
// ("cmn" or "en") the result's.
Animation withSpeech(const Animation &before, const LipsyncResult &result, const SpeechPlacement &placement);

// `before` with its blinks in [start, end) replaced by Timeline::randomBlinks(seed, end - start)
// moved to start. requires: start < end
Animation withBlinks(const Animation &before, quint32 seed, double start, double end);

// `before` with `clip` on the emotion track. With `replace`, the emotion clips under the new
// clip give way: a clip inside it is removed, one that overlaps an edge is cut back to that
// edge, and one that holds it is cut in two around it (fades shortened to fit).
Animation withEmotion(const Animation &before, const EmotionClip &clip, bool replace);

} // namespace toonface
