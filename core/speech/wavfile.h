#pragma once

#include <QString>
#include <QtGlobal>

#include <optional>

namespace toonface {

// The layout of a WAV file that holds plain PCM: 8, 16, 24 or 32-bit integers or 32-bit floats,
// one or two channels, at a rate speech can have, with a complete data chunk. Such a file is
// decoded without FFmpeg's formats and codecs (speech/audio.h's streamAudio gives the same
// samples either way).
struct PlainWav
{
    int channels = 0;
    int sampleRate = 0;
    int bitsPerSample = 0;
    bool floating = false; // IEEE float samples (format 3), else integers (format 1)
    int blockAlign = 0; // bytes per sample frame (all channels)
    qint64 dataOffset = 0;
    qint64 dataBytes = 0;
};

// The file's layout when it is a plain PCM WAV file as above; nullopt for anything else
// (another format, a compressed or unusual WAV, a damaged header, an unreadable file).
std::optional<PlainWav> probePlainWav(const QString &path);

} // namespace toonface
