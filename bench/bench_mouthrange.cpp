#include "benchmark.h"

#include "media/mediareader.h"
#include "track/mouthrange.h"
#include "track/trackaccuracy.h"
#include "track/trackvideo.h"

#include <QFileInfo>
#include <QJsonArray>

#include <cmath>
#include <set>

using namespace toonface;

namespace {

constexpr int kSoundRate = 16000;

double rounded(double v)
{
    return std::round(v * 1000) / 1000;
}

QJsonObject shapesUsed(const QVector<TrackedFrame> &frames, int *distinct)
{
    QMap<QString, int> counts;
    for (const TrackedFrame &f : frames) {
        if (f.mouthShape)
            ++counts[mouthShapeName(*f.mouthShape)];
    }
    *distinct = int(counts.size());
    QJsonObject o;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        o.insert(it.key(), it.value());
    return o;
}

QJsonObject describe(const QVector<TrackedFrame> &frames, const QVector<float> &sound, double period)
{
    int distinct = 0;
    QJsonObject o;
    o.insert(QStringLiteral("frames"), shapesUsed(frames, &distinct));
    o.insert(QStringLiteral("distinctShapes"), distinct);
    if (!sound.isEmpty()) {
        const SoundAgreement a = mouthSoundAgreement(frames, sound, kSoundRate, period);
        o.insert(QStringLiteral("soundCorrelation"), rounded(a.correlation));
        o.insert(QStringLiteral("soundCorrelationInSync"), rounded(a.correlationInSync));
        o.insert(QStringLiteral("leadFrames"), a.leadFrames);
    }
    return o;
}

// Video import's snapped mouth on every GRID clip of shared/data/video: the shapes it uses
// (how many of the nine, and how many frames each) and how its opening follows the clip's own
// sound (mouthSoundAgreement(): the lips' parting against the loudness, Pearson, at the best
// lead of the mouth over the sound up to 3 frames, and in sync). Three mouths per clip: the
// tracked one before snapping (what the shapes can at best follow), the old frame-by-frame
// snap (relative to the neutral frame 0, unscaled), and the snap over the whole clip (its own
// closed mouth and range, track/mouthrange.h).
QJsonObject benchMouthShapes()
{
    QJsonObject out;
    const QStringList clips = bench::gridClips();
    if (clips.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QString::fromLatin1(bench::kGridClipsAbsent));
        return out;
    }
    QJsonArray rows;
    double newSum = 0, oldSum = 0, rawSum = 0;
    int newShapes = 0, oldShapes = 0, counted = 0;
    for (const QString &path : clips) {
        QJsonObject row;
        row.insert(QStringLiteral("clip"), QFileInfo(path).fileName());
        TrackVideoOptions options;
        const TrackResult raw = trackVideo(path, options);
        Tracker tracker;
        QString error;
        if (raw.status != TrackStatus::Ok || !tracker.setNeutral(raw.neutralImage, &error)) {
            row.insert(QStringLiteral("error"), raw.status != TrackStatus::Ok ? raw.error : error);
            rows.append(row);
            continue;
        }
        const double period = raw.fps > 0 ? 1.0 / raw.fps : 0.04;
        const QVector<float> sound = readAudio(path, kSoundRate, &error).value_or(QVector<float>());

        QVector<TrackedFrame> old = raw.frames;
        snapClipMouth(&old, tracker, MouthRange {});
        const MouthRange range = measureMouthRange(raw.frames, widestMouthOpeningEs0(tracker));
        QVector<TrackedFrame> clip = raw.frames;
        snapClipMouth(&clip, tracker, range);

        row.insert(QStringLiteral("wideOpeningEs0"), rounded(range.wideOpeningEs0));
        row.insert(QStringLiteral("widestShapeOpeningEs0"), rounded(widestMouthOpeningEs0(tracker)));
        row.insert(QStringLiteral("gain"), rounded(range.gain));
        row.insert(QStringLiteral("closedPartingEs0"), rounded(range.closedEs0[Down].y() - range.closedEs0[Up].y()));
        QJsonObject tracked;
        if (!sound.isEmpty()) {
            const SoundAgreement a = mouthSoundAgreement(raw.frames, sound, kSoundRate, period);
            tracked.insert(QStringLiteral("soundCorrelation"), rounded(a.correlation));
            tracked.insert(QStringLiteral("soundCorrelationInSync"), rounded(a.correlationInSync));
            tracked.insert(QStringLiteral("leadFrames"), a.leadFrames);
            rawSum += a.correlation;
        }
        row.insert(QStringLiteral("tracked"), tracked);
        const QJsonObject oldRow = describe(old, sound, period);
        const QJsonObject newRow = describe(clip, sound, period);
        row.insert(QStringLiteral("frameByFrame"), oldRow);
        row.insert(QStringLiteral("wholeClip"), newRow);
        if (!sound.isEmpty()) {
            oldSum += oldRow.value(QStringLiteral("soundCorrelation")).toDouble();
            newSum += newRow.value(QStringLiteral("soundCorrelation")).toDouble();
            ++counted;
        }
        oldShapes += oldRow.value(QStringLiteral("distinctShapes")).toInt();
        newShapes += newRow.value(QStringLiteral("distinctShapes")).toInt();
        rows.append(row);
    }
    out.insert(QStringLiteral("clips"), rows);
    if (!rows.isEmpty()) {
        out.insert(QStringLiteral("meanDistinctShapesFrameByFrame"), rounded(double(oldShapes) / rows.size()));
        out.insert(QStringLiteral("meanDistinctShapesWholeClip"), rounded(double(newShapes) / rows.size()));
    }
    if (counted > 0) {
        out.insert(QStringLiteral("meanSoundCorrelationTracked"), rounded(rawSum / counted));
        out.insert(QStringLiteral("meanSoundCorrelationFrameByFrame"), rounded(oldSum / counted));
        out.insert(QStringLiteral("meanSoundCorrelationWholeClip"), rounded(newSum / counted));
    }
    return out;
}

} // namespace

TOONFACE_BENCHMARK("track.mouthShapes", benchMouthShapes);
