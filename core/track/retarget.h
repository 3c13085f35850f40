#pragma once

#include "anim/timeline.h"
#include "track/tracker.h"

#include <QVector>

namespace toonface {

// Blinks in a series of lid openings (1 = the neutral's, 0 = shut), one per frame at `times`:
// runs of frames below `closedBelow` times the clip's median opening, runs one frame apart
// merged. Each becomes a BlinkEvent whose shut phase (kBlinkPhases) lies on the run: its
// closing starts before the run's first frame and its opening ends after the last.
QVector<BlinkEvent> detectBlinks(
    const QVector<double> &times, const QVector<double> &openness, double fps, double closedBelow = 0.6);

// The moment of a blink's deepest closure (the middle of its shut phase).
double blinkMiddle(const BlinkEvent &blink);

struct RetargetOptions
{
    bool pose = true; // mouth and brow motion as pose keys
    bool blinks = true;
    bool gaze = true;
    bool head = true;
    // Frames whose mouthShape is set (the tracker snapped them) give mouth keys, one per change
    // of shape, instead of mouth motion in the pose track.
    bool mouthKeysFromShapes = true;
};

// Puts tracked frames onto `timeline` as ordinary key frames, `offset` seconds added to their
// times: a pose key per frame (the mouth controls 8.9 8.2 8.4 8.3 and the eight brow points, in
// ES0 units, so any face can play them), a gaze key and a head key per frame, and the blinks
// the lids show. Lost frames give no keys (the keys around them ease across). What the
// filled tracks held in the frames' span (the first frame's time to one period after the
// last's, `offset` added) is replaced; keys and blinks outside it are kept. Mouth keys in the
// span give way too (to the snapped shapes, or to the tracked mouth in the pose keys), and a
// shut key starts the span when a key before it would otherwise sound on into it.
void addTrackToTimeline(const QVector<TrackedFrame> &frames, double fps, Timeline *timeline,
    const RetargetOptions &options = {}, double offset = 0.0);

} // namespace toonface

namespace toonface {

// Puts a recorded live take onto `timeline` at `at` seconds, in place of what its span
// [at, at + duration] held: the tracked frames (times from the take's start) keyed as
// addTrackToTimeline() keys them (pose, gaze, head, blinks). With `soundMouth` (mouth keys
// timed from the take's start, e.g. audioMouthKeys()) the mouth follows those keys and the pose
// keys leave the mouth controls out; without, the tracked mouth is in the pose keys. Keys and
// blinks outside the span are kept; mouth keys inside it are replaced, and a shut key starts
// the span when a key before it would otherwise sound on into it.
//
// With `soundWhileLost` (live mode's "camera, microphone when the lips are lost"), the sound's
// keys drive the mouth only where the camera lost the face, as live mode showed it: there the
// last tracked pose holds with the mouth controls at rest, the sound's shape sounds from the
// span's start, and a shut key hands the mouth back to the camera where the face is found
// again; elsewhere the tracked mouth stays in the pose keys.
//
// A take with no frames (the performer was only heard) puts only its mouth keys in the span;
// the pose, gaze, head and blinks there are kept.
void addTakeToTimeline(const QVector<TrackedFrame> &frames, double fps, double duration,
    const QVector<MouthKey> &soundMouth, Timeline *timeline, double at, bool soundWhileLost = false);

} // namespace toonface
