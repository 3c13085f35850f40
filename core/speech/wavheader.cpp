#include "speech/wavheader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>

namespace toonface {

namespace {

std::uint32_t le32(const unsigned char *p)
{
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

int le16(const unsigned char *p)
{
    return int(p[0]) | int(p[1]) << 8;
}

struct FileCloser
{
    void operator()(std::FILE *f) const { std::fclose(f); }
};

} // namespace

std::optional<PlainWav> probePlainWav(const char *localPath)
{
    std::unique_ptr<std::FILE, FileCloser> f(std::fopen(localPath, "rb"));
    if (!f || std::fseek(f.get(), 0, SEEK_END) != 0)
        return std::nullopt;
    const std::int64_t size = std::ftell(f.get());
    unsigned char riff[12];
    if (size < 12 || std::fseek(f.get(), 0, SEEK_SET) != 0 || std::fread(riff, 1, 12, f.get()) != 12
        || std::memcmp(riff, "RIFF", 4) != 0 || std::memcmp(riff + 8, "WAVE", 4) != 0)
        return std::nullopt;
    PlainWav w;
    bool haveFormat = false;
    std::int64_t at = 12;
    // The chunks up to "data": "fmt " first; others (LIST, fact, ...) are skipped.
    while (at + 8 <= size) {
        unsigned char head[8];
        if (std::fseek(f.get(), long(at), SEEK_SET) != 0 || std::fread(head, 1, 8, f.get()) != 8)
            return std::nullopt;
        const std::int64_t length = le32(head + 4);
        const std::int64_t body = at + 8;
        if (std::memcmp(head, "fmt ", 4) == 0) {
            unsigned char fmt[16];
            if (haveFormat || length < 16 || std::fread(fmt, 1, 16, f.get()) != 16)
                return std::nullopt;
            const int tag = le16(fmt);
            w.channels = le16(fmt + 2);
            w.sampleRate = int(le32(fmt + 4));
            w.blockAlign = le16(fmt + 12);
            w.bitsPerSample = le16(fmt + 14);
            w.floating = tag == 3;
            const bool integers = tag == 1
                && (w.bitsPerSample == 8 || w.bitsPerSample == 16 || w.bitsPerSample == 24 || w.bitsPerSample == 32);
            const bool floats = tag == 3 && w.bitsPerSample == 32;
            if (!(integers || floats) || w.channels < 1 || w.channels > 2 || w.sampleRate < kMinSpeechSampleRate
                || w.sampleRate > 384000 || w.blockAlign != w.channels * w.bitsPerSample / 8)
                return std::nullopt;
            haveFormat = true;
        } else if (std::memcmp(head, "data", 4) == 0) {
            // A data chunk of unknown length (0 or 0xffffffff, as written by a stream),
            // running past the end, or ending in a partial sample frame: FFmpeg's business.
            if (!haveFormat || length == 0 || length == 0xffffffffLL || body + length > size
                || length % w.blockAlign != 0)
                return std::nullopt;
            w.dataOffset = body;
            w.dataBytes = length;
            return w;
        }
        at = body + length + (length & 1);
    }
    return std::nullopt;
}

std::optional<WavExtent> probeWavExtent(const char *localPath)
{
    std::unique_ptr<std::FILE, FileCloser> f(std::fopen(localPath, "rb"));
    if (!f || std::fseek(f.get(), 0, SEEK_END) != 0)
        return std::nullopt;
    const std::int64_t size = std::ftell(f.get());
    unsigned char riff[12];
    if (size < 12 || std::fseek(f.get(), 0, SEEK_SET) != 0 || std::fread(riff, 1, 12, f.get()) != 12
        || std::memcmp(riff, "RIFF", 4) != 0 || std::memcmp(riff + 8, "WAVE", 4) != 0)
        return std::nullopt;
    std::int64_t byteRate = 0;
    for (std::int64_t at = 12; at + 8 <= size;) {
        unsigned char head[8];
        if (std::fseek(f.get(), long(at), SEEK_SET) != 0 || std::fread(head, 1, 8, f.get()) != 8)
            return std::nullopt;
        const std::int64_t length = le32(head + 4);
        const std::int64_t body = at + 8;
        if (std::memcmp(head, "fmt ", 4) == 0) {
            unsigned char fmt[12];
            if (length < 12 || std::fread(fmt, 1, 12, f.get()) != 12)
                return std::nullopt;
            byteRate = le32(fmt + 8);
        } else if (std::memcmp(head, "data", 4) == 0) {
            if (byteRate <= 0 || length == 0 || length == 0xffffffffLL)
                return std::nullopt;
            return WavExtent {
                double(length) / double(byteRate), double(std::min(length, size - body)) / double(byteRate)};
        }
        at = body + length + (length & 1);
    }
    return std::nullopt;
}

} // namespace toonface
