#pragma once

#include "export/smilexport.h"

#include <QByteArray>
#include <QRectF>
#include <QString>

namespace toonface {
class Timeline;
}

// The sound of an SMIL export: the audio file as a data: URI or a relative reference, the
// document's <metadata>, and the player script that keeps the animation on the audio clock.
namespace toonface::smil {

// The sound an export carries.
struct SmilAudio
{
    QByteArray uri; // empty: no sound
    double offset = 0;
    double duration = 0;
};

// Finds the sound of `timeline` (or options.audioPath) and makes its URI as options ask;
// false with *error naming the file when it cannot be read.
bool resolveAudio(
    const Timeline &timeline, double duration, const AnimationExportOptions &options, SmilAudio *out, QString *error);

// <metadata> with <tf:animation> and, with sound, <tf:audio>.
QByteArray metadata(const SmilAudio &audio, double duration, double fps);

// The standalone document's player: a play button over the drawing and the script that
// starts the sound with the animation and keeps the animation on the audio clock.
QByteArray playerScript(QRectF canvas);

} // namespace toonface::smil
