#include "speech/waveformpeaks.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// Noise whose loudness rises and falls (a word every half second), seeded.
Audio speechLike(double seconds, quint32 seed)
{
    Audio audio;
    QRandomGenerator random(seed);
    const int n = int(seconds * audio.sampleRate);
    audio.samples.resize(n);
    for (int i = 0; i < n; ++i) {
        const double t = double(i) / audio.sampleRate;
        const double envelope = 0.5 + 0.45 * std::sin(2 * M_PI * 2 * t);
        audio.samples[i] = float((random.generateDouble() * 2 - 1) * envelope);
    }
    return audio;
}

std::pair<float, float> bruteRange(const Audio &audio, qint64 from, qint64 to)
{
    from = std::clamp<qint64>(from, 0, audio.samples.size() - 1);
    to = std::clamp<qint64>(to, from + 1, audio.samples.size());
    const auto [lo, hi] = std::minmax_element(audio.samples.begin() + from, audio.samples.begin() + to);
    return {*lo, *hi};
}

} // namespace

class TestWaveformPeaks : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void levelsCoverTheSound()
    {
        const Audio audio = speechLike(7.3, 1);
        const WaveformPeaks peaks = WaveformPeaks::compute(audio);
        QVERIFY(!peaks.isEmpty());
        QCOMPARE(peaks.sampleCount(), qint64(audio.samples.size()));
        QCOMPARE(peaks.duration(), audio.duration());
        QVERIFY(peaks.levels().size() >= 4);
        for (int i = 0; i < peaks.levels().size(); ++i) {
            const WaveformPeaks::Level &level = peaks.levels()[i];
            QCOMPARE(level.samplesPerBin, WaveformPeaks::kBaseBin * int(std::pow(WaveformPeaks::kLevelFactor, i)));
            QCOMPARE(level.min.size(), (audio.samples.size() + level.samplesPerBin - 1) / level.samplesPerBin);
            // Each bin holds exactly the extremes of its samples.
            for (qsizetype b : {qsizetype(0), level.min.size() / 2, level.min.size() - 1}) {
                const auto [lo, hi] = bruteRange(audio, b * level.samplesPerBin, (b + 1) * level.samplesPerBin);
                QCOMPARE(level.min[b], lo);
                QCOMPARE(level.max[b], hi);
            }
        }
        QVERIFY(peaks.levels().last().min.size() <= 256);
    }

    // A range read from the peaks never misses an extreme of the samples and, bins being at
    // most the range's width, reaches at most one bin beyond each end.
    void rangeBoundsTheSamples()
    {
        const Audio audio = speechLike(5.0, 2);
        const WaveformPeaks peaks = WaveformPeaks::compute(audio);
        QRandomGenerator random(3);
        for (int k = 0; k < 300; ++k) {
            const double t0 = random.generateDouble() * 4.9;
            const double t1 = t0 + random.generateDouble() * random.generateDouble() * 2;
            const qint64 s0 = qint64(t0 * audio.sampleRate), s1 = qint64(std::ceil(t1 * audio.sampleRate));
            const auto [lo, hi] = peaks.range(t0, t1);
            const auto [exactLo, exactHi] = bruteRange(audio, s0, s1);
            QVERIFY2(lo <= exactLo && hi >= exactHi, qPrintable(QStringLiteral("%1..%2").arg(t0).arg(t1)));
            const int bin = peaks.levels()[peaks.levelFor(double(s1 - s0))].samplesPerBin;
            const auto [wideLo, wideHi] = bruteRange(audio, s0 - bin, s1 + bin);
            QVERIFY(lo >= wideLo && hi <= wideHi);
        }
        // Outside the sound: flat.
        QCOMPARE(peaks.range(-2, -1), std::make_pair(0.f, 0.f));
        QCOMPARE(peaks.range(6, 7), std::make_pair(0.f, 0.f));
    }

    void levelForPicksTheCoarsestFit()
    {
        const WaveformPeaks peaks = WaveformPeaks::compute(speechLike(30, 4));
        QCOMPARE(peaks.levelFor(1), 0);
        QCOMPARE(peaks.levelFor(16), 0);
        QCOMPARE(peaks.levelFor(64), 1);
        QCOMPARE(peaks.levelFor(100), 1);
        QCOMPARE(peaks.levelFor(1e9), int(peaks.levels().size()) - 1);
    }

    void emptyAndCancelled()
    {
        QVERIFY(WaveformPeaks::compute(Audio()).isEmpty());
        std::atomic_bool cancel(true);
        QVERIFY(WaveformPeaks::compute(speechLike(2, 5), &cancel).isEmpty());
    }

    void loadsAFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("speech.wav"));
        const Audio audio = speechLike(3, 6);
        QString error;
        QVERIFY2(writeAudio(path, audio, &error), qPrintable(error));
        const WaveformPeaksResult result = loadWaveformPeaks(path);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(std::abs(result.peaks.duration() - 3.0) < 0.01);
        // 16-bit PCM keeps the loudest sample to within a step.
        const auto [lo, hi] = result.peaks.range(0, 3);
        const auto [exactLo, exactHi] = bruteRange(audio, 0, audio.samples.size());
        QVERIFY(std::abs(lo - exactLo) < 1e-3 && std::abs(hi - exactHi) < 1e-3);
    }

    void badFileIsNamed()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("not-sound.wav"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("this is not a sound file at all");
        file.close();
        const WaveformPeaksResult result = loadWaveformPeaks(path);
        QVERIFY(!result.ok());
        QVERIFY(result.peaks.isEmpty());
        QVERIFY2(result.error.contains(path), qPrintable(result.error));
        QVERIFY(!loadWaveformPeaks(dir.filePath(QStringLiteral("missing.wav"))).ok());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestWaveformPeaks)
#include "tst_waveformpeaks.moc"
