#include "speech/features.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

// One second at kSpeechSampleRate: a sawtooth (every harmonic, as a glottal source has) at
// `f0` Hz, or white noise when f0 is 0.
Audio tone(double f0)
{
    Audio a;
    QRandomGenerator rng(7);
    for (int i = 0; i < kSpeechSampleRate; ++i) {
        const double t = double(i) / kSpeechSampleRate;
        a.samples.append(
            f0 > 0 ? float(0.3 * (2 * std::fmod(t * f0, 1.0) - 1)) : float(0.3 * (2 * rng.generateDouble() - 1)));
    }
    return a;
}

double medianVoicing(const SpeechFeatures &f)
{
    std::vector<float> v(f.voicing.begin() + 5, f.voicing.end() - 5);
    std::nth_element(v.begin(), v.begin() + qsizetype(v.size() / 2), v.end());
    return v[v.size() / 2];
}

} // namespace

class TestFeatures : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void quietStretchIsMeasuredAgainstItsOwnLevel()
    {
        // The same sentences twice, the second time 20 dB quieter (a recording joined from
        // two sources, or a speaker turning away): the second's speech must be speech and
        // its pauses pauses, as in the first.
        const TtsResult spoken = synthesize(parseScript(
            QStringLiteral("今天天气很好，我们去公园散步吧。银行的工作人员说，明天下午三点以后可以来取钱。"))
                                                .script);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        const Audio once = resampled(spoken.audio, kSpeechSampleRate);
        Audio both;
        both.samples.fill(0.0f, kSpeechSampleRate / 2);
        both.samples += once.samples;
        both.samples += QVector<float>(kSpeechSampleRate, 0.0f);
        const qsizetype second = both.samples.size();
        for (const float x : once.samples)
            both.samples.append(0.1f * x);
        both.samples += QVector<float>(kSpeechSampleRate / 2, 0.0f);
        QRandomGenerator rng(3);
        for (float &x : both.samples)
            x += float(1e-4 * (2 * rng.generateDouble() - 1));
        const SpeechFeatures f = computeSpeechFeatures(both);
        const int first = f.frameAt(0.5), offset = f.frameAt(double(second) / kSpeechSampleRate) - first;
        const int frames = f.frameAt(once.duration()) - 2;
        int agree = 0, speechLoud = 0, speechQuiet = 0;
        double loudDiff = 0;
        for (int t = first; t < first + frames; ++t) {
            const bool a = f.silence[size_t(t)] < 0.5f, b = f.silence[size_t(t + offset)] < 0.5f;
            agree += a == b;
            speechLoud += a;
            speechQuiet += b;
            loudDiff += std::abs(f.loudnessNorm[size_t(t)] - f.loudnessNorm[size_t(t + offset)]);
        }
        QVERIFY2(agree >= 0.95 * frames,
            qPrintable(QStringLiteral("%1 of %2 frames agree; speech %3 loud, %4 quiet")
                           .arg(agree)
                           .arg(frames)
                           .arg(speechLoud)
                           .arg(speechQuiet)));
        QVERIFY2(
            loudDiff / frames < 0.1, qPrintable(QStringLiteral("mean loudness difference %1").arg(loudDiff / frames)));
    }

    // Fed in pieces of any size, the stream computes exactly what the whole recording gives.
    void streamEqualsWhole()
    {
        Audio a;
        QRandomGenerator rng(11);
        for (int i = 0; i < 3 * kSpeechSampleRate + 123; ++i) {
            const double t = double(i) / kSpeechSampleRate;
            const double env = std::fmod(t, 0.4) < 0.25 ? 1.0 : 0.02; // syllables and gaps
            a.samples.append(float(env * (0.3 * std::sin(2 * M_PI * 140 * t) + 0.05 * (rng.generateDouble() - 0.5))));
        }
        const SpeechFeatures whole = computeSpeechFeatures(a);
        for (const qsizetype piece : {qsizetype(1), qsizetype(159), qsizetype(4096), qsizetype(100000)}) {
            SpeechFeatureStream stream;
            for (qsizetype at = 0; at < a.samples.size(); at += piece)
                stream.push(a.samples.constData() + at, std::min(piece, a.samples.size() - at));
            QCOMPARE(stream.samples(), qint64(a.samples.size()));
            const SpeechFeatures f = stream.finish();
            QCOMPARE(f.frames, whole.frames);
            QVERIFY(f.vectors == whole.vectors);
            QVERIFY(f.voicing == whole.voicing);
            QVERIFY(f.silence == whole.silence);
            QVERIFY(f.loudness == whole.loudness);
            QCOMPARE(f.noiseFloor, whole.noiseFloor);
        }
        QVERIFY(whole.frames > 290);
        // Fewer samples than one window: no frames, as for the whole.
        SpeechFeatureStream tiny;
        tiny.push(a.samples.constData(), 399);
        QCOMPARE(tiny.finish().frames, 0);
    }

    void voicingOfAPeriodicSound_data()
    {
        QTest::addColumn<double>("f0");
        // From a deep male voice (fewer than two periods in the 25 ms window) to a child's.
        QTest::newRow("70 Hz") << 70.0;
        QTest::newRow("85 Hz") << 85.0;
        QTest::newRow("120 Hz") << 120.0;
        QTest::newRow("220 Hz") << 220.0;
        QTest::newRow("380 Hz") << 380.0;
    }
    void voicingOfAPeriodicSound()
    {
        QFETCH(double, f0);
        const SpeechFeatures f = computeSpeechFeatures(tone(f0));
        QVERIFY(f.frames > 90);
        // The window's own taper is divided out: a 70 Hz voice read 0.3 before.
        const double v = medianVoicing(f);
        QVERIFY2(v >= 0.8, qPrintable(QStringLiteral("voicing %1").arg(v)));
    }

    void noiseIsNotVoiced()
    {
        const double v = medianVoicing(computeSpeechFeatures(tone(0)));
        QVERIFY2(v <= 0.4, qPrintable(QStringLiteral("voicing %1").arg(v)));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestFeatures)
#include "tst_features.moc"
