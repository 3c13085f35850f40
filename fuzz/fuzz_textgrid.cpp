// A Praat TextGrid (long or short text format, UTF-8 or UTF-16) as the lip-sync scoring and
// the interchange import read it. The first byte picks the tier asked for. Intervals read are
// finite and in order of their start.

#include "fuzzinput.h"

#include "io/textgrid.h"

#include <cmath>

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const fuzz::Split in = fuzz::split(data, size);
    static const QString kTiers[] = {QStringLiteral("words"), QStringLiteral("phones"), QStringLiteral("word"),
        QStringLiteral("phone"), QStringLiteral("")};
    const QString path = fuzz::scratchFile(in.data, in.size, QStringLiteral("input.TextGrid"));
    QString error;
    const QVector<TextGridInterval> tier = readTextGridTier(path, kTiers[in.selector % 5], &error);
    if (tier.isEmpty())
        return 0;
    for (const TextGridInterval &i : tier)
        TOONFACE_FUZZ_CHECK(std::isfinite(i.start) && std::isfinite(i.end));
    return 0;
}
