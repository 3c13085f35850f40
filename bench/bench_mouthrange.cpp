#include "benchmark.h"

#include "media/mediareader.h"
#include "track/clipsilence.h"
#include "track/mouthrange.h"
#include "track/neutralchoice.h"
#include "track/trackaccuracy.h"
#include "track/trackvideo.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <optional>
#include <set>

using namespace toonface;

namespace {

constexpr int kSoundRate = 16000;

double processCpuMs()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

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

// The word times of a GRID clip (its .align beside it, units 1/25000 s): the end of the leading
// `sil` and the start of the trailing one, in seconds; nullopt without the file.
std::optional<std::pair<double, double>> alignedSilence(const QString &clip)
{
    const QString name = QFileInfo(clip).completeBaseName().section(QLatin1Char('_'), -1);
    QFile file(QFileInfo(clip).dir().filePath(name + QStringLiteral(".align")));
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    QList<QStringList> rows;
    for (const QByteArray &line : file.readAll().split('\n')) {
        const QStringList cells = QString::fromUtf8(line).simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (cells.size() == 3)
            rows.append(cells);
    }
    if (rows.size() < 2 || rows.first()[2] != QLatin1String("sil") || rows.last()[2] != QLatin1String("sil"))
        return std::nullopt;
    return std::make_pair(rows.first()[1].toDouble() / 25000.0, rows.last()[0].toDouble() / 25000.0);
}

// The first frame of speech and the first of the trailing silence (-1 when none).
std::pair<int, int> speechSpan(const QVector<bool> &silent)
{
    int first = -1, last = -1;
    for (int i = 0; i < silent.size(); ++i) {
        if (!silent[i]) {
            if (first < 0)
                first = i;
            last = i;
        }
    }
    return {first, last + 1 < silent.size() ? last + 1 : -1};
}

// Video import's silence (track/clipsilence.h) on the GRID clips: each clip's loud level and
// room (its frames' levels, dBFS: 95th and 5th percentile); for each share of the way from the
// room to the voice from 0.1 to 0.9, where the leading silence ends and the trailing one starts
// (frames), against the word times where the clip has them (swwp2s.align: the error in frames
// at either end), so that the share is chosen over all clips; and at the chosen share the
// shapes snapped in the leading silence without and with it, the whole clip's agreement
// with the sound, and the neutral frame Import Video would choose with its CPU time.
QJsonObject benchClipSilence()
{
    QJsonObject out;
    const QStringList clips = bench::gridClips();
    if (clips.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QString::fromLatin1(bench::kGridClipsAbsent));
        return out;
    }
    QJsonArray rows;
    for (const QString &path : clips) {
        QJsonObject row;
        row.insert(QStringLiteral("clip"), QFileInfo(path).fileName());
        const TrackResult raw = trackVideo(path, TrackVideoOptions {});
        Tracker tracker;
        QString error;
        const std::optional<QVector<float>> sound = readAudio(path, kSilenceSampleRate, &error);
        if (raw.status != TrackStatus::Ok || !sound || !tracker.setNeutral(raw.neutralImage, &error)) {
            row.insert(QStringLiteral("error"), raw.status != TrackStatus::Ok ? raw.error : error);
            rows.append(row);
            continue;
        }
        const double period = raw.fps > 0 ? 1.0 / raw.fps : 0.04;
        QVector<double> levels = frameLevelsDb(raw.frames, *sound, kSilenceSampleRate, period);
        std::sort(levels.begin(), levels.end());
        row.insert(QStringLiteral("loudDb"), rounded(levels[qsizetype(0.95 * double(levels.size() - 1))]));
        row.insert(QStringLiteral("roomDb"), rounded(levels[qsizetype(0.05 * double(levels.size() - 1))]));
        const auto aligned = alignedSilence(path);
        QJsonArray sweep;
        for (int percent = 10; percent <= 90; percent += 5) {
            const auto [first, trailing]
                = speechSpan(silentFrames(raw.frames, *sound, kSilenceSampleRate, period, percent / 100.0));
            QJsonObject s;
            s.insert(QStringLiteral("share"), percent / 100.0);
            s.insert(QStringLiteral("speechFrom"), first);
            s.insert(QStringLiteral("silenceFrom"), trailing);
            if (aligned) {
                s.insert(QStringLiteral("startErrorFrames"), rounded(first - aligned->first / period));
                s.insert(QStringLiteral("endErrorFrames"), rounded(trailing - aligned->second / period));
            }
            sweep.append(s);
        }
        row.insert(QStringLiteral("sweep"), sweep);

        const MouthRange range = measureMouthRange(raw.frames, widestMouthOpeningEs0(tracker));
        const QVector<bool> silent = silentFrames(raw.frames, *sound, kSilenceSampleRate, period);
        QVector<TrackedFrame> without = raw.frames, with = raw.frames;
        snapClipMouth(&without, tracker, range);
        snapClipMouth(&with, tracker, range, silent);
        QString leadWithout, leadWith;
        for (int i = 0; i < silent.size() && silent[i]; ++i) {
            leadWithout += mouthShapeName(*without[i].mouthShape);
            leadWith += mouthShapeName(*with[i].mouthShape);
        }
        row.insert(QStringLiteral("silentFrames"), int(std::count(silent.cbegin(), silent.cend(), true)));
        row.insert(QStringLiteral("leadingSilenceWithout"), leadWithout);
        row.insert(QStringLiteral("leadingSilenceWith"), leadWith);
        row.insert(QStringLiteral("without"), describe(without, *sound, period));
        row.insert(QStringLiteral("with"), describe(with, *sound, period));
        // The Import Video dialog's search for a frame at rest (track/neutralchoice.h): the
        // frame it chooses, and what it costs in CPU time (every thread of the process).
        const double cpuBefore = processCpuMs();
        const NeutralChoice choice = chooseNeutralFrame(path);
        row.insert(QStringLiteral("neutralChoiceCpuMs"), rounded(processCpuMs() - cpuBefore));
        row.insert(QStringLiteral("neutralChoiceFrame"), choice.found ? choice.frame : -1);
        row.insert(QStringLiteral("neutralChoiceSilent"), choice.silent);
        rows.append(row);
    }
    out.insert(QStringLiteral("share"), kSilenceShare);
    out.insert(QStringLiteral("load"), bench::loadAverage());
    out.insert(QStringLiteral("clips"), rows);
    return out;
}

} // namespace

TOONFACE_BENCHMARK("track.mouthShapes", benchMouthShapes);
TOONFACE_BENCHMARK("track.clipSilence", benchClipSilence);
