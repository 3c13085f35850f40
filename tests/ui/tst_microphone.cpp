#include "pulseserver.h"
#include "testmain.h"
#include "uifixture.h"
#include "videofixture.h"

#include "capture/livesession.h"
#include "capture/livewindow.h"
#include "capture/microphone.h"
#include "document/document.h"
#include "playback/playhead.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "track/videofilesource.h"

#include <QAudioDevice>
#include <QFileInfo>
#include <QMediaDevices>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// Spoken Mandarin with a second of silence before, between two sentences and after: where
// the mouth must open and where it must shut.
Audio speechWithPauses()
{
    TtsOptions voice;
    voice.voice = QStringLiteral("cmn-latn-pinyin+f2");
    Audio out {{}, kSpeechSampleRate};
    const QVector<float> second(kSpeechSampleRate, 0.0f);
    out.samples += second;
    for (const QString &text : {QStringLiteral("今天天气很好"), QStringLiteral("我们去公园散步吧")}) {
        const Audio spoken
            = resampled(synthesize(parseScript(text, Language::Mandarin).script, voice).audio, kSpeechSampleRate);
        out.samples += spoken.samples;
        out.samples += second;
    }
    return out;
}

// Loudness (RMS, dB) every 10 ms.
QVector<double> loudness(const QVector<float> &samples, int rate)
{
    const int hop = rate / 100;
    QVector<double> out;
    for (qsizetype i = 0; i + hop <= samples.size(); i += hop) {
        double sum = 0;
        for (int k = 0; k < hop; ++k)
            sum += double(samples[i + k]) * samples[i + k];
        out.append(10 * std::log10(sum / hop + 1e-10));
    }
    return out;
}

double correlation(const QVector<double> &a, const QVector<double> &b, int shift, int length)
{
    double ma = 0, mb = 0;
    for (int i = 0; i < length; ++i) {
        ma += a[i];
        mb += b[i + shift];
    }
    ma /= length;
    mb /= length;
    double ab = 0, aa = 0, bb = 0;
    for (int i = 0; i < length; ++i) {
        ab += (a[i] - ma) * (b[i + shift] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i + shift] - mb) * (b[i + shift] - mb);
    }
    return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0;
}

} // namespace

// The microphone through a real sound server: PulseAudio with a speaker whose sound the
// microphone hears, so what the tests play is what the microphone records.
class TestMicrophone : public QObject
{
    Q_OBJECT

