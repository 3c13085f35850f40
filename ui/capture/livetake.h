#pragma once

#include "capture/livesession.h"

#include <QString>

namespace toonface {

class Document;

// Puts a recorded live take into `document` at `at` seconds as ONE undo step
// (Document::changeAnimation): the tracked motion as key frames in place of what the take's
// span held (addTakeToTimeline), the mouth from the sound's keys when the sound drove it, and
// the take's sound, written as a WAV to `audioPath`, as a new clip on the audio track at `at`
// (recordings already there stay: their sounds mix).
// A take without sound keeps the timeline's audio and says "motion only"; a take heard only
// (the microphone alone, no frames) puts the sound's mouth keys and its sound. Returns false with
// *message naming the problem (an empty take, an unwritable sound file); else true with
// *message describing what was added.
bool commitTake(Document *document, const LiveTake &take, double at, const QString &audioPath, QString *message);

} // namespace toonface
