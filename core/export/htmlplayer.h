#pragma once

#include "export/smilexport.h"

#include <QByteArray>
#include <QString>

namespace toonface {

// A self-contained HTML page that plays the animation with its sound: the Smil-mode SVG inline
// (exportSmilElement) above the player's controls: a play/pause button (#tf-toggle), a seek bar
// over the whole animation (#tf-seek, seconds) and the time (#tf-time). The sound is a hidden
// <audio id="tf-audio"> (a data: URI, or a relative reference with ExportAudio::Reference) that
// starts at the clip's offset in the animation: before it (a lead-in) and after it the animation
// runs on its own clock, while it plays the audio is the clock and the animation is put back on
// it whenever they drift apart by more than 40 ms (checked on every animation frame). Seeking
// moves both. Space plays and pauses, the arrow keys step a second, a click on the drawing plays
// and pauses. `window.toonfacePlayer` offers play(), pause(), seek(seconds) and time() to a page
// that embeds the player. Returns an empty array and sets *error as exportSmilSvg() does.
QByteArray exportHtmlPlayer(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options = {}, QString *error = nullptr);

} // namespace toonface
