#include "detect/cachefile.h"

#include "i18n/coretext.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryFile>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <new>
#include <system_error>

namespace toonface {

namespace {

constexpr char kMagic[8] = {'T', 'O', 'O', 'N', 'F', 'A', 'C', 'E'};
constexpr quint32 kVersion = 1;
constexpr quint32 kByteOrderTag = 0x01020304;
constexpr size_t kAlignment = 64;
// A temporary file older than this was left by a writer that died: removed by the next one.
constexpr qint64 kStaleTemporarySeconds = 3600;

// The header before the block; its size keeps the block on a 64-byte boundary of the file (and
// so of its mapping).
struct Header
{
    char magic[8];
    quint32 version;
    quint32 headerBytes;
    quint32 byteOrder;
    char kind[4];
    quint64 keySize;
    qint64 keyTime;
    quint64 keyChecksum;
    quint64 blockBytes;
    quint64 blockChecksum;
};
static_assert(sizeof(Header) == kAlignment);

// Leftovers of writers that died before renaming their file.
void removeStaleTemporaries(const QString &path)
{
    const QFileInfo target(path);
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QFileInfoList temporaries = target.absoluteDir().entryInfoList(
        {target.fileName() + QStringLiteral(".*.tmp")}, QDir::Files | QDir::Hidden);
    for (const QFileInfo &t : temporaries) {
        if (t.lastModified().secsTo(now) > kStaleTemporarySeconds)
            QFile::remove(t.absoluteFilePath());
    }
}

} // namespace

QString detectionCacheDir()
{
    const QString env = qEnvironmentVariable("TOONFACE_CACHE_DIR");
    if (!env.isEmpty())
        return env;
    const QString base = QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation);
    return base.isEmpty() ? QString() : QDir(base).filePath(QStringLiteral("toonface"));
}

// A Fletcher sum over 32-bit words in eight interleaved lanes, which the compiler turns into
// vector additions, so that a 65 MB block is checked at about the speed memory is read; then
// the lanes mixed into one word.
quint64 cacheChecksum(std::span<const std::byte> bytes)
{
    constexpr int kLanes = 8;
    quint64 sum[kLanes] = {}, sumOfSums[kLanes] = {};
    const size_t blocks = bytes.size() / (kLanes * sizeof(quint32));
    for (size_t b = 0; b < blocks; ++b) {
        quint32 w[kLanes];
        std::memcpy(w, bytes.data() + b * sizeof w, sizeof w);
        for (int k = 0; k < kLanes; ++k) {
            sum[k] += w[k];
            sumOfSums[k] += sum[k];
        }
    }
    auto mix = [](quint64 h, quint64 v) {
        h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdULL;
        return h ^ (h >> 33);
    };
    quint64 h = mix(0, bytes.size());
    for (int k = 0; k < kLanes; ++k)
        h = mix(mix(h, sum[k]), sumOfSums[k]);
    for (size_t i = blocks * kLanes * sizeof(quint32); i < bytes.size(); ++i)
        h = mix(h, quint64(bytes[i]));
    return h;
}

bool readCacheFile(const QString &path, const char (&kind)[5], const CacheKey &key, CachedBlock *out, QString *why)
{
    auto file = std::make_shared<QFile>(path);
    if (!file->exists()) {
        *why = DetectText::tr("there is no cache yet");
        return false;
    }
    if (!file->open(QIODevice::ReadOnly)) {
        *why = DetectText::tr("the cache could not be opened: %1").arg(file->errorString());
        return false;
    }
    const qint64 size = file->size();
    Header header {};
    if (size < qint64(sizeof header) || file->read(reinterpret_cast<char *>(&header), sizeof header) != sizeof header) {
        *why = DetectText::tr("the cache is cut short");
        return false;
    }
    if (!std::equal(std::begin(kMagic), std::end(kMagic), header.magic) || header.byteOrder != kByteOrderTag
        || header.headerBytes != sizeof header || !std::equal(kind, kind + 4, header.kind)) {
        *why = DetectText::tr("the file is not a cache of this kind");
        return false;
    }
    if (header.version != kVersion) {
        *why = DetectText::tr("the cache is of another version (%1)").arg(header.version);
        return false;
    }
    if (header.keySize != key.size || header.keyTime != key.time || header.keyChecksum != key.checksum) {
        *why = DetectText::tr("the cache was made from another model");
        return false;
    }
    if (header.blockBytes != quint64(size) - sizeof header) {
        *why = DetectText::tr("the cache is %1 bytes, not the %2 its header gives")
                   .arg(size)
                   .arg(header.blockBytes + sizeof header);
        return false;
    }
    // Mapped, the block is shared with every process using it; where mapping is not
    // possible, read in one go.
    std::shared_ptr<const void> owner = file;
    const std::byte *bytes = reinterpret_cast<const std::byte *>(file->map(0, size));
    if (bytes) {
        bytes += sizeof header;
    } else {
        auto *copy = static_cast<std::byte *>(::operator new(header.blockBytes, std::align_val_t(kAlignment)));
        owner = std::shared_ptr<std::byte>(
            copy, [](std::byte *p) { ::operator delete(p, std::align_val_t(kAlignment)); });
        if (file->read(reinterpret_cast<char *>(copy), qint64(header.blockBytes)) != qint64(header.blockBytes)) {
            *why = DetectText::tr("the cache could not be read: %1").arg(file->errorString());
            return false;
        }
        bytes = copy;
    }
    const std::span<const std::byte> block(bytes, header.blockBytes);
    if (cacheChecksum(block) != header.blockChecksum) {
        *why = DetectText::tr("the cache is damaged (its checksum does not match)");
        return false;
    }
    *out = {owner, block};
    return true;
}

bool writeCacheFile(
    const QString &path, const char (&kind)[5], const CacheKey &key, std::span<const std::byte> block, QString *error)
{
    const QString dir = QFileInfo(path).absolutePath();
    if (!QDir().mkpath(dir)) {
        *error = DetectText::tr("the folder %1 could not be made").arg(dir);
        return false;
    }
    removeStaleTemporaries(path);
    Header header {};
    std::copy(std::begin(kMagic), std::end(kMagic), header.magic);
    header.version = kVersion;
    header.headerBytes = sizeof header;
    header.byteOrder = kByteOrderTag;
    std::copy(kind, kind + 4, header.kind);
    header.keySize = key.size;
    header.keyTime = key.time;
    header.keyChecksum = key.checksum;
    header.blockBytes = block.size();
    header.blockChecksum = cacheChecksum(block);

    QTemporaryFile temporary(path + QStringLiteral(".XXXXXX.tmp"));
    if (!temporary.open()) {
        *error = DetectText::tr("%1 could not be written: %2").arg(path, temporary.errorString());
        return false;
    }
    if (temporary.write(reinterpret_cast<const char *>(&header), sizeof header) != sizeof header
        || temporary.write(reinterpret_cast<const char *>(block.data()), qint64(block.size())) != qint64(block.size())
        || !temporary.flush()) {
        *error = DetectText::tr("%1 could not be written: %2").arg(path, temporary.errorString());
        return false;
    }
    temporary.close();
    // rename() replaces the target in one step, so that a reader maps either the old file or
    // the new one; QFile::rename would refuse an existing target.
    std::error_code ec;
    std::filesystem::rename(
        QFile::encodeName(temporary.fileName()).toStdString(), QFile::encodeName(path).toStdString(), ec);
    if (ec) {
        *error = DetectText::tr("%1 could not be written: %2").arg(path, QString::fromLocal8Bit(ec.message()));
        return false;
    }
    temporary.setAutoRemove(false);
    return true;
}

} // namespace toonface
