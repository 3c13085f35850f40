// The plain-WAV reader (speech/wavfile.h) against FFmpeg's: which files it takes, and that it
// gives exactly FFmpeg's samples, duration and errors for every layout it takes.
#include "speech/audio.h"
#include "speech/audioconvert.h"
#include "speech/wavfile.h"
#include "testmain.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace toonface;

namespace {

struct WavSpec
{
    int tag = 1; // 1 PCM integers, 3 floats, others compressed
    int channels = 1;
    int rate = 16000;
    int bits = 16;
    double seconds = 1.3;
    double amplitude = 0.5;
    bool listChunkFirst = false; // a LIST chunk (odd length) between "fmt " and "data"
};

void put32(QByteArray &b, quint32 v)
{
    for (int k = 0; k < 4; ++k)
        b.append(char((v >> (8 * k)) & 0xff));
}

void put16(QByteArray &b, quint16 v)
{
    b.append(char(v & 0xff));
    b.append(char(v >> 8));
}

// A chirp with a different tone in each channel, stored in the spec's sample format.
QByteArray samplesOf(const WavSpec &s)
{
    QByteArray d;
    const int frames = int(s.seconds * s.rate);
    for (int i = 0; i < frames; ++i) {
        for (int c = 0; c < s.channels; ++c) {
            const double t = double(i) / s.rate;
            const double v = s.amplitude * std::sin(2 * M_PI * (150 + 90 * c + 400 * t) * t);
            if (s.tag == 3) {
                const float f = float(v);
                quint32 bits;
                std::memcpy(&bits, &f, 4);
                put32(d, bits);
            } else if (s.bits == 8) {
                d.append(char(quint8(std::lround(128 + 127 * v))));
            } else if (s.bits == 16) {
                put16(d, quint16(qint16(std::lround(32767 * v))));
            } else if (s.bits == 24) {
                const qint32 x = qint32(std::lround(8388607 * v));
                d.append(char(x & 0xff));
                d.append(char((x >> 8) & 0xff));
                d.append(char((x >> 16) & 0xff));
            } else {
                put32(d, quint32(qint32(std::lround(2147483647.0 * v))));
            }
        }
    }
    return d;
}

QByteArray wavBytes(const WavSpec &s, const QByteArray &data, qint64 declaredData = -1)
{
    QByteArray b("RIFF");
    put32(b, 0); // patched below
    b.append("WAVEfmt ");
    put32(b, 16);
    put16(b, quint16(s.tag));
    put16(b, quint16(s.channels));
    put32(b, quint32(s.rate));
    put32(b, quint32(s.rate * s.channels * s.bits / 8));
    put16(b, quint16(s.channels * s.bits / 8));
    put16(b, quint16(s.bits));
    if (s.listChunkFirst) {
        b.append("LIST");
        put32(b, 5);
        b.append("INFOx");
        b.append('\0'); // the pad byte of an odd chunk
    }
    b.append("data");
    put32(b, quint32(declaredData >= 0 ? declaredData : data.size()));
    b.append(data);
    const quint32 riff = quint32(b.size() - 8);
    for (int k = 0; k < 4; ++k)
        b[4 + k] = char((riff >> (8 * k)) & 0xff);
    return b;
}

struct Decoded
{
    AudioResult result;
    QVector<float> samples;
    QVector<double> progress;
};

template<typename Decode>
Decoded decodeWith(Decode decode)
{
    Decoded d;
    const AudioSink sink = [&](const float *s, qsizetype n) { d.samples.append(QVector<float>(s, s + n)); };
    const SpeechProgressFn progress = [&](double f, const QString &) { d.progress << f; };
    d.result = decode(sink, progress);
    return d;
}

} // namespace

class TestWavFile : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            return {};
        return path;
    }

