#pragma once

// The landmark model's cache: the predictor's flat arrays (LandmarkPredictor::flat()) written
// once to the user's cache folder, so that later processes map the file instead of parsing
// dlib's 100 MB model (about 0.9 s) again.
//
// The cache file is a header and the block. The header names the model it was made from by
// its size, its modification time and a checksum of its first and last mebibyte, and holds a
// checksum of the block: a cache of another model, or one whose checksum or layout does not
// hold (cut short, overwritten, another version), is ignored and made again, never used.
// It is written to a temporary file beside it and renamed over it, so that processes
// building it at once leave one whole file, and a reader never sees a half-written one.

#include "detect/landmarkpredictor.h"

#include <QString>

#include <memory>

namespace toonface {

struct LandmarkModelLoad
{
    enum class Cache {
        Used, // the model came from its cache
        Built, // the model was read from its file and its cache written
        NotWritten, // the model was read from its file; its cache could not be written (cacheNote)
        Off, // no cache folder: the model was read from its file
    };

    std::shared_ptr<const LandmarkPredictor> model; // nullptr: error says why
    QString error; // names the model file and the problem
    Cache cache = Cache::Off;
    QString cachePath; // the cache file used or written
    // Why the cache was not used (missing, made from another model, damaged: how) and, with
    // NotWritten, why it could not be written.
    QString cacheNote;
    double ms = 0; // wall time of the whole load
};

// The cache folder: TOONFACE_CACHE_DIR when set (tests point it at a temporary folder), else
// "toonface" in the user's cache location (XDG_CACHE_HOME or ~/.cache).
QString landmarkCacheDir();

// The cache file of the model at `modelPath` in `cacheDir`: one per model path.
QString landmarkCachePath(const QString &modelPath, const QString &cacheDir);

// The model at `modelPath`, from its cache in `cacheDir` when that cache was made from this
// very file and is whole; otherwise read from the file, and its cache (re)written. An empty
// `cacheDir` uses no cache. Thread-safe: loads in several threads or processes at once each
// get a model, and leave one good cache file.
LandmarkModelLoad loadLandmarkModel(const QString &modelPath, const QString &cacheDir);

} // namespace toonface
