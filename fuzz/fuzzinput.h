#pragma once

// What the fuzz targets share: the input as Qt types, and a scratch file for readers that take
// a path. Each target defines LLVMFuzzerTestOneInput; in a TOONFACE_FUZZ build libFuzzer drives
// it, in an ordinary build corpusrunner.cpp runs it over the seed corpus and the inputs that
// once failed (fuzz/corpus/<target>/, fuzz/regressions/<target>/), as a ctest test.

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <cstddef>
#include <cstdint>

namespace toonface::fuzz {

inline QByteArray bytes(const uint8_t *data, size_t size)
{
    return QByteArray(reinterpret_cast<const char *>(data), qsizetype(size));
}

// Writes the input to one file of this process's scratch folder (named `fileName`, so readers
// that look at the extension see the one they expect) and returns its path.
inline QString scratchFile(const uint8_t *data, size_t size, const QString &fileName)
{
    static QTemporaryDir dir(QDir::tempPath() + QStringLiteral("/toonface-fuzz-XXXXXX"));
    const QString path = dir.filePath(fileName);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        qFatal("fuzz: cannot write the scratch file %s", qPrintable(path));
    file.write(reinterpret_cast<const char *>(data), qint64(size));
    return path;
}

// The first byte picks a variant (language, format, tier), the rest is the input.
struct Split
{
    uint8_t selector = 0;
    const uint8_t *data = nullptr;
    size_t size = 0;
};

inline Split split(const uint8_t *data, size_t size)
{
    if (size == 0)
        return {};
    return {data[0], data + 1, size - 1};
}

// A failed property: abort, so that libFuzzer keeps the input and the corpus test fails.
#define TOONFACE_FUZZ_CHECK(condition)                                                                                 \
    do {                                                                                                               \
        if (!(condition))                                                                                              \
            qFatal("fuzz check failed: %s (%s:%d)", #condition, __FILE__, __LINE__);                                   \
    } while (false)

} // namespace toonface::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
