#include "shareddata.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace toonface;

namespace {

// A 16-bit PCM WAV written byte by byte (not through the code under test): `channels`
// channels, each sample = amplitude·sin(2π·freq·t), for `seconds`.
QByteArray wavBytes(int rate, int channels, double freq, double amplitude, double seconds)
{
    const int n = int(std::lround(rate * seconds));
    QByteArray pcm;
    for (int i = 0; i < n; ++i) {
        const qint16 v = qint16(std::lround(32767.0 * amplitude * std::sin(2 * M_PI * freq * i / rate)));
        for (int c = 0; c < channels; ++c) {
            pcm.append(char(v & 0xff));
            pcm.append(char((v >> 8) & 0xff));
        }
    }
    QByteArray h;
    auto u32 = [&](quint32 x) {
        for (int k = 0; k < 4; ++k)
            h.append(char((x >> (8 * k)) & 0xff));
    };
    auto u16 = [&](quint16 x) {
        h.append(char(x & 0xff));
        h.append(char(x >> 8));
    };
    h.append("RIFF");
    u32(quint32(36 + pcm.size()));
    h.append("WAVEfmt ");
    u32(16);
    u16(1);
    u16(quint16(channels));
    u32(quint32(rate));
    u32(quint32(rate * channels * 2));
    u16(quint16(channels * 2));
    u16(16);
    h.append("data");
    u32(quint32(pcm.size()));
    return h + pcm;
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

double rms(const QVector<float> &s, qsizetype from, qsizetype to)
{
    double acc = 0;
    for (qsizetype i = from; i < to; ++i)
        acc += double(s[i]) * s[i];
    return std::sqrt(acc / double(std::max<qsizetype>(to - from, 1)));
}

// Frequency from the rate of upward zero crossings over the middle of the signal.
double frequency(const Audio &a)
{
    const qsizetype from = a.samples.size() / 4, to = 3 * a.samples.size() / 4;
    int ups = 0;
    for (qsizetype i = from + 1; i < to; ++i)
        ups += a.samples[i - 1] < 0 && a.samples[i] >= 0;
    return ups / (double(to - from) / a.sampleRate);
}

} // namespace

class TestAudio : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void wavIsResampledAndMixedToMono_data()
    {
        QTest::addColumn<int>("rate");
        QTest::addColumn<int>("channels");
        QTest::newRow("16k mono") << 16000 << 1;
        QTest::newRow("44.1k stereo") << 44100 << 2;
        QTest::newRow("48k stereo") << 48000 << 2;
        QTest::newRow("8k mono") << 8000 << 1;
    }
    void wavIsResampledAndMixedToMono()
    {
        QFETCH(int, rate);
        QFETCH(int, channels);
        const QString path = m_dir.filePath(QStringLiteral("tone_%1_%2.wav").arg(rate).arg(channels));
        QVERIFY(writeFile(path, wavBytes(rate, channels, 440, 0.5, 1.0)));
        const AudioResult r = loadAudio(path);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.audio.sampleRate, kSpeechSampleRate);
        QVERIFY(std::abs(r.audio.duration() - 1.0) < 0.01);
        QVERIFY(std::abs(frequency(r.audio) - 440) < 5);
        // Equal channels average to the same sine: RMS 0.5/√2 within 3 %.
        const double level = rms(r.audio.samples, r.audio.samples.size() / 4, 3 * r.audio.samples.size() / 4);
        QVERIFY2(std::abs(level - 0.5 / std::sqrt(2.0)) < 0.01, qPrintable(QString::number(level)));
    }

    void encodedFormatsRoundTrip_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char *s : {"wav", "flac", "mp3", "ogg", "opus", "m4a"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }
    void encodedFormatsRoundTrip()
    {
        QFETCH(QString, suffix);
        Audio a;
        a.sampleRate = 22050;
        for (int i = 0; i < 22050 * 2; ++i)
            a.samples.append(float(0.4 * std::sin(2 * M_PI * 300.0 * i / 22050)));
        const QString path = m_dir.filePath(QStringLiteral("round.") + suffix);
        QString error;
        QVERIFY2(writeAudio(path, a, &error), qPrintable(error));
        const AudioResult r = loadAudio(path);
        QVERIFY2(r.ok(), qPrintable(r.error));
        // Lossy codecs add priming and padding of up to a few frames.
        QVERIFY2(std::abs(r.audio.duration() - 2.0) < 0.1, qPrintable(QString::number(r.audio.duration())));
        QVERIFY(std::abs(frequency(r.audio) - 300) < 5);
    }

    void soxEncodedFiles_data()
    {
        QTest::addColumn<QString>("suffix");
        QTest::newRow("flac") << "flac";
        QTest::newRow("ogg") << "ogg";
    }
    void soxEncodedFiles()
    {
        // An encoder independent of the code under test.
        QFETCH(QString, suffix);
        const QString sox = QStandardPaths::findExecutable(QStringLiteral("sox"));
        if (sox.isEmpty())
            QSKIP("sox is not installed");
        const QString wav = m_dir.filePath(QStringLiteral("sox_in.wav"));
        QVERIFY(writeFile(wav, wavBytes(44100, 2, 250, 0.5, 1.5)));
        const QString out = m_dir.filePath(QStringLiteral("sox_out.") + suffix);
        if (QProcess::execute(sox, {wav, out}) != 0)
            QSKIP("this sox cannot write the format");
        const AudioResult r = loadAudio(out);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(std::abs(r.audio.duration() - 1.5) < 0.05);
        QVERIFY(std::abs(frequency(r.audio) - 250) < 5);
    }

    void videoSoundTrack()
    {
        const QString clip = testing::sharedDataDir() + QStringLiteral("/video/id2_vcd_swwp2s.mpg");
        if (!QFile::exists(clip))
            QSKIP("shared data (video/id2_vcd_swwp2s.mpg) not present");
        const AudioResult r = loadAudio(clip);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(std::abs(r.audio.duration() - 3.0) < 0.1);
    }

    void realRecordingAt48k()
    {
        const QString path = testing::sharedDataDir() + QStringLiteral("/speech/NST_ID001.wav");
        if (!QFile::exists(path))
            QSKIP("shared data (speech/NST_ID001.wav) not present");
        const AudioResult r = loadAudio(path);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(std::abs(r.audio.duration() - 140288.0 / 48000.0) < 0.01);
    }

    void badInput_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("status");
        QTest::newRow("empty file") << "empty.wav" << QByteArray() << int(AudioStatus::Empty);
        QTest::newRow("text as mp3") << "text.mp3" << QByteArray("this is not sound at all\n").repeated(40)
                                     << int(AudioStatus::Unreadable);
        QByteArray noise;
        for (int i = 0; i < 4096; ++i)
            noise.append(char((i * 7919 + 13) % 251));
        QTest::newRow("garbage wav") << "garbage.wav" << noise << int(AudioStatus::Unreadable);
        QTest::newRow("header only") << "header.wav" << wavBytes(16000, 1, 440, 0.5, 0) << int(AudioStatus::Empty);
        QTest::newRow("silence") << "silence.wav" << wavBytes(16000, 1, 440, 0.0, 1.0) << int(AudioStatus::Silent);
        QByteArray truncatedFlac = QByteArray("fLaC") + noise.left(200);
        QTest::newRow("corrupt flac") << "corrupt.flac" << truncatedFlac << int(AudioStatus::Unreadable);
    }
    void badInput()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(int, status);
        const QString path = m_dir.filePath(name);
        QVERIFY(writeFile(path, bytes));
        const AudioResult r = loadAudio(path);
        QVERIFY(!r.ok());
        QCOMPARE(int(r.status), status);
        QVERIFY2(r.error.contains(path), qPrintable(r.error));
        QVERIFY(r.audio.isEmpty());
    }

    // Found by fuzz_audio: a float WAV holding NaN and infinite samples. They are heard as
    // nothing: every sample read is finite, the sound around them is kept.
    void nonFiniteSamplesBecomeSilence()
    {
        const int rate = kSpeechSampleRate;
        QByteArray data;
        for (int i = 0; i < rate / 2; ++i) {
            float v = float(0.5 * std::sin(2 * M_PI * 440.0 * i / rate));
            if (i == rate / 4)
                v = std::numeric_limits<float>::quiet_NaN();
            if (i == rate / 4 + 100)
                v = std::numeric_limits<float>::infinity();
            data.append(reinterpret_cast<const char *>(&v), sizeof v);
        }
        // A WAVE_FORMAT_IEEE_FLOAT header, written by hand.
        QByteArray h;
        auto u32 = [&](quint32 x) { h.append(reinterpret_cast<const char *>(&x), 4); };
        auto u16 = [&](quint16 x) { h.append(reinterpret_cast<const char *>(&x), 2); };
        h.append("RIFF");
        u32(quint32(36 + data.size()));
        h.append("WAVEfmt ");
        u32(16);
        u16(3);
        u16(1);
        u32(quint32(rate));
        u32(quint32(rate * 4));
        u16(4);
        u16(32);
        h.append("data");
        u32(quint32(data.size()));
        const QString path = m_dir.filePath(QStringLiteral("nan.wav"));
        QVERIFY(writeFile(path, h + data));
        const AudioResult r = loadAudio(path);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.audio.samples.size(), qsizetype(rate / 2));
        for (const float v : r.audio.samples)
            QVERIFY(std::isfinite(v));
        QVERIFY(rms(r.audio.samples, 0, rate / 5) > 0.3); // the tone before them is intact
        QVERIFY(rms(r.audio.samples, rate / 3, rate / 2) > 0.3); // and after
    }

    // Found by fuzz_audio (a 20-second timeout in CI): a WAV header claiming 1 sample a second,
    // which resampled to speech rate made hours of sound from kilobytes. Refused at its first frame.
    void sampleRateTooLowIsRefused()
    {
        const QString path = m_dir.filePath(QStringLiteral("rate1.wav"));
        QVERIFY(writeFile(path, wavBytes(1, 1, 0.1, 0.5, 20000)));
        const AudioResult r = loadAudio(path);
        QCOMPARE(int(r.status), int(AudioStatus::Unreadable));
        QVERIFY2(r.error.contains(path) && r.error.contains(QStringLiteral("sample rate (1 Hz)")), qPrintable(r.error));
        QCOMPARE(r.sampleCount, qint64(0));
        // The lowest rate speech is recorded at still loads.
        const QString phone = m_dir.filePath(QStringLiteral("rate8k.wav"));
        QVERIFY(writeFile(phone, wavBytes(8000, 1, 300, 0.5, 0.5)));
        QVERIFY2(loadAudio(phone).ok(), qPrintable(loadAudio(phone).error));
    }

    // A file that decodes to far more sound than its size can hold is damaged or made to blow
    // up: refused as soon as the decoded length passes what the size allows, not decoded whole.
    // The fixture is ten minutes of a constant level at 8000 Hz in 9 KB, made with
    // `ffmpeg -f lavfi -i aevalsrc=0.25:s=8000:d=600 -c:a flac -frame_size 65535`.
    void soundMoreThanItsSizeCanHoldIsRefused()
    {
        const QString path = QStringLiteral(TOONFACE_TEST_DATA "/speech/constant-10min.flac");
        QVERIFY(QFileInfo(path).size() < 600 * 100 / 2); // the premise: far under 100 bytes a second
        const AudioResult r = loadAudio(path);
        QCOMPARE(int(r.status), int(AudioStatus::Unreadable));
        QVERIFY2(r.error.contains(path) && r.error.contains(QStringLiteral("damaged")), qPrintable(r.error));
        QVERIFY2(r.sourceDuration < 300, qPrintable(QString::number(r.sourceDuration)));
        QVERIFY(r.audio.isEmpty());
    }

    void missingFile()
    {
        const QString path = m_dir.filePath(QStringLiteral("nope.wav"));
        const AudioResult r = loadAudio(path);
        QCOMPARE(r.status, AudioStatus::Unreadable);
        QVERIFY(r.error.contains(path));
    }

    void progressAndCancel()
    {
        const QString path = m_dir.filePath(QStringLiteral("long.wav"));
        QVERIFY(writeFile(path, wavBytes(16000, 1, 200, 0.3, 20.0)));
        double last = 0;
        int calls = 0;
        const AudioResult ok = loadAudio(path, [&](double f, const QString &) {
            QVERIFY(f >= last);
            last = f;
            ++calls;
        });
        QVERIFY(ok.ok());
        QVERIFY(calls >= 2);
        QCOMPARE(last, 1.0);
        std::atomic_bool cancel {true};
        const AudioResult cancelled = loadAudio(path, {}, &cancel);
        QCOMPARE(cancelled.status, AudioStatus::Cancelled);
    }

    void resampling()
    {
        Audio a;
        a.sampleRate = 16000;
        for (int i = 0; i < 16000; ++i)
            a.samples.append(float(0.5 * std::sin(2 * M_PI * 500.0 * i / 16000)));
        const Audio b = resampled(a, 22050);
        QCOMPARE(b.sampleRate, 22050);
        QVERIFY(std::abs(b.duration() - 1.0) < 0.005);
        QVERIFY(std::abs(frequency(b) - 500) < 5);
    }

    // streamAudio hands over exactly what loadAudio keeps, in pieces; the same errors.
    void streamingMatchesLoading()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("tone.wav"));
        QVERIFY(writeFile(path, wavBytes(44100, 2, 440, 0.5, 2.0)));
        const AudioResult loaded = loadAudio(path);
        QVERIFY(loaded.ok());
        QVector<float> streamed;
        int pieces = 0;
        const AudioResult r = streamAudio(path, [&](const float *s, qsizetype n) {
            streamed.append(QVector<float>(s, s + n));
            ++pieces;
        });
        QVERIFY(r.ok());
        QVERIFY(r.audio.samples.isEmpty());
        QVERIFY(pieces > 1);
        QCOMPARE(r.sampleCount, qint64(loaded.audio.samples.size()));
        QCOMPARE(loaded.sampleCount, r.sampleCount);
        QVERIFY(streamed == loaded.audio.samples);
        const QString silent = dir.filePath(QStringLiteral("silent.wav"));
        QVERIFY(writeFile(silent, wavBytes(16000, 1, 440, 0.0, 1.0)));
        const AudioResult s = streamAudio(silent, [](const float *, qsizetype) {});
        QCOMPARE(s.status, AudioStatus::Silent);
        QVERIFY(s.error.contains(silent));
    }

    // The streaming resampler gives what resampled() gives, whatever the pieces.
    void resamplerInPieces()
    {
        Audio a;
        a.sampleRate = 22050;
        for (int i = 0; i < 50000; ++i)
            a.samples.append(float(0.5 * std::sin(2 * M_PI * 300.0 * i / 22050)));
        const Audio whole = resampled(a, 16000);
        for (const qsizetype piece : {qsizetype(1000), qsizetype(70000)}) {
            QVector<float> out;
            AudioResampler r(22050, 16000, [&](const float *s, qsizetype n) { out.append(QVector<float>(s, s + n)); });
            QVERIFY(r.ok());
            for (qsizetype at = 0; at < a.samples.size(); at += piece)
                r.push(a.samples.constData() + at, std::min(piece, a.samples.size() - at));
            r.finish();
            QCOMPARE(out.size(), whole.samples.size());
            double worst = 0;
            for (qsizetype i = 0; i < out.size(); ++i)
                worst = std::max(worst, double(std::abs(out[i] - whole.samples[i])));
            QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
        }
        QVector<float> same;
        AudioResampler pass(16000, 16000, [&](const float *s, qsizetype n) { same.append(QVector<float>(s, s + n)); });
        pass.push(a.samples.constData(), 100);
        pass.finish();
        QCOMPARE(same, a.samples.mid(0, 100));
    }

    void unknownOutputFormat()
    {
        QString error;
        QVERIFY(!writeAudio(m_dir.filePath(QStringLiteral("x.xyz")), Audio {{0.1f, 0.2f}, 16000}, &error));
        QVERIFY(error.contains(QStringLiteral("x.xyz")));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestAudio)
#include "tst_audio.moc"
