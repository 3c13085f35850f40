#include "playbackfixture.h"
#include "pulseserver.h"
#include "testmain.h"
#include "uifixture.h"

#include "capture/microphone.h"
#include "playback/playbackcontroller.h"
#include "playback/playhead.h"
#include "speech/audio.h"

#include <QElapsedTimer>
#include <QMediaDevices>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>
#include <optional>

using namespace toonface;

namespace {

// Sound with a 0.3 s tone at each whole second from 1 s on and silence between: when the
// speaker sounds a tone tells which second of the file it is playing.
Audio beeps(double seconds)
{
    Audio out;
    out.sampleRate = 16000;
    out.samples.resize(int(seconds * out.sampleRate));
    for (int i = 0; i < out.samples.size(); ++i) {
        const double t = double(i) / out.sampleRate;
        if (t >= 1.0 && t - std::floor(t) < 0.3)
            out.samples[i] = 0.4f * float(std::sin(2 * std::numbers::pi * 660.0 * t));
    }
    return out;
}

} // namespace

// Playback on a machine with speakers: a private PulseAudio server gives an output device (so the
// controller runs on the sound's clock through QMediaPlayer, not the wall clock) and a
// microphone that hears it, so the test can tell when each part of the sound came out.
class TestPlaybackDevice : public QObject
{
    Q_OBJECT

    testing::PulseServer m_server;
    QString m_skip;
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        m_skip = m_server.start(); // before QtMultimedia looks for devices
    }

    // Playing from 1.5 s: the tones come out of the speaker when the playhead reaches their
    // seconds (not the one at 1 s: the sound starts where the playhead is), the picture never
    // steps back (this server's sink takes about a second to start and reports 0.6 s of
    // latency: the picture waits for it), and pausing silences it.
    void soundComesOutWithThePicture()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        QVERIFY(!QMediaDevices::audioOutputs().isEmpty());
        const QString path = m_dir.filePath(QStringLiteral("beeps.wav"));
        QString error;
        QVERIFY2(writeAudio(path, beeps(4.0), &error), qPrintable(error));
        Document document;
        fixture::fill(document);
        Timeline timeline = fixture::talkingTimeline(4.0);
        timeline.setAudioClips({AudioClip {path, 0.0, 4.0}});
        fixture::setTimeline(document, timeline);
        Playhead playhead;
        PlaybackController controller(&document, &playhead);
        QVERIFY2(controller.hasSound(), qPrintable(controller.soundProblem()));

        QElapsedTimer wall;
        wall.start();
        // The playhead's time against the wall clock, and when each loud 10 ms of sound was heard.
        QVector<std::pair<double, double>> picture; // (wall s, playhead s)
        connect(&playhead, &Playhead::timeChanged, this, [&](double t) {
            picture.append({wall.nsecsElapsed() / 1e9, t});
        });
        QVector<double> loudAt; // wall seconds
        Microphone microphone;
        connect(&microphone, &Microphone::samples, this, [&](const QVector<float> &mono, int rate) {
            const double arrived = wall.nsecsElapsed() / 1e9;
            const int hop = rate / 100;
            for (qsizetype i = 0; i + hop <= mono.size(); i += hop) {
                double sum = 0;
                for (int k = 0; k < hop; ++k)
                    sum += double(mono[i + k]) * mono[i + k];
                if (sum / hop > 0.01 * 0.01) // louder than -40 dBFS
                    loudAt.append(arrived - double(mono.size() - i) / rate);
            }
        });
        QVERIFY2(microphone.start(&error), qPrintable(error));
        QTest::qWait(300); // the player loads the file

        playhead.setTime(1.5);
        const double started = wall.nsecsElapsed() / 1e9;
        controller.play();
        QTest::qWait(3000);
        controller.pause();
        const double paused = wall.nsecsElapsed() / 1e9;
        QTest::qWait(700);
        microphone.stop();

        QVERIFY2(controller.soundProblem().isEmpty(), qPrintable(controller.soundProblem()));
        // The picture never stepped back while it played.
        for (qsizetype i = 1; i < picture.size(); ++i)
            QVERIFY2(picture[i].second >= picture[i - 1].second,
                qPrintable(QStringLiteral("%1 -> %2").arg(picture[i - 1].second).arg(picture[i].second)));
        // Each tone heard (its onset: loud after 0.5 s of quiet): where was the playhead then?
        QStringList offsets;
        int tones = 0;
        double previous = started;
        for (double t : loudAt) {
            const bool onset = t - previous > 0.5;
            previous = t;
            if (!onset || t > paused)
                continue;
            double playheadThen = -1;
            for (const auto &[w, p] : picture) {
                if (w <= t)
                    playheadThen = p;
            }
            const double tone = std::round(playheadThen); // the tones start on whole seconds
            const double offset = playheadThen - tone; // > 0: the sound came out after the picture
            offsets << QStringLiteral("%1 s: %2 ms").arg(tone).arg(std::round(offset * 1000));
            QVERIFY2(tone >= 2, qPrintable(QString::number(playheadThen))); // not the tone before the start
            // The microphone hears through the server's own buffers (a few hundred ms with a null
            // sink): a sound far ahead of the picture, or a second behind it, is wrong here.
            QVERIFY2(offset > -0.1 && offset < 0.5, qPrintable(offsets.join(QStringLiteral(", "))));
            ++tones;
        }
        qInfo("tones heard, sound after picture (microphone latency included): %s; %d re-syncs, largest "
              "slewed error %.1f ms",
            qPrintable(offsets.join(QStringLiteral(", "))), controller.audioResyncs(),
            controller.maxAudioError() * 1000);
        QVERIFY2(tones >= 1, "the speaker sounded nothing the microphone heard");
        // Paused: silent (allowing for what was already on its way).
        for (double t : loudAt)
            QVERIFY2(t < paused + 0.3, qPrintable(QString::number(t - paused)));
    }
};

TOONFACE_TEST_MAIN(TestPlaybackDevice)
#include "tst_playbackdevice.moc"