    testing::PulseServer m_server;
    QString m_skip;
    QTemporaryDir m_dir;
    QString m_speech;
    Audio m_played;

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        m_skip = m_server.start(); // before QtMultimedia looks for devices
        if (!m_skip.isEmpty())
            return;
        m_played = speechWithPauses();
        QVERIFY(m_played.duration() > 4);
        m_speech = m_dir.filePath(QStringLiteral("speech.wav"));
        QString error;
        QVERIFY2(writeAudio(m_speech, m_played, &error), qPrintable(error));
    }

    void findsTheMicrophoneByItsName()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        QVERIFY(Microphone::isPresent());
        QCOMPARE(QMediaDevices::defaultAudioInput().description(),
            QString::fromLatin1(testing::PulseServer::kMicrophoneDescription));
    }

    // What the microphone delivers is the sound in the room: its loudness over time follows the
    // speech played, from the first word to the pauses.
    void hearsWhatIsPlayed()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        Microphone microphone;
        QVector<float> heard;
        int rate = 0;
        connect(&microphone, &Microphone::samples, this, [&](const QVector<float> &mono, int sampleRate) {
            heard += mono;
            rate = sampleRate;
        });
        QString error;
        QVERIFY2(microphone.start(&error), qPrintable(error));
        QVERIFY(microphone.isActive());
        QProcess player;
        testing::PulseServer::play(player, m_speech);
        QVERIFY(player.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(player.state() == QProcess::NotRunning, 20000);
        QCOMPARE(player.exitCode(), 0);
        QTest::qWait(500);
        microphone.stop();
        QVERIFY(rate > 0);
        const Audio got = resampled(Audio {heard, rate}, kSpeechSampleRate);
        QVERIFY2(got.duration() >= m_played.duration(), qPrintable(QString::number(got.duration())));
        const QVector<double> played = loudness(m_played.samples, kSpeechSampleRate);
        const QVector<double> recorded = loudness(got.samples, kSpeechSampleRate);
        // The recording starts before the player: find the delay (up to 2 s) where they match.
        double best = -1;
        for (int shift = 0; shift <= 200 && shift + played.size() <= recorded.size(); ++shift)
            best = std::max(best, correlation(played, recorded, shift, int(played.size())));
        qInfo("microphone loudness against the speech played: r = %.3f", best);
        QVERIFY2(best > 0.9, qPrintable(QString::number(best)));
    }

    // Live mode with the mouth from the microphone: while the speech plays the cartoon's mouth
    // opens, in the pauses it shuts, and a take keeps the microphone's sound.
    void microphoneDrivesTheLiveMouth()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        bool skipped = false;
        const QString clip = m_dir.filePath(QStringLiteral("face.mp4"));
        const QString written = videofixture::writeTalkingClip(clip, false, &skipped);
        if (skipped)
            QSKIP("the portrait the drawn face is drawn on is not installed");
        QVERIFY2(written.isEmpty(), qPrintable(written));
        Document document;
        fixture::fill(document);
        LiveSession session(&document);
        session.setImageSize(QSize(160, 160));
        session.setMouthMode(LiveMouth::Microphone);
        Microphone microphone;
        connect(&microphone, &Microphone::samples, this,
            [&](const QVector<float> &mono, int rate) { session.pushAudio(mono.constData(), mono.size(), rate); });
        QString error;
        QVERIFY2(microphone.start(&error), qPrintable(error));

        // The face in view for as long as the speech lasts: the drawn clip, slowed down.
        auto source = std::make_unique<VideoFileSource>();
        VideoFileSource::Options options;
        options.paced = true;
        options.speed = videofixture::kTalkingFrames / videofixture::kFps / (m_played.duration() + 1.0);
        QVERIFY2(source->open(clip, options, &error), qPrintable(error));
        QVector<WeightedShape> mouths;
        connect(&session, &LiveSession::frameReady, this, [&] {
            const LiveFrame &f = session.current();
            QVERIFY(f.soundDrivesMouth);
            mouths.append(f.sound);
        });
        QSignalSpy finished(&session, &LiveSession::finished);
        session.start(std::move(source));
        session.startRecording();
        QProcess player;
        testing::PulseServer::play(player, m_speech);
        QVERIFY(finished.wait(30000));
        const LiveTake take = session.stopRecording();
        player.waitForFinished(20000);
        microphone.stop();
        int open = 0, shut = 0;
        for (const WeightedShape &m : mouths)
            (m.shape == MouthShape::M || m.weight < 0.1 ? shut : open) += 1;
        qInfo("microphone-driven mouth: %d open, %d shut of %lld frames", open, shut, qlonglong(mouths.size()));
        QVERIFY2(open >= mouths.size() / 5, qPrintable(QString::number(open)));
        QVERIFY2(shut >= mouths.size() / 5, qPrintable(QString::number(shut)));
        QVERIFY(take.audio.duration() > m_played.duration() * 0.8);
        const QVector<double> level = loudness(take.audio.samples, take.audio.sampleRate);
        QVERIFY(*std::max_element(level.begin(), level.end()) > -30); // the speech, not silence
    }

    // Live mode with no camera, as here: "Microphone only" makes the voice the performer. The
    // cartoon speaks while the speech plays, and Record puts the mouth and the sound on the
    // timeline in one undo step.
    void microphoneOnlyPerformance()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        QTemporaryDir dir;
        Document document;
        fixture::fill(document, dir.filePath(QStringLiteral("portrait.png")));
        Playhead playhead;
        playhead.setTime(2.0);
        LiveWindow window(&document, &playhead);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY2(window.startMicrophoneOnly(), qPrintable(window.statusText()));
        QVERIFY2(window.statusText().contains(QString::fromLatin1(testing::PulseServer::kMicrophoneDescription)),
            qPrintable(window.statusText()));
        QVERIFY(!window.restPoseButton()->isEnabled()); // no picture to take it from
        int open = 0, frames = 0;
        connect(window.session(), &LiveSession::frameReady, this, [&] {
            ++frames;
            open += window.session()->current().sound.shape != MouthShape::M ? 1 : 0;
        });
        const int steps = document.undoStack()->count();
        QTest::mouseClick(window.recordButton(), Qt::LeftButton);
        QVERIFY(window.session()->isRecording());
        QProcess player;
        testing::PulseServer::play(player, m_speech);
        QVERIFY(player.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(player.state() == QProcess::NotRunning, 20000);
        QTest::qWait(300);
        QTest::mouseClick(window.recordButton(), Qt::LeftButton);
        qInfo(
            "microphone only: %d of %d frames with the mouth open; %s", open, frames, qPrintable(window.statusText()));
        QVERIFY(frames > 30 * m_played.duration() / 2); // drawn at about the clock's 30 fps
        QVERIFY(open >= frames / 5);
        QCOMPARE(document.undoStack()->count(), steps + 1);
        const Timeline &t = document.timeline();
        QVERIFY(t.poseKeys().isEmpty());
        int opened = 0;
        for (const MouthKey &k : t.mouthKeys())
            opened += k.shape != MouthShape::M && k.time >= 2.0 ? 1 : 0;
        QVERIFY2(opened >= 5, qPrintable(QString::number(opened)));
        QVERIFY(!t.audioClips().isEmpty());
        QCOMPARE(t.audioClips().first().offset, 2.0);
        QVERIFY(t.audioClips().first().duration > 0.8 * m_played.duration());
        QVERIFY(QFileInfo::exists(t.audioClips().first().path));
        window.close();
    }

    // The microphone taken away while it records: a message naming it, no crash; afterwards
    // there is none to start, and starting says so.
    void unpluggedMicrophoneSaysSo()
    {
        if (!m_skip.isEmpty())
            QSKIP(qPrintable(m_skip));
        Microphone microphone;
        QSignalSpy failed(&microphone, &Microphone::failed);
        QString error;
        QVERIFY2(microphone.start(&error), qPrintable(error));
        QTest::qWait(300);
        QVERIFY(testing::PulseServer::pactl({QStringLiteral("unload-module"), QStringLiteral("module-remap-source")}));
        QVERIFY(failed.wait(10000));
        QVERIFY2(failed.first().first().toString().contains(
                     QString::fromLatin1(testing::PulseServer::kMicrophoneDescription)),
            qPrintable(failed.first().first().toString()));
        QVERIFY(!microphone.isActive());
        QTRY_VERIFY_WITH_TIMEOUT(!Microphone::isPresent(), 10000);
        QVERIFY(!microphone.start(&error));
        QCOMPARE(error, Microphone::noMicrophoneMessage());
    }
};

TOONFACE_TEST_MAIN(TestMicrophone)
#include "tst_microphone.moc"
