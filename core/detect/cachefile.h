#pragma once

// A file of detection's cache folder (detectionCacheDir()): a header, then a block of bytes
// made once from something slow to prepare (the landmark model's flat arrays, the face
// detector decoded). The header names what the block was made from by a key of three numbers
// (for a model file: its size, modification time and a checksum of its ends) and holds a
// checksum of the block: a file of another kind or key, or one whose checksum does not hold
// (cut short, overwritten, another version), is reported and not used. It is written to a
// temporary file beside it and renamed over it, so that processes writing it at once leave
// one whole file, and a reader never sees a half-written one.

#include <QString>

#include <cstddef>
#include <memory>
#include <span>

namespace toonface {

// What became of a cache when something was loaded through it.
enum class CacheUse {
    Used, // loaded from the cache
    Built, // made anew (no cache, or an unusable one: the note says why) and the cache written
    NotWritten, // made anew; the cache could not be written (the note says why)
    Off, // no cache folder: made anew
};

struct CacheKey
{
    quint64 size = 0;
    qint64 time = 0;
    quint64 checksum = 0;
    bool operator==(const CacheKey &) const = default;
};

struct CachedBlock
{
    std::shared_ptr<const void> owner; // keeps `bytes` alive (a mapping of the file, or a copy)
    std::span<const std::byte> bytes; // aligned to 64 bytes
};

// The folder: TOONFACE_CACHE_DIR when set (tests point it at a temporary folder), else
// "toonface" in the user's cache location (XDG_CACHE_HOME or ~/.cache); empty when there is
// none.
QString detectionCacheDir();

// A checksum for telling a damaged copy from a whole one (not a defence against forgery).
quint64 cacheChecksum(std::span<const std::byte> bytes);

// The block of the cache file at `path` if it is of `kind` (four characters) and was made from
// `key`; otherwise false and *why (no cache yet, made from something else, damaged: how).
bool readCacheFile(const QString &path, const char (&kind)[5], const CacheKey &key, CachedBlock *out, QString *why);

// Writes `block` as the cache file at `path`, making its folder; false and *error naming the
// file when it cannot. Removes temporary files of writers that died (older than an hour).
bool writeCacheFile(
    const QString &path, const char (&kind)[5], const CacheKey &key, std::span<const std::byte> block, QString *error);

} // namespace toonface
