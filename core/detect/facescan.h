#pragma once

// dlib's HOG face detector, run on threads of its own (see facescan.cpp for why). dlib keeps
// the detector as a compressed string that takes about 0.4 s to decode; decoded once, it is
// kept in the cache folder (cachefile.h) in dlib's own serialised form, which loads in a few
// milliseconds.

#include "detect/cachefile.h"

#include <QImage>
#include <QRectF>
#include <QSize>

#include <vector>

namespace toonface {

struct FaceBox
{
    QRectF box; // in the pixels of the image scanned (of the photo, once findFaces() scales it back)
    double score = 0; // the detector's margin: 0 at its threshold
};

// The faces in `gray` (Format_Grayscale8), scanning at most `levels` levels of the detector's
// image pyramid of 5/6 steps (0: all of them, down to the smallest layer its 80-pixel window
// fits). Thread-safe: scans from several threads run side by side.
std::vector<FaceBox> scanFaces(const QImage &gray, unsigned long levels);

// How a face detector was made ready.
struct FaceDetectorLoad
{
    CacheUse cache = CacheUse::Off;
    QString cachePath;
    QString cacheNote; // why the cache was not used, or could not be written
    double ms = 0;
    // A checksum of the detector's serialised form: the same detector, the same figure.
    quint64 fingerprint = 0;
};

// Makes a face detector ready through its cache in `cacheDir` (empty: no cache), as the
// process's own is the first time it is needed; each call makes one anew.
FaceDetectorLoad loadFaceDetector(const QString &cacheDir);

// How the process's face detector was made ready; cache Off and no time before it was.
FaceDetectorLoad faceDetectorLoad();

// Does now what the first scan of an image of `size` would otherwise do on its way: decodes
// the detector (dlib keeps it as a compressed string), starts a scan thread, and scans a blank
// image of that size so that its arrays are allocated on that thread's heap.
void warmUpFaceScan(QSize size);

} // namespace toonface
