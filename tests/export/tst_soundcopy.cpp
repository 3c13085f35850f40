// A recording re-encoded a block at a time (issue 29: an hour-long --audio streams through the
// book): the same sound as encoding it whole, progress that rises to 1, cancel and bad input
// that leave no file.
#include "media/mediareader.h"
#include "media/soundcopy.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// Two tones, one after the other, so that a block lost or repeated moves the change.
Audio twoTones(int rate, double seconds)
{
    Audio a;
    a.sampleRate = rate;
    a.samples.resize(qsizetype(seconds * rate));
    for (qsizetype i = 0; i < a.samples.size(); ++i) {
        const double t = double(i) / rate;
        a.samples[i] = float(0.4 * std::sin(2 * M_PI * (t < seconds / 2 ? 330.0 : 660.0) * t));
    }
    return a;
}

} // namespace

class TestSoundCopy : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_wav; // 30 s at 44.1 kHz

    QStringList files() const { return QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_wav = m_dir.filePath(QStringLiteral("reading.wav"));
        QString error;
        QVERIFY2(writeAudio(m_wav, twoTones(44100, 30), &error), qPrintable(error));
    }

    // Written in blocks of any size, a file holds what writeAudio writes of the whole (FLAC:
    // lossless, so sample for sample up to the 16-bit rounding).
    void writerInBlocksKeepsEverySample()
    {
        const Audio tones = twoTones(16000, 3);
        QString error;
        const QString whole = m_dir.filePath(QStringLiteral("whole.flac"));
        QVERIFY2(writeAudio(whole, tones, &error), qPrintable(error));
        const QString blocks = m_dir.filePath(QStringLiteral("blocks.flac"));
        std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(blocks, 16000, &error);
        QVERIFY2(writer, qPrintable(error));
        qsizetype at = 0;
        for (const qsizetype n : {1, 7, 1000, 4097, 20000}) {
            QVERIFY2(writer->write(tones.samples.constData() + at, n, &error), qPrintable(error));
            at += n;
        }
        QVERIFY2(writer->write(tones.samples.constData() + at, tones.samples.size() - at, &error), qPrintable(error));
        QVERIFY2(writer->finish(&error), qPrintable(error));
        QVERIFY(!writer->write(tones.samples.constData(), 1, &error)); // closed
        const std::optional<QVector<float>> a = readAudio(whole, 16000, &error);
        const std::optional<QVector<float>> b = readAudio(blocks, 16000, &error);
        QVERIFY2(a && b, qPrintable(error));
        QCOMPARE(b->size(), tones.samples.size());
        QCOMPARE(*b, *a);
        for (qsizetype i = 0; i < b->size(); ++i)
            QVERIFY(std::abs((*b)[i] - tones.samples[i]) < 1.0f / 16000);
        QVERIFY(!openAudioFileWriter(m_dir.filePath(QStringLiteral("x.xyz")), 16000, &error));
        QVERIFY2(error.contains(u"x.xyz"), qPrintable(error));
    }

    // The copy at the book's 24 kHz: MP3 of the recording's length whose tones change where
    // the recording's do; progress rises to 1.
    void copiesAtTheRateAsked()
    {
        const QString mp3 = m_dir.filePath(QStringLiteral("book.mp3"));
        QVector<double> reported;
        const SoundCopy copy = copySound(m_wav, mp3, 24000, [&](double f) { reported.append(f); });
        QVERIFY2(copy.ok(), qPrintable(copy.error));
        // The resampler's filter may round the end by a sample.
        QVERIFY2(std::abs(copy.samples - 30 * 24000) <= 2, qPrintable(QString::number(copy.samples)));
        QCOMPARE(copy.seconds, double(copy.samples) / 24000);
        QVERIFY(reported.size() > 2);
        QVERIFY(std::is_sorted(reported.begin(), reported.end()));
        QCOMPARE(reported.constLast(), 1.0);
        QString error;
        const std::optional<MediaInfo> info = probeMedia(mp3, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->audioCodec, QStringLiteral("mp3"));
        QCOMPARE(info->audioSampleRate, 24000);
        QVERIFY2(std::abs(info->audioDurationS - 30.0) < 0.1, qPrintable(QString::number(info->audioDurationS)));
        // The higher tone starts at 15 s: count zero crossings a second either side.
        const std::optional<QVector<float>> samples = readAudio(mp3, 24000, &error);
        QVERIFY2(samples, qPrintable(error));
        const auto crossings = [&](double from) {
            int n = 0;
            for (qsizetype i = qsizetype(from * 24000) + 1; i < qsizetype((from + 1) * 24000); ++i)
                n += ((*samples)[i - 1] < 0) != ((*samples)[i] < 0);
            return n;
        };
        QVERIFY2(std::abs(crossings(13.5) - 660) < 20, qPrintable(QString::number(crossings(13.5))));
        QVERIFY2(std::abs(crossings(15.5) - 1320) < 20, qPrintable(QString::number(crossings(15.5))));
    }

    void cancelLeavesNoFile()
    {
        const QString mp3 = m_dir.filePath(QStringLiteral("cancelled.mp3"));
        std::atomic_bool cancel = false;
        int calls = 0;
        const SoundCopy copy = copySound(
            m_wav, mp3, 24000,
            [&](double) {
                if (++calls == 2)
                    cancel = true;
            },
            &cancel);
        QCOMPARE(copy.status, SoundCopyStatus::Cancelled);
        QVERIFY2(copy.error.contains(u"reading.wav"), qPrintable(copy.error));
        QCOMPARE(calls, 2);
        QVERIFY(!QFileInfo::exists(mp3));
    }

    void badInputNamesTheFile()
    {
        const QString text = m_dir.filePath(QStringLiteral("notes.txt"));
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a sound at all\n");
        f.close();
        const QString out = m_dir.filePath(QStringLiteral("bad.mp3"));
        const SoundCopy bad = copySound(text, out, 24000);
        QCOMPARE(bad.status, SoundCopyStatus::BadInput);
        QVERIFY2(bad.error.contains(u"notes.txt"), qPrintable(bad.error));
        QVERIFY(!QFileInfo::exists(out));

        const QString nowhere = m_dir.filePath(QStringLiteral("no/such/folder/book.mp3"));
        const SoundCopy unwritable = copySound(m_wav, nowhere, 24000);
        QCOMPARE(unwritable.status, SoundCopyStatus::Failed);
        QVERIFY2(unwritable.error.contains(nowhere), qPrintable(unwritable.error));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSoundCopy)
#include "tst_soundcopy.moc"
