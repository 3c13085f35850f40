#pragma once

#include <QString>

namespace toonface {

// espeak-ng's pitch flutter follows a counter inside the library that no call resets: each
// rendering would start where the one before stopped, and the same text would sound (and
// last) a little differently depending on what was spoken before in the process. A voice
// loaded from a file that turns the flutter off renders the same every time.
//
// Writes under `dir` (once; later calls reuse the file) a voice file equal to `voice`
// ("name" or "name+variant", as espeak-ng names them) but without flutter: the base voice's
// file (found under `dataDir`/lang, any depth, the name compared case-insensitively), the
// variant's attributes (`dataDir`/voices/!v/variant), then "flutter 0". Returns its path, or
// an empty string when either file is missing or cannot be written.
QString steadyVoiceFile(const QString &voice, const QString &dataDir, const QString &dir);

} // namespace toonface
