#pragma once

// The landmark model's cache: the predictor's flat arrays (LandmarkPredictor::flat()) written
// once to the cache folder (cachefile.h), so that later processes map the file instead of
// parsing dlib's 100 MB model (about 0.9 s) again. The cache is keyed by the model file's
// size, modification time and a checksum of its first and last mebibyte: a cache of another
// model, or a damaged one, is made again, never used.

#include "detect/cachefile.h"
#include "detect/landmarkpredictor.h"

#include <QString>

#include <functional>
#include <memory>

namespace toonface {

struct LandmarkModelLoad
{
    using Cache = CacheUse;

    std::shared_ptr<const LandmarkPredictor> model; // nullptr: error says why
    QString error; // names the model file and the problem
    Cache cache = Cache::Off;
    QString cachePath; // the cache file used or written
    // Why the cache was not used (missing, made from another model, damaged: how) and, with
    // NotWritten, why it could not be written.
    QString cacheNote;
    double ms = 0; // wall time of the whole load
    // With CacheWrite::Later and a cache to (re)write: the writing, for the caller to run once
    // it has handed the model on (cache is Built until then; the writing sets cache and
    // cacheNote to how it went). Empty otherwise.
    std::function<void(LandmarkModelLoad *)> writeCache;
};

enum class CacheWrite {
    Now, // before loadLandmarkModel() returns
    Later, // by the caller, through LandmarkModelLoad::writeCache
};

// The cache file of the model at `modelPath` in `cacheDir`: one per model path.
QString landmarkCachePath(const QString &modelPath, const QString &cacheDir);

// The model at `modelPath`, from its cache in `cacheDir` when that cache was made from this
// very file and is whole; otherwise read from the file, and its cache (re)written. An empty
// `cacheDir` uses no cache. Thread-safe: loads in several threads or processes at once each
// get a model, and leave one good cache file.
LandmarkModelLoad loadLandmarkModel(
    const QString &modelPath, const QString &cacheDir, CacheWrite write = CacheWrite::Now);

} // namespace toonface
