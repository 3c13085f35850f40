#pragma once

#include "speech/wavheader.h"

#include <QString>

#include <optional>

namespace toonface {

// The file's layout when it is a plain PCM WAV file as above; nullopt for anything else
// (another format, a compressed or unusual WAV, a damaged header, an unreadable file).
std::optional<PlainWav> probePlainWav(const QString &path);

} // namespace toonface
