// A recording as lip sync reads it (loadAudio through FFmpeg: any container and codec, resampled
// to mono at kSpeechSampleRate). Samples read are finite; a refused file is named.

#include "fuzzinput.h"

#include "speech/audio.h"

#include <cmath>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString path = fuzz::scratchFile(data, size, QStringLiteral("input.sound"));
    const AudioResult result = loadAudio(path);
    if (!result.ok()) {
        TOONFACE_FUZZ_CHECK(result.error.contains(path));
        return 0;
    }
    TOONFACE_FUZZ_CHECK(result.audio.sampleRate == kSpeechSampleRate);
    for (const float s : result.audio.samples)
        TOONFACE_FUZZ_CHECK(std::isfinite(s));
    return 0;
}
