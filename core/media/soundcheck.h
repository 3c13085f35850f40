#pragma once

#include <QString>

namespace toonface {

// What a sound file's header says of its sound, and whether its samples decode where it was
// sampled.
struct SoundCheck
{
    QString error; // "<path>: <problem>"; empty when the sound is fine
    double seconds = 0; // from the header (0 when the container does not say)
    int sampleRate = 0;
    int channels = 0;
    QString codec; // "pcm_s16le", "aac", ...
    bool ok() const { return error.isEmpty(); }
};

// Checks that `path` (a sound, or a video with a sound track) holds sound that decodes, without
// decoding it all: reads the header, decodes the first packets, then seeks to the middle and
// near the end and decodes a packet there (when the container can seek). An hour of sound costs
// about what a second does, where probeMedia() decodes every packet. A file cut short inside
// the sampled stretches, or whose packets there do not decode, fails; damage elsewhere is left
// to the decoder that reads the whole sound later (mediaDamage() finds it without decoding).
SoundCheck checkSound(const QString &path);

} // namespace toonface
