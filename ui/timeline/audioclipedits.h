#pragma once

#include "document/animation.h"
#include "timeline/timelineedits.h"

#include <QStringList>
#include <QVector>

#include <optional>

namespace toonface {

// The audio track's edits, as plain functions like timelineedits.h. A clip owns the syllables
// and the mouth keys that start inside its span [start(), end()): they move and go with it.
// Times stay within [0, Timeline::kMaxSeconds].

// The clips (but `except`) heard somewhere in [start, end), ascending.
QVector<int> audioClipsOverlapping(const Timeline &timeline, double start, double end, int except = -1);
// The earliest time from `start` on where `length` seconds meet no clip.
double freeAudioTime(const Timeline &timeline, double start, double length);

// Moves the clips at `indices` by dt with what they own. dt is clamped so that no moved clip
// starts before 0, ends past kMaxSeconds or runs into a clip not moved (clips that overlapped
// before may stay overlapped). *applied receives the dt applied.
Animation moveAudioClips(const Animation &animation, const QVector<int> &indices, double dt, double *applied = nullptr);
// Moves one edge of a clip's heard span to `to` by trimming its file: within the file, at least
// minSpan long, not into a neighbouring clip. Nothing else moves.
Animation trimAudioClip(const Animation &animation, int clip, SpanEdge edge, double to, double minSpan);
// Removes the clips at `indices` with their syllables and mouth keys.
Animation removeAudioClips(const Animation &animation, const QVector<int> &indices);

// What to do when a new recording would play over recordings already on the track.
enum class ClipOverlap {
    PlaceAfter, // it starts where it meets none (after them)
    Replace, // they are removed with their syllables and mouth keys
    Mix, // both stay where they are and sound together
};

// A new recording `length` seconds long wanted at `start`: where it goes and which clips it
// replaces. An existing clip of the same file at the same place is the same recording again (a
// new lip sync of it): it is always replaced. nullopt when the clip would end past
// Timeline::kMaxSeconds.
struct ClipPlace
{
    double start = 0;
    QVector<int> replaced; // ascending
    QVector<int> overlapped; // the clips it would have met at the wanted start
};
std::optional<ClipPlace> placeAudioClip(
    const Timeline &timeline, const QString &path, double start, double length, ClipOverlap overlap);

} // namespace toonface
