#pragma once

#include "render/smilexport.h"

#include <QByteArray>
#include <QString>

namespace toonface {

// A self-contained HTML page that plays the animation with its sound: the Smil-mode SVG inline
// (exportSmilElement) above an <audio id="tf-audio" controls> element holding the sound (a
// data: URI, or a relative reference with ExportAudio::Reference). The audio element is the
// clock: its play and pause start and stop the animation, and the animation's time is set to
// the audio's when it seeks and whenever they drift apart by more than 40 ms (checked on every
// animation frame while playing). Without sound the page has its own play button
// (#tf-toggle) and seek bar (#tf-seek). Returns an empty array and sets *error as
// exportSmilSvg() does.
QByteArray exportHtmlPlayer(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options = {}, QString *error = nullptr);

} // namespace toonface
