#include "benchmark.h"
#include "benchtimeline.h"

#include "document/document.h"
#include "face/averageface.h"
#include "media/audiomix.h"
#include "playback/audiotrack.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "speech/audio.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>

using namespace toonface;

namespace {

constexpr double kTrackSeconds = 600.0;
constexpr int kClipRate = 44100; // a recording's usual rate: the mix is made at it

double processCpuS()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + t.tv_nsec / 1e9;
}

QString loadAverage()
{
    QFile f(QStringLiteral("/proc/loadavg"));
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readAll()).section(QLatin1Char(' '), 0, 2) : QString();
}

// Six recordings of 95-110 s, speech-like (a voiced buzz whose loudness comes and goes with
// syllables and pauses), laid over ten minutes with two of them overlapping and some trimmed:
// the mix has to decode, resample nothing, sum and limit, as a real several-clip track.
QVector<AudioClip> writeClips(const QString &folder, QString *error)
{
    std::mt19937 rng(3);
    QVector<AudioClip> clips;
    const double offsets[] = {0.0, 100.0, 190.0, 300.0, 400.0, 495.0}; // 190: overlaps the one before
    for (int c = 0; c < 6; ++c) {
        const double seconds = 95.0 + 3.0 * c;
        Audio audio;
        audio.sampleRate = kClipRate;
        audio.samples.resize(qsizetype(seconds * kClipRate));
        std::uniform_real_distribution<float> noise(-0.02f, 0.02f);
        for (qsizetype i = 0; i < audio.samples.size(); ++i) {
            const double t = double(i) / kClipRate;
            const double syllable = std::max(0.0, std::sin(2 * M_PI * 4.0 * t)) * (std::fmod(t, 3.0) < 2.4 ? 1 : 0);
            audio.samples[i] = float(0.3 * syllable * std::sin(2 * M_PI * (110.0 + 20 * c) * t)) + noise(rng);
        }
        const QString path = folder + QStringLiteral("/clip%1.wav").arg(c);
        if (!writeAudio(path, audio, error))
            return {};
        AudioClip clip(path, offsets[c], seconds);
        if (c % 2 == 1) {
            clip.trimIn = 1.5;
            clip.trimOut = 2.0;
        }
        clips.append(clip);
    }
    return clips;
}

// A sound device that plays nothing: its position runs with the wall clock, so the controller
// plays as with a real one.
class SilentTrack : public AudioTrack
{
public:
    bool open(const QString &, QString *) override { return true; }
    void play(double seconds) override
    {
        m_from = seconds;
        m_clock.start();
    }
    void pause() override { m_clock.invalidate(); }
    bool isPlaying() const override { return m_clock.isValid(); }
    std::optional<double> position() const override
    {
        if (!m_clock.isValid())
            return std::nullopt;
        return m_from + m_clock.nsecsElapsed() / 1e9;
    }

private:
    double m_from = 0;
    QElapsedTimer m_clock;
};

// Mixing a ten-minute track of six clips (two overlapping, three trimmed), 44.1 kHz:
// - `mix`: trackSoundFile() alone as Play makes it (decode, sum, limit, write the WAV), best of
//   three, in CPU-seconds of the process and wall seconds;
// - `play`: Play pressed on the editor's controller with that track (a silent device): how long
//   play() holds the GUI thread, the longest the event loop waits between two turns while the
//   mix runs in the background (a 5 ms timer's late ticks), the frames the playhead advanced
//   before the sound joined, and the wall time until it did (soundReady()).
QJsonObject benchPlaybackMix()
{
    QJsonObject out;
    QTemporaryDir dir;
    QString error;
    const QVector<AudioClip> clips = writeClips(dir.path(), &error);
    if (clips.isEmpty()) {
        out.insert(QStringLiteral("error"), error);
        return out;
    }
    out.insert(QStringLiteral("clips"), int(clips.size()));
    out.insert(QStringLiteral("trackSeconds"), kTrackSeconds);
    out.insert(QStringLiteral("sampleRate"), kClipRate);
    out.insert(QStringLiteral("loadAverageBefore"), loadAverage());

    double bestCpu = 1e9, bestWall = 1e9;
    for (int run = 0; run < 3; ++run) {
        QTemporaryDir mixDir;
        const double cpu0 = processCpuS();
        QElapsedTimer wall;
        wall.start();
        const std::optional<TrackSound> sound = trackSoundFile(clips, mixDir.path(), QStringLiteral("mix.wav"), &error);
        const double wallS = wall.nsecsElapsed() / 1e9;
        const double cpuS = processCpuS() - cpu0;
        if (!sound || !sound->mixed) {
            out.insert(QStringLiteral("error"), sound ? QStringLiteral("the track was not mixed") : error);
            return out;
        }
        out.insert(QStringLiteral("mixedSeconds"), std::round(sound->duration * 10) / 10);
        bestCpu = std::min(bestCpu, cpuS);
        bestWall = std::min(bestWall, wallS);
    }
    QJsonObject mix;
    mix.insert(QStringLiteral("cpuS"), std::round(bestCpu * 1000) / 1000);
    mix.insert(QStringLiteral("wallS"), std::round(bestWall * 1000) / 1000);
    out.insert(QStringLiteral("mix"), mix);

    Document document;
    Project project;
    project.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    project.style = Style::preset(QStringLiteral("normal"));
    project.timeline = bench::tenMinuteTimeline();
    project.timeline.setAudioClips(clips);
    document.reset(project, QImage(), {}, true);
    Playhead playhead;
    PlaybackController controller(&document, &playhead);
    controller.setAudioTrack(std::make_unique<SilentTrack>());

    QElapsedTimer sinceTick;
    double longestGapMs = 0;
    QTimer ticker;
    ticker.setInterval(5);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        longestGapMs = std::max(longestGapMs, sinceTick.nsecsElapsed() / 1e6);
        sinceTick.restart();
    });
    int framesBeforeSound = 0;
    QObject::connect(&playhead, &Playhead::timeChanged, [&] { ++framesBeforeSound; });
    QEventLoop loop;
    QObject::connect(&controller, &PlaybackController::soundReady, &loop, &QEventLoop::quit);
    QTimer::singleShot(120000, &loop, &QEventLoop::quit); // a mix that never ends says so below

    ticker.start();
    sinceTick.start();
    QElapsedTimer untilSound;
    untilSound.start();
    controller.play();
    const double playCallMs = untilSound.nsecsElapsed() / 1e6;
    const bool mixing = controller.isMixing();
    loop.exec();
    const double soundMs = untilSound.nsecsElapsed() / 1e6;
    ticker.stop();
    controller.pause();

    QJsonObject play;
    play.insert(QStringLiteral("playCallMs"), std::round(playCallMs * 10) / 10);
    play.insert(QStringLiteral("mixedInBackground"), mixing);
    play.insert(QStringLiteral("longestEventLoopGapMs"), std::round(longestGapMs * 10) / 10);
    play.insert(QStringLiteral("framesBeforeSound"), framesBeforeSound);
    play.insert(QStringLiteral("soundJoinedAfterMs"), std::round(soundMs));
    play.insert(QStringLiteral("hasSound"), controller.hasSound());
    out.insert(QStringLiteral("play"), play);
    out.insert(QStringLiteral("loadAverageAfter"), loadAverage());
    return out;
}

} // namespace

TOONFACE_BENCHMARK("playback.mix", benchPlaybackMix);
