#include "benchmark.h"

#include "document/document.h"
#include "face/averageface.h"
#include "playback/playhead.h"
#include "render/style.h"
#include "speech/lipsync.h"
#include "speech/syllableshapes.h"
#include "speech/waveformpeaks.h"
#include "timeline/timelineview.h"

#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace toonface;

namespace {

constexpr double kTenMinutes = 600;

// The median CPU time of `fn` on this thread, in milliseconds. The machine is shared: wall
// time (medianMs) counts the time other processes held the cores, CPU time only the work.
double medianCpuMs(const std::function<void()> &fn, int runs)
{
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        timespec a {}, b {};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
        fn();
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
        times.push_back((b.tv_sec - a.tv_sec) * 1e3 + (b.tv_nsec - a.tv_nsec) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

// Speech-like noise: loud syllables, quiet gaps, seeded.
Audio tenMinutesOfSound()
{
    Audio audio;
    QRandomGenerator random(11);
    audio.samples.resize(qsizetype(kTenMinutes * audio.sampleRate));
    for (qsizetype i = 0; i < audio.samples.size(); ++i) {
        const double t = double(i) / audio.sampleRate;
        const double envelope = 0.05 + 0.6 * std::max(0.0, std::sin(2 * M_PI * 2 * t));
        audio.samples[i] = float((random.generateDouble() * 2 - 1) * envelope);
    }
    return audio;
}

// Ten minutes of Mandarin speech on the timeline: four syllables a second in phrases of eight
// with a pause after each, their mouth keys, an emotion every ten seconds, blinks, head shakes.
Project tenMinuteProject(const QString &audioPath)
{
    static const char *const pinyin[] = {"ni", "hao", "ma", "ming", "tian", "jian", "xie", "guang", "zhou", "bao",
        "dao", "hou", "cheng", "wei", "le", "she", "hui", "re", "dian", "yun"};
    Project project;
    project.face = averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
    project.style = Style::preset(QStringLiteral("normal"));
    double t = 0.3;
    int n = 0;
    while (t < kTenMinutes - 1) {
        const QString p = QString::fromLatin1(pinyin[n % 20]);
        const double length = 0.22 + 0.06 * ((n * 7) % 5) / 4.0;
        project.syllables.append({p, p, 1, t, t + length, 0.9, syllableShapeKeys(syllableShapes(p), t, length)});
        t += length;
        if (++n % 8 == 0)
            t += 0.4;
    }
    Timeline &tl = project.timeline;
    tl.addMouthCues(mouthCues(project.syllables, kTenMinutes));
    for (double s = 0; s < kTenMinutes; s += 10)
        tl.addEmotionClip({s + 1, s + 7, Emotion(int(s / 10) % 5), 0.8, 0.4, 0.6});
    tl.generateBlinks(5, kTenMinutes);
    for (double s = 5; s < kTenMinutes; s += 20)
        tl.addShake(s, s + 1.5);
    AudioClip clip {audioPath, 0, kTenMinutes};
    clip.script = QStringLiteral("bench");
    clip.language = QStringLiteral("cmn");
    tl.setAudioClips({clip});
    return project;
}

QJsonObject benchPeaks()
{
    const Audio audio = tenMinutesOfSound();
    QJsonObject o;
    o.insert(QStringLiteral("seconds"), kTenMinutes);
    auto compute = [&]() { WaveformPeaks::compute(audio); };
    o.insert(QStringLiteral("computeMs"), bench::medianMs(compute, 3, 500));
    o.insert(QStringLiteral("computeCpuMs"), medianCpuMs(compute, 5));
    // Once, as the editor does it: decoding the file and computing the peaks.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ten-minutes.wav"));
    QString error;
    if (writeAudio(path, audio, &error)) {
        QElapsedTimer timer;
        timer.start();
        const WaveformPeaksResult result = loadWaveformPeaks(path);
        o.insert(QStringLiteral("decodeAndComputeMs"), timer.nsecsElapsed() / 1e6);
        o.insert(QStringLiteral("levels"), int(result.peaks.levels().size()));
    }
    return o;
}

QJsonObject benchPaint()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ten-minutes.wav"));
    QString error;
    if (!writeAudio(path, tenMinutesOfSound(), &error))
        return {{QStringLiteral("error"), error}};
    Document document;
    const Project project = tenMinuteProject(path);
    document.reset(project, QImage(), {}, true);
    Playhead playhead;
    playhead.setTime(300);
    TimelineView view(&document, &playhead);
    view.resize(1600, 420);
    view.show();
    view.waveform()->waitForFinished();
    QImage target(view.viewport()->size(), QImage::Format_ARGB32_Premultiplied);
    auto paint = [&]() {
        QPainter painter(&target);
        view.viewport()->render(&painter);
    };
    QJsonObject o;
    o.insert(QStringLiteral("syllables"), int(project.syllables.size()));
    o.insert(QStringLiteral("mouthKeys"), int(project.timeline.mouthKeys().size()));
    o.insert(QStringLiteral("headKeys"), int(project.timeline.headKeys().size()));
    o.insert(QStringLiteral("viewport"), QStringLiteral("%1x%2").arg(target.width()).arg(target.height()));
    view.zoomToFit();
    o.insert(QStringLiteral("zoomedOutMs"), bench::medianMs(paint, 20, 500));
    o.insert(QStringLiteral("zoomedOutCpuMs"), medianCpuMs(paint, 31));
    o.insert(QStringLiteral("zoomedOutPixelsPerSecond"), view.timelineLayout().pixelsPerSecond());
    view.setPixelsPerSecond(400, view.xOf(300));
    o.insert(QStringLiteral("zoomedInMs"), bench::medianMs(paint, 20, 500));
    o.insert(QStringLiteral("zoomedInCpuMs"), medianCpuMs(paint, 31));
    o.insert(QStringLiteral("zoomedInPixelsPerSecond"), view.timelineLayout().pixelsPerSecond());
    return o;
}

} // namespace

TOONFACE_BENCHMARK("timeline.waveformPeaks10min", benchPeaks);
TOONFACE_BENCHMARK("timeline.paint10min", benchPaint);
