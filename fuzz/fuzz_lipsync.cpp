// Mouth tracks from other lip-sync programs: Rhubarb's TSV and JSON, Papagayo's .pgo and Moho's
// switch .dat. The first byte picks the format. A track read keeps LipSyncTrack's promise
// (finite cues, sorted, not overlapping, end > start) and writes back to a file that reads.

#include "fuzzinput.h"

#include "io/lipsyncformats.h"

#include <cmath>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const fuzz::Split in = fuzz::split(data, size);
    static constexpr LipSyncFormat kFormats[]
        = {LipSyncFormat::RhubarbTsv, LipSyncFormat::RhubarbJson, LipSyncFormat::Papagayo, LipSyncFormat::MohoSwitch};
    const LipSyncFormat format = kFormats[in.selector % 4];
    QString error;
    const auto track = parseLipSync(fuzz::bytes(in.data, in.size), format, QStringLiteral("input"), {}, &error);
    if (!track) {
        TOONFACE_FUZZ_CHECK(error.startsWith(QStringLiteral("input")));
        return 0;
    }
    double previousEnd = -INFINITY;
    for (const MouthCue &cue : track->cues) {
        TOONFACE_FUZZ_CHECK(std::isfinite(cue.start) && std::isfinite(cue.end));
        TOONFACE_FUZZ_CHECK(cue.end > cue.start && cue.start >= previousEnd);
        previousEnd = cue.end;
    }
    TOONFACE_FUZZ_CHECK(std::isfinite(track->duration));
    const QByteArray written = writeLipSync(*track, format);
    TOONFACE_FUZZ_CHECK(parseLipSync(written, format, QStringLiteral("written"), {}, &error).has_value());
    return 0;
}
