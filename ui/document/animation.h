#pragma once

#include "anim/timeline.h"
#include "speech/lipsync.h"

#include <QString>
#include <QVector>

namespace toonface {

// The part of a project that animation edits change, as one value: the timeline (every track
// and the audio clip), the script's timed syllables (the script row) and the script itself.
// An edit replaces the whole value; undo keeps the values before and after (a 10-minute
// timeline is well under a megabyte), so undo restores the exact previous state.
struct Animation
{
    Timeline timeline;
    QVector<LipsyncSyllable> syllables;
    QString script;
    QString scriptLanguage; // "cmn", "en" or empty

    bool operator==(const Animation &) const = default;
};

} // namespace toonface
