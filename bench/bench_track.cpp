#include "benchmark.h"

#include "detect/detector.h"
#include "track/facesearch.h"
#include "track/trackaccuracy.h"
#include "track/trackvideo.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QLineF>
#include <QPainter>

#include <algorithm>
#include <vector>

using namespace toonface;

namespace {

// Video tracking on the GRID clips of shared/data/video (360x288, 25 fps, 3 s each):
// - speed: frames tracked a second by trackVideo() (decoding on its own thread beside the
//   tracker, the neutral frame's detection excluded), best of three runs per clip: `fps` by the
//   wall clock, `cpuFps` by the process's CPU time (all threads summed, so the rate one core
//   alone would reach: on a machine shared with other work the wall clock says more about the
//   other work than about the tracker);
// - accuracy: per-frame mouth opening and eye aperture against the raw landmark model run on
//   every frame from the face detector's box (referenceSignals()): Pearson correlations, and
//   the reference's blinks found by the tracking (within two frames).
// Both methods: landmarks (the default) and classic (thesis ch. 6).
QJsonObject benchTrack()
{
    QJsonObject out;
    const QStringList clips = bench::gridClips();
    if (clips.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QString::fromLatin1(bench::kGridClipsAbsent));
        return out;
    }
    QJsonArray rows;
    for (const DetectionMethod method : {DetectionMethod::Landmarks, DetectionMethod::Classic}) {
        int frames = 0;
        double ms = 0, cpuMs = 0;
        double mouthSum = 0, mouthMin = 1, eyeSum = 0;
        int refBlinks = 0, found = 0, extra = 0, clipCount = 0;
        for (const QString &path : clips) {
            const QString name = QFileInfo(path).fileName();
            TrackVideoOptions options;
            options.tracker.method = method;
            TrackResult best;
            for (int run = 0; run < 3; ++run) {
                TrackResult r = trackVideo(path, options);
                if (r.status != TrackStatus::Ok) {
                    best = r;
                    break;
                }
                if (run == 0 || r.trackingCpuMs < best.trackingCpuMs)
                    best = std::move(r);
            }
            QJsonObject row;
            row.insert(QStringLiteral("clip"), name);
            row.insert(QStringLiteral("method"), detectionMethodName(method));
            if (best.status != TrackStatus::Ok) {
                row.insert(QStringLiteral("error"), best.error);
                rows.append(row);
                continue;
            }
            QString error;
            const auto reference = referenceSignals(path, &error);
            const double fps = best.frames.size() / (best.trackingMs / 1000.0);
            row.insert(QStringLiteral("frames"), int(best.frames.size()));
            row.insert(QStringLiteral("fps"), std::round(fps));
            row.insert(QStringLiteral("cpuFps"), std::round(best.frames.size() / (best.trackingCpuMs / 1000.0)));
            frames += int(best.frames.size());
            ms += best.trackingMs;
            cpuMs += best.trackingCpuMs;
            if (reference) {
                const TrackAccuracy a = compareSignals(trackedSignals(best), *reference, best.fps);
                row.insert(QStringLiteral("mouthCorrelation"), std::round(a.mouthCorrelation * 1000) / 1000);
                row.insert(QStringLiteral("eyeCorrelation"), std::round(a.eyeCorrelation * 1000) / 1000);
                row.insert(QStringLiteral("referenceBlinks"), a.referenceBlinks);
                row.insert(QStringLiteral("blinksFound"), a.blinksFound);
                row.insert(QStringLiteral("extraBlinks"), a.extraBlinks);
                mouthSum += a.mouthCorrelation;
                mouthMin = std::min(mouthMin, a.mouthCorrelation);
                eyeSum += a.eyeCorrelation;
                refBlinks += a.referenceBlinks;
                found += a.blinksFound;
                extra += a.extraBlinks;
                ++clipCount;
            }
            rows.append(row);
        }
        QJsonObject summary;
        summary.insert(QStringLiteral("fps"), ms > 0 ? std::round(frames / (ms / 1000.0)) : 0.0);
        summary.insert(QStringLiteral("cpuFps"), cpuMs > 0 ? std::round(frames / (cpuMs / 1000.0)) : 0.0);
        if (clipCount > 0) {
            summary.insert(QStringLiteral("meanMouthCorrelation"), std::round(mouthSum / clipCount * 1000) / 1000);
            summary.insert(QStringLiteral("minMouthCorrelation"), std::round(mouthMin * 1000) / 1000);
            summary.insert(QStringLiteral("meanEyeCorrelation"), std::round(eyeSum / clipCount * 1000) / 1000);
            summary.insert(QStringLiteral("blinks"),
                QStringLiteral("%1 of %2 found, %3 extra").arg(found).arg(refBlinks).arg(extra));
        }
        out.insert(detectionMethodName(method), summary);
    }
    out.insert(QStringLiteral("clips"), rows);
    out.insert(QStringLiteral("frameSize"), QStringLiteral("360x288"));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("track", benchTrack);

namespace {

// While a face is lost the classic method searches every frame for it (FaceSearch): the time
// of one search at the camera sizes the editor offers, median of 15 runs. The face is the
// scikit-image astronaut's, put at a third of the frame.
QJsonObject benchFaceSearch()
{
    QJsonObject out;
    const QString portrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
    const QImage photo(portrait);
    DetectOptions options;
    options.method = DetectionMethod::Landmarks;
    const DetectionResult r = photo.isNull() ? DetectionResult {} : detectFace(photo, options);
    if (r.status != DetectStatus::Ok) {
        out.insert(QStringLiteral("skipped"), QStringLiteral("astronaut.png (python3-skimage) is absent"));
        return out;
    }
    const QPointF l = r.face.point("3.6"), right = r.face.point("3.5");
    const double d = QLineF(l, right).length();
    const QPointF mid = (l + right) / 2;
    const FaceSearch search(photo, QRectF(mid.x() - 0.8 * d, mid.y() - 0.35 * d, 1.6 * d, 1.7 * d));
    for (const QSize size : {QSize(640, 480), QSize(1280, 720)}) {
        QImage frame(size, QImage::Format_RGB32);
        frame.fill(Qt::darkGray);
        QPainter(&frame).drawImage(QPointF(size.width() / 3.0, 0), photo);
        std::vector<double> ms;
        double likeness = 0;
        for (int run = 0; run < 15; ++run) {
            QElapsedTimer t;
            t.start();
            likeness = search.find(frame).likeness;
            ms.push_back(t.nsecsElapsed() / 1e6);
        }
        std::nth_element(ms.begin(), ms.begin() + 7, ms.end());
        QJsonObject row;
        row.insert(QStringLiteral("ms"), std::round(ms[7] * 100) / 100);
        row.insert(QStringLiteral("likeness"), std::round(likeness * 1000) / 1000);
        out.insert(QStringLiteral("%1x%2").arg(size.width()).arg(size.height()), row);
    }
    out.insert(QStringLiteral("faceEyeDistance"), std::round(d));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("track.search", benchFaceSearch);
