// The sound check that reads a header and samples a few packets instead of decoding the whole
// file, and the sound copied a block at a time (issue 29: animate --video streams its clip's
// sound): the same file as decoding it whole, cancel and errors that leave no file.
#include "export/videoencoder.h"
#include "media/mediareader.h"
#include "media/soundcheck.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// A rising tone at `rate`: a block lost or repeated shows in the samples.
Audio sweep(int rate, double seconds)
{
    Audio a;
    a.sampleRate = rate;
    a.samples.resize(qsizetype(seconds * rate));
    for (qsizetype i = 0; i < a.samples.size(); ++i) {
        const double t = double(i) / rate;
        a.samples[i] = float(0.4 * std::sin(2 * M_PI * (200.0 + 40.0 * t) * t));
    }
    return a;
}

QByteArray bytesOf(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestSoundCheck : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // Each format's header gives the length decoding finds, and its packets decode where they
    // are sampled.
    void readsTheHeader_data()
    {
        QTest::addColumn<QString>("suffix");
        QTest::addColumn<QString>("codec");
        QTest::newRow("wav") << QStringLiteral("wav") << QStringLiteral("pcm_s16le");
        QTest::newRow("flac") << QStringLiteral("flac") << QStringLiteral("flac");
        QTest::newRow("mp3") << QStringLiteral("mp3") << QStringLiteral("mp3");
        QTest::newRow("m4a") << QStringLiteral("m4a") << QStringLiteral("aac");
        QTest::newRow("ogg") << QStringLiteral("ogg") << QStringLiteral("vorbis");
    }
    void readsTheHeader()
    {
        QFETCH(QString, suffix);
        QFETCH(QString, codec);
        const QString path = m_dir.filePath(QStringLiteral("sweep.") + suffix);
        QString error;
        QVERIFY2(writeAudio(path, sweep(22050, 20), &error), qPrintable(error));
        const SoundCheck check = checkSound(path);
        QVERIFY2(check.ok(), qPrintable(check.error));
        QCOMPARE(check.codec, codec);
        QCOMPARE(check.channels, 1);
        QVERIFY(check.sampleRate > 0);
        const std::optional<MediaInfo> decoded = probeMedia(path, &error);
        QVERIFY2(decoded, qPrintable(error));
        QCOMPARE(check.sampleRate, decoded->audioSampleRate);
        // MP3 and AAC headers count their encoder's padding (a frame or two).
        QVERIFY2(std::abs(check.seconds - decoded->audioDurationS) < 0.1,
            qPrintable(
                QStringLiteral("%1 s in the header, %2 s decoded").arg(check.seconds).arg(decoded->audioDurationS)));
    }

    // A video's sound track is sound; a video without one, a text, an empty file or a folder
    // is not, and the error names the file.
    void badInputNamesTheFile()
    {
        const QString silentVideo = m_dir.filePath(QStringLiteral("silent.mp4"));
        QString error;
        QImage frame(64, 64, QImage::Format_RGB32);
        frame.fill(Qt::darkCyan);
        QVERIFY2(writeVideo(
                     silentVideo, VideoFormat::Mp4, frame.size(), 25, 10, [&](int) { return frame; }, AudioSource {},
                     &error),
            qPrintable(error));
        const QString soundVideo = m_dir.filePath(QStringLiteral("talking.mp4"));
        const Audio sound = sweep(16000, 0.4);
        QVERIFY2(writeVideo(
                     soundVideo, VideoFormat::Mp4, frame.size(), 25, 10, [&](int) { return frame; },
                     AudioSource::fromSamples(sound.samples, sound.sampleRate), &error),
            qPrintable(error));
        QVERIFY2(checkSound(soundVideo).ok(), qPrintable(checkSound(soundVideo).error));

        const QString text = m_dir.filePath(QStringLiteral("notes.wav"));
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a sound at all\n");
        f.close();
        const QString empty = m_dir.filePath(QStringLiteral("empty.mp3"));
        QFile e(empty);
        QVERIFY(e.open(QIODevice::WriteOnly));
        e.close();
        for (const QString &path :
            {silentVideo, text, empty, m_dir.path(), m_dir.filePath(QStringLiteral("none.wav"))}) {
            const SoundCheck check = checkSound(path);
            QVERIFY2(!check.ok(), qPrintable(path));
            QVERIFY2(check.error.contains(QDir::toNativeSeparators(path)) || check.error.contains(path),
                qPrintable(check.error));
        }
        QVERIFY2(checkSound(silentVideo).error.contains(u"holds no sound"), qPrintable(checkSound(silentVideo).error));
    }

    // Copied a block at a time, a clip's sound is the file that decoding it whole and writing
    // it makes: the same bytes for WAV, the same samples for FLAC.
    void copyIsTheWholeFilePath_data()
    {
        QTest::addColumn<QString>("source");
        QTest::addColumn<QString>("target");
        QTest::newRow("mp3 to wav") << QStringLiteral("mp3") << QStringLiteral("wav");
        QTest::newRow("m4a to wav") << QStringLiteral("m4a") << QStringLiteral("wav");
        QTest::newRow("wav to flac") << QStringLiteral("wav") << QStringLiteral("flac");
    }
    void copyIsTheWholeFilePath()
    {
        QFETCH(QString, source);
        QFETCH(QString, target);
        const QString from = m_dir.filePath(QStringLiteral("clip.") + source);
        QString error;
        QVERIFY2(writeAudio(from, sweep(44100, 30), &error), qPrintable(error));
        const AudioResult whole = loadAudio(from);
        QVERIFY2(whole.ok(), qPrintable(whole.error));
        const QString wholeFile = m_dir.filePath(QStringLiteral("whole.") + target);
        QVERIFY2(writeAudio(wholeFile, whole.audio, &error), qPrintable(error));

        const QString streamed = m_dir.filePath(QStringLiteral("streamed.") + target);
        QVector<double> reported;
        const AudioResult copy = copyAudio(from, streamed, [&](double f, const QString &) { reported.append(f); });
        QVERIFY2(copy.ok(), qPrintable(copy.error));
        QVERIFY(copy.audio.isEmpty()); // never held whole
        QCOMPARE(copy.sampleCount, qint64(whole.audio.samples.size()));
        QVERIFY(!reported.isEmpty());
        QVERIFY(std::is_sorted(reported.begin(), reported.end()));
        if (target == QLatin1StringView("wav")) {
            QCOMPARE(bytesOf(streamed), bytesOf(wholeFile));
        } else {
            const std::optional<QVector<float>> a = readAudio(wholeFile, kSpeechSampleRate, &error);
            const std::optional<QVector<float>> b = readAudio(streamed, kSpeechSampleRate, &error);
            QVERIFY2(a && b, qPrintable(error));
            QCOMPARE(*b, *a);
        }
    }

    // Cancelled, or the target cannot be written: no file, and the status says which.
    void copyCancelAndErrorsLeaveNoFile()
    {
        const QString from = m_dir.filePath(QStringLiteral("long.flac"));
        QString error;
        QVERIFY2(writeAudio(from, sweep(16000, 60), &error), qPrintable(error));
        const QString out = m_dir.filePath(QStringLiteral("cancelled.wav"));
        std::atomic_bool cancel = false;
        int calls = 0;
        const AudioResult cancelled = copyAudio(
            from, out,
            [&](double, const QString &) {
                if (++calls == 2)
                    cancel = true;
            },
            &cancel);
        QCOMPARE(cancelled.status, AudioStatus::Cancelled);
        QVERIFY(!QFileInfo::exists(out));

        const QString nowhere = m_dir.filePath(QStringLiteral("no/such/folder/sound.wav"));
        const AudioResult unwritable = copyAudio(from, nowhere);
        QCOMPARE(unwritable.status, AudioStatus::Unwritable);
        QVERIFY2(unwritable.error.contains(nowhere), qPrintable(unwritable.error));

        const QString text = m_dir.filePath(QStringLiteral("text.mp3"));
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a sound at all\n");
        f.close();
        const QString bad = m_dir.filePath(QStringLiteral("bad.wav"));
        const AudioResult unreadable = copyAudio(text, bad);
        QVERIFY(!unreadable.ok());
        QVERIFY2(unreadable.error.contains(u"text.mp3"), qPrintable(unreadable.error));
        QVERIFY(!QFileInfo::exists(bad));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSoundCheck)
#include "tst_soundcheck.moc"
