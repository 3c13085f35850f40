#pragma once

#include "anim/timeline.h"
#include "speech/lipsync.h"

#include <QString>
#include <QVector>

namespace toonface {

// The part of a project that animation edits change, as one value: the timeline (every track
// and the audio track, whose clips hold their scripts) and the syllables of those scripts at
// their timeline times (the script row; a syllable belongs to the clip it lies in, as the mouth
// keys do). An edit replaces the whole value; undo keeps the values before and after (a
// 10-minute timeline is well under a megabyte), so undo restores the exact previous state.
struct Animation
{
    Timeline timeline;
    QVector<LipsyncSyllable> syllables;

    bool operator==(const Animation &) const = default;
};

} // namespace toonface
