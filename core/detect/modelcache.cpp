#include "detect/modelcache.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryFile>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <new>
#include <span>
#include <system_error>

namespace toonface {

namespace {

constexpr char kCacheMagic[8] = {'T', 'F', 'L', 'M', 'C', 'A', 'C', 'H'};
constexpr quint32 kCacheVersion = 1;
constexpr quint32 kByteOrderTag = 0x01020304;
// How much of each end of the model file its checksum covers: reading the whole 100 MB file
// to check it would cost more than loading the cache saves.
constexpr qint64 kSourceSample = 1 << 20;
// A temporary file older than this was left by a builder that died: removed by the next one.
constexpr qint64 kStaleTemporarySeconds = 3600;

// The header before the block; its size keeps the block on a 64-byte boundary of the file
// (and so of its mapping), as the block's own sections are.
struct CacheHeader
{
    char magic[8];
    quint32 version;
    quint32 headerBytes;
    quint32 byteOrder;
    quint32 reserved;
    quint64 sourceSize;
    qint64 sourceTime; // modification time, in the file clock's ticks (nanoseconds here)
    quint64 sourceChecksum;
    quint64 blockBytes;
    quint64 blockChecksum;
};
static_assert(sizeof(CacheHeader) == 64);

// What identifies the model file a cache was made from.
struct SourceKey
{
    quint64 size = 0;
    qint64 time = 0;
    quint64 checksum = 0;
};

// A checksum of `bytes` for telling a damaged copy from a whole one (not a defence against
// someone forging a file): a Fletcher sum over 32-bit words in eight interleaved lanes, which
// the compiler turns into vector additions, so that the 65 MB block is checked at the speed
// memory is read; then the lanes mixed into one word.
quint64 checksum(std::span<const std::byte> bytes)
{
    constexpr int kLanes = 8;
    quint64 sum[kLanes] = {}, sumOfSums[kLanes] = {};
    const size_t words = bytes.size() / sizeof(quint32);
    const size_t blocks = words / kLanes;
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

bool sourceKey(const QString &modelPath, SourceKey *key)
{
    std::error_code ec;
    const std::filesystem::path path(QFile::encodeName(modelPath).toStdString());
    const auto time = std::filesystem::last_write_time(path, ec);
    if (ec)
        return false;
    QFile file(modelPath);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    key->size = quint64(file.size());
    key->time = qint64(time.time_since_epoch().count());
    QByteArray sample = file.read(kSourceSample);
    if (file.size() > kSourceSample) {
        file.seek(std::max(kSourceSample, file.size() - kSourceSample));
        sample += file.read(kSourceSample);
    }
    key->checksum = checksum(std::as_bytes(std::span(sample.constData(), size_t(sample.size()))));
    return true;
}

// The model in the cache file at `path` made from the model named by `key`; nullptr and *why
// when there is none, or it was made from another file, or it is damaged.
std::shared_ptr<const LandmarkPredictor> readCache(const QString &path, const SourceKey &key, QString *why)
{
    auto file = std::make_shared<QFile>(path);
    if (!file->exists()) {
        *why = QStringLiteral("there is no cache yet");
        return {};
    }
    if (!file->open(QIODevice::ReadOnly)) {
        *why = QStringLiteral("the cache could not be opened: %1").arg(file->errorString());
        return {};
    }
    const qint64 size = file->size();
    CacheHeader header {};
    if (size < qint64(sizeof header) || file->read(reinterpret_cast<char *>(&header), sizeof header) != sizeof header) {
        *why = QStringLiteral("the cache is cut short");
        return {};
    }
    if (!std::equal(std::begin(kCacheMagic), std::end(kCacheMagic), header.magic) || header.byteOrder != kByteOrderTag
        || header.headerBytes != sizeof header) {
        *why = QStringLiteral("the cache is not a landmark model cache");
        return {};
    }
    if (header.version != kCacheVersion) {
        *why = QStringLiteral("the cache is of another version (%1)").arg(header.version);
        return {};
    }
    if (header.sourceSize != key.size || header.sourceTime != key.time || header.sourceChecksum != key.checksum) {
        *why = QStringLiteral("the cache was made from another model file");
        return {};
    }
    if (header.blockBytes != quint64(size) - sizeof header) {
        *why = QStringLiteral("the cache is %1 bytes, not the %2 its header gives")
                   .arg(size)
                   .arg(header.blockBytes + sizeof header);
        return {};
    }
    // Mapped, the block is shared with every process using the model; where mapping is not
    // possible, read in one go.
    std::shared_ptr<const void> owner = file;
    const std::byte *bytes = reinterpret_cast<const std::byte *>(file->map(0, size));
    if (bytes) {
        bytes += sizeof header;
    } else {
        auto *copy = static_cast<std::byte *>(::operator new(header.blockBytes, std::align_val_t(64)));
        owner = std::shared_ptr<std::byte>(copy, [](std::byte *p) { ::operator delete(p, std::align_val_t(64)); });
        if (file->read(reinterpret_cast<char *>(copy), qint64(header.blockBytes)) != qint64(header.blockBytes)) {
            *why = QStringLiteral("the cache could not be read: %1").arg(file->errorString());
            return {};
        }
        bytes = copy;
    }
    const std::span<const std::byte> block(bytes, header.blockBytes);
    if (checksum(block) != header.blockChecksum) {
        *why = QStringLiteral("the cache is damaged (its checksum does not match)");
        return {};
    }
    QString error;
    auto model = LandmarkPredictor::fromFlat(owner, block, &error);
    if (!model)
        *why = QStringLiteral("the cache is damaged (%1)").arg(error);
    return model;
}

// Leftovers of builders that died before renaming their file.
void removeStaleTemporaries(const QString &path)
{
    const QFileInfo target(path);
    const QDir dir = target.absoluteDir();
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QFileInfoList temporaries
        = dir.entryInfoList({target.fileName() + QStringLiteral(".*.tmp")}, QDir::Files | QDir::Hidden);
    for (const QFileInfo &t : temporaries) {
        if (t.lastModified().secsTo(now) > kStaleTemporarySeconds)
            QFile::remove(t.absoluteFilePath());
    }
}

// Writes the cache of `model` (made from the file `key` names) at `path`: into a temporary
// file beside it, renamed over it once whole.
bool writeCache(const QString &path, const SourceKey &key, const LandmarkPredictor &model, QString *error)
{
    if (!QDir().mkpath(QFileInfo(path).absolutePath())) {
        *error = QStringLiteral("the folder %1 could not be made").arg(QFileInfo(path).absolutePath());
        return false;
    }
    removeStaleTemporaries(path);
    const std::span<const std::byte> block = model.flat();
    CacheHeader header {};
    std::copy(std::begin(kCacheMagic), std::end(kCacheMagic), header.magic);
    header.version = kCacheVersion;
    header.headerBytes = sizeof header;
    header.byteOrder = kByteOrderTag;
    header.sourceSize = key.size;
    header.sourceTime = key.time;
    header.sourceChecksum = key.checksum;
    header.blockBytes = block.size();
    header.blockChecksum = checksum(block);

    QTemporaryFile temporary(path + QStringLiteral(".XXXXXX.tmp"));
    if (!temporary.open()) {
        *error = QStringLiteral("%1 could not be written: %2").arg(path, temporary.errorString());
        return false;
    }
    if (temporary.write(reinterpret_cast<const char *>(&header), sizeof header) != sizeof header
        || temporary.write(reinterpret_cast<const char *>(block.data()), qint64(block.size())) != qint64(block.size())
        || !temporary.flush()) {
        *error = QStringLiteral("%1 could not be written: %2").arg(path, temporary.errorString());
        return false;
    }
    temporary.close();
    // rename() replaces the target in one step, so that a reader maps either the old file or
    // the new one; QFile::rename would refuse an existing target.
    std::error_code ec;
    std::filesystem::rename(
        QFile::encodeName(temporary.fileName()).toStdString(), QFile::encodeName(path).toStdString(), ec);
    if (ec) {
        *error = QStringLiteral("%1 could not be written: %2").arg(path, QString::fromLocal8Bit(ec.message()));
        return false;
    }
    temporary.setAutoRemove(false);
    return true;
}

} // namespace

QString landmarkCacheDir()
{
    const QString env = qEnvironmentVariable("TOONFACE_CACHE_DIR");
    if (!env.isEmpty())
        return env;
    const QString base = QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation);
    return base.isEmpty() ? QString() : QDir(base).filePath(QStringLiteral("toonface"));
}

QString landmarkCachePath(const QString &modelPath, const QString &cacheDir)
{
    const QFileInfo model(modelPath);
    const QByteArray id
        = QCryptographicHash::hash(model.absoluteFilePath().toUtf8(), QCryptographicHash::Sha1).toHex().left(12);
    return QDir(cacheDir).filePath(
        model.completeBaseName() + QLatin1Char('-') + QString::fromLatin1(id) + QStringLiteral(".landmarks-cache"));
}

LandmarkModelLoad loadLandmarkModel(const QString &modelPath, const QString &cacheDir)
{
    QElapsedTimer timer;
    timer.start();
    LandmarkModelLoad load;
    auto finish = [&] {
        load.ms = timer.nsecsElapsed() / 1e6;
        return load;
    };
    SourceKey key;
    if (cacheDir.isEmpty() || !sourceKey(modelPath, &key)) {
        // No cache folder, or no model file to key a cache by (read() names the problem).
        load.model = LandmarkPredictor::read(modelPath, &load.error);
        return finish();
    }
    load.cachePath = landmarkCachePath(modelPath, cacheDir);
    load.model = readCache(load.cachePath, key, &load.cacheNote);
    if (load.model) {
        load.cache = LandmarkModelLoad::Cache::Used;
        return finish();
    }
    load.model = LandmarkPredictor::read(modelPath, &load.error);
    if (!load.model)
        return finish();
    QString writeError;
    if (writeCache(load.cachePath, key, *load.model, &writeError)) {
        load.cache = LandmarkModelLoad::Cache::Built;
    } else {
        load.cache = LandmarkModelLoad::Cache::NotWritten;
        load.cacheNote += QStringLiteral("; ") + writeError;
    }
    return finish();
}

} // namespace toonface
