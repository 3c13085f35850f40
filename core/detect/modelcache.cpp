#include "detect/modelcache.h"

#include "i18n/coretext.h"

#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace toonface {

namespace {

constexpr char kKind[5] = "LM68";
// How much of each end of the model file its key's checksum covers: reading the whole 100 MB
// file to check it would cost more than loading the cache saves.
constexpr qint64 kSourceSample = 1 << 20;

// The model file's size, modification time (in the file clock's ticks, nanoseconds here) and
// a checksum of its first and last mebibyte.
bool sourceKey(const QString &modelPath, CacheKey *key)
{
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(QFile::encodeName(modelPath).toStdString(), ec);
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
    key->checksum = cacheChecksum(std::as_bytes(std::span(sample.constData(), size_t(sample.size()))));
    return true;
}

} // namespace

QString landmarkCachePath(const QString &modelPath, const QString &cacheDir)
{
    const QFileInfo model(modelPath);
    const QByteArray id
        = QCryptographicHash::hash(model.absoluteFilePath().toUtf8(), QCryptographicHash::Sha1).toHex().left(12);
    return QDir(cacheDir).filePath(
        model.completeBaseName() + QLatin1Char('-') + QString::fromLatin1(id) + QStringLiteral(".landmarks-cache"));
}

LandmarkModelLoad loadLandmarkModel(const QString &modelPath, const QString &cacheDir, CacheWrite write)
{
    QElapsedTimer timer;
    timer.start();
    LandmarkModelLoad load;
    auto finish = [&] {
        load.ms = timer.nsecsElapsed() / 1e6;
        return load;
    };
    CacheKey key;
    if (cacheDir.isEmpty() || !sourceKey(modelPath, &key)) {
        // No cache folder, or no model file to key a cache by (read() names the problem).
        load.model = LandmarkPredictor::read(modelPath, &load.error);
        return finish();
    }
    load.cachePath = landmarkCachePath(modelPath, cacheDir);
    CachedBlock cached;
    if (readCacheFile(load.cachePath, kKind, key, &cached, &load.cacheNote)) {
        QString damage;
        load.model = LandmarkPredictor::fromFlat(cached.owner, cached.bytes, &damage);
        if (load.model) {
            load.cache = CacheUse::Used;
            return finish();
        }
        load.cacheNote = DetectText::tr("the cache is damaged (%1)").arg(damage);
    }
    load.model = LandmarkPredictor::read(modelPath, &load.error);
    if (!load.model)
        return finish();
    // The model's block written as it is, in one write, to a temporary file renamed over the
    // cache (cachefile.h); nothing waits for it to reach the disk.
    auto writeCache = [path = load.cachePath, key, model = load.model](LandmarkModelLoad *report) {
        QString writeError;
        if (writeCacheFile(path, kKind, key, model->flat(), &writeError)) {
            report->cache = CacheUse::Built;
        } else {
            report->cache = CacheUse::NotWritten;
            report->cacheNote += QStringLiteral("; ") + writeError;
        }
    };
    load.cache = CacheUse::Built;
    if (write == CacheWrite::Later)
        load.writeCache = writeCache;
    else
        writeCache(&load);
    return finish();
}

} // namespace toonface
