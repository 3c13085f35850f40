#pragma once

// The plain-WAV probe in plain C++ (no Qt), its own small library (toonface_wavheader):
// core's sound decoding uses it, and so does toonface-cli's launcher, which decides from it,
// before any library is loaded, which program runs a lipsync command line.

#include <cstdint>
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
    std::int64_t dataOffset = 0;
    std::int64_t dataBytes = 0;
};

// Below this rate sound cannot carry speech (telephone speech is 8000 Hz); a header claiming
// less is damaged, and resampling it up to kSpeechSampleRate would make hours from kilobytes.
inline constexpr int kMinSpeechSampleRate = 4000;

// The file's layout when it is a plain PCM WAV file as above; nullopt for anything else
// (another format, a compressed or unusual WAV, a damaged header, an unreadable file). The
// path is in the file system's encoding.
std::optional<PlainWav> probePlainWav(const char *localPath);

// How long a WAV file's data chunk says its sound is, and how much of it the file holds: a
// file copied or recorded only in part keeps the header of the whole.
struct WavExtent
{
    double promisedSeconds = 0;
    double heldSeconds = 0;
};

// The extent of any RIFF WAVE file whose header gives a data length and a byte rate (whatever
// its codec); nullopt for anything else, or when the length is left open (0 or 0xffffffff, as
// a stream writes it).
std::optional<WavExtent> probeWavExtent(const char *localPath);

} // namespace toonface