private Q_SLOTS:
    void takesPlainPcm_data()
    {
        QTest::addColumn<int>("tag");
        QTest::addColumn<int>("bits");
        QTest::addColumn<int>("channels");
        QTest::addColumn<int>("rate");
        QTest::addColumn<bool>("listChunk");
        for (const auto &[tag, bits] : {std::pair {1, 8}, {1, 16}, {1, 24}, {1, 32}, {3, 32}}) {
            for (const int channels : {1, 2}) {
                for (const int rate : {8000, 16000, 22050, 44100, 48000}) {
                    const QByteArray name = QStringLiteral("%1-%2bit-%3ch-%4Hz")
                                                .arg(tag == 3 ? QStringLiteral("float") : QStringLiteral("int"))
                                                .arg(bits)
                                                .arg(channels)
                                                .arg(rate)
                                                .toUtf8();
                    QTest::newRow(name.constData()) << tag << bits << channels << rate << (rate == 22050);
                }
            }
        }
    }

    // Every layout the reader takes decodes to FFmpeg's samples, bit for bit, with FFmpeg's
    // duration.
    void takesPlainPcm()
    {
        QFETCH(int, tag);
        QFETCH(int, bits);
        QFETCH(int, channels);
        QFETCH(int, rate);
        QFETCH(bool, listChunk);
        WavSpec spec {tag, channels, rate, bits, 1.3, 0.5, listChunk};
        const QString path = write(QStringLiteral("plain.wav"), wavBytes(spec, samplesOf(spec)));
        const std::optional<PlainWav> wav = probePlainWav(path);
        QVERIFY(wav);
        QCOMPARE(wav->channels, channels);
        QCOMPARE(wav->sampleRate, rate);
        QCOMPARE(wav->bitsPerSample, bits);
        QCOMPARE(wav->floating, tag == 3);

        const Decoded own = decodeWith([&](const AudioSink &sink, const SpeechProgressFn &progress) {
            return detail::decodePlainWav(path, *wav, sink, progress, nullptr);
        });
        const Decoded ffmpeg = decodeWith([&](const AudioSink &sink, const SpeechProgressFn &progress) {
            return detail::decodeWithFfmpeg(path, sink, progress, nullptr);
        });
        QVERIFY2(ffmpeg.result.ok(), qPrintable(ffmpeg.result.error));
        QVERIFY2(own.result.ok(), qPrintable(own.result.error));
        QVERIFY(own.samples.size() > rate / 2 * kSpeechSampleRate / rate);
        QCOMPARE(own.samples.size(), ffmpeg.samples.size());
        QCOMPARE(own.result.sampleCount, ffmpeg.result.sampleCount);
        QVERIFY(
            std::memcmp(own.samples.constData(), ffmpeg.samples.constData(), size_t(own.samples.size()) * sizeof(float))
            == 0);
        QCOMPARE(own.result.sourceDuration, ffmpeg.result.sourceDuration);
        // Progress by the position in the file (FFmpeg's moves by its read buffer, so more coarsely).
        QVERIFY(own.progress.size() >= 2);
        QVERIFY(std::is_sorted(own.progress.begin(), own.progress.end()));
        QVERIFY(own.progress.first() > 0);
        QCOMPARE(own.progress.last(), 1.0);

        // streamAudio, which every caller uses, takes this reader for it.
        const Decoded streamed = decodeWith([&](const AudioSink &sink, const SpeechProgressFn &progress) {
            return streamAudio(path, sink, progress, nullptr);
        });
        QCOMPARE(streamed.samples, own.samples);
    }

    // Silence is refused with FFmpeg's error, word for word.
    void silentLikeFfmpeg()
    {
        WavSpec spec;
        spec.amplitude = 0;
        const QString path = write(QStringLiteral("silent.wav"), wavBytes(spec, samplesOf(spec)));
        const std::optional<PlainWav> wav = probePlainWav(path);
        QVERIFY(wav);
        const AudioResult own = detail::decodePlainWav(path, *wav, {}, {}, nullptr);
        const AudioResult ffmpeg = detail::decodeWithFfmpeg(path, {}, {}, nullptr);
        QCOMPARE(own.status, AudioStatus::Silent);
        QCOMPARE(own.status, ffmpeg.status);
        QCOMPARE(own.error, ffmpeg.error);
    }

    // Anything else is left to FFmpeg: other formats and codecs, unusual layouts, damaged or
    // open-ended data chunks.
    void leavesTheRestToFfmpeg()
    {
        WavSpec plain;
        const QByteArray data = samplesOf(plain);
        QVERIFY(probePlainWav(write(QStringLiteral("ok.wav"), wavBytes(plain, data))));

        WavSpec adpcm = plain;
        adpcm.tag = 2;
        QVERIFY(!probePlainWav(write(QStringLiteral("adpcm.wav"), wavBytes(adpcm, data))));
        WavSpec three = plain;
        three.channels = 3;
        QVERIFY(!probePlainWav(write(QStringLiteral("three.wav"), wavBytes(three, samplesOf(three)))));
        WavSpec slow = plain;
        slow.rate = 2000;
        QVERIFY(!probePlainWav(write(QStringLiteral("slow.wav"), wavBytes(slow, samplesOf(slow)))));
        WavSpec float64 = plain;
        float64.tag = 3;
        float64.bits = 64;
        QVERIFY(!probePlainWav(write(QStringLiteral("f64.wav"), wavBytes(float64, data))));
        // Data chunk lengths: open-ended (as a stream writes them), past the end, partial frame.
        QVERIFY(!probePlainWav(write(QStringLiteral("zero.wav"), wavBytes(plain, data, 0))));
        QVERIFY(!probePlainWav(write(QStringLiteral("open.wav"), wavBytes(plain, data, 0xffffffffLL))));
        QVERIFY(!probePlainWav(write(QStringLiteral("long.wav"), wavBytes(plain, data, data.size() + 100))));
        QVERIFY(!probePlainWav(write(QStringLiteral("odd.wav"), wavBytes(plain, data.left(data.size() - 1)))));
        // Not WAV at all, or a header cut short.
        QVERIFY(!probePlainWav(write(QStringLiteral("flac.wav"), QByteArray("fLaC\0\0\0\x22", 8) + data)));
        QVERIFY(!probePlainWav(write(QStringLiteral("cut.wav"), wavBytes(plain, data).left(30))));
        QVERIFY(!probePlainWav(m_dir.filePath(QStringLiteral("missing.wav"))));
        // A real FLAC file is decoded by FFmpeg as before.
        Audio tone;
        tone.samples = QVector<float>(16000, 0.0f);
        for (int i = 0; i < tone.samples.size(); ++i)
            tone.samples[i] = float(0.3 * std::sin(i * 0.05));
        QString error;
        const QString flac = m_dir.filePath(QStringLiteral("tone.flac"));
        QVERIFY2(writeAudio(flac, tone, &error), qPrintable(error));
        QVERIFY(!probePlainWav(flac));
        const AudioResult decoded = loadAudio(flac);
        QVERIFY2(decoded.ok(), qPrintable(decoded.error));
        QCOMPARE(decoded.audio.samples.size(), tone.samples.size());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestWavFile)
#include "tst_wavfile.moc"
