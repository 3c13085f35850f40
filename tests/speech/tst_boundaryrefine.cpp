#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/boundaryrefine.h"
#include "speech/features.h"
#include "speech/onsetsignals.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace toonface;

namespace {

// A made signal: `piece(t)` gives each sample (t in seconds), `seconds` long, at the
// features' rate.
Audio made(double seconds, const std::function<double(double)> &piece)
{
    Audio a;
    a.sampleRate = kSpeechSampleRate;
    const qsizetype n = qsizetype(seconds * kSpeechSampleRate);
    a.samples.resize(n);
    for (qsizetype i = 0; i < n; ++i)
        a.samples[i] = float(piece(double(i) / kSpeechSampleRate));
    return a;
}

// A voiced vowel-like sound: harmonics of 140 Hz with formant-like weights.
double vowel(double t)
{
    double s = 0;
    for (int h = 1; h <= 20; ++h) {
        const double f = 140.0 * h;
        const double w
            = std::exp(-std::pow((f - 700) / 300, 2)) + 0.6 * std::exp(-std::pow((f - 1200) / 300, 2)) + 0.05;
        s += w * std::sin(2 * M_PI * f * t + h);
    }
    return 0.15 * s;
}

double noise(QRandomGenerator &rng)
{
    return rng.generateDouble() * 2 - 1;
}

std::vector<RefinedBoundary> refine(const Audio &audio, const BoundaryInput &in)
{
    const SpeechFeatures f = computeSpeechFeatures(audio);
    const OnsetSignals sig(f);
    return refineBoundaries(f, sig, in);
}

BoundaryInput input(std::vector<double> starts, std::vector<OnsetKind> kinds, double end)
{
    BoundaryInput in;
    in.starts = std::move(starts);
    in.kinds = std::move(kinds);
    in.afterNasal.assign(in.starts.size(), false);
    in.minSeconds.assign(in.starts.size(), 0.06);
    in.speechEnd = end;
    return in;
}

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

// Absolute onset errors (ms) of an alignment against the truth.
std::vector<double> errors(const AlignResult &r, const std::vector<double> &truth)
{
    std::vector<double> e;
    for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k)
        e.push_back(std::abs(r.syllables[k].start - truth[size_t(k)]) * 1000);
    return e;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 1e9;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

class TestBoundaryRefine : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A vowel cut by a voiceless fricative at 0.5 s: an onset estimated 25 ms early (where the
    // smoothed loudness starts to fall) or 25 ms late moves to the cut.
    void voicelessOnsetMovesToTheFall_data()
    {
        QTest::addColumn<double>("estimate");
        QTest::newRow("early") << 0.475;
        QTest::newRow("late") << 0.525;
    }
    void voicelessOnsetMovesToTheFall()
    {
        QFETCH(double, estimate);
        QRandomGenerator rng(7);
        const Audio a = made(1.0, [&](double t) {
            if (t < 0.1)
                return 0.0003 * noise(rng);
            if (t < 0.5 || t >= 0.65)
                return vowel(t);
            return 0.02 * noise(rng);
        });
        const auto out = refine(a, input({0.1, estimate}, {OnsetKind::Vowel, OnsetKind::Voiceless}, 0.95));
        QVERIFY2(std::abs(out[1].start - 0.5) <= 0.006, qPrintable(QString::number(out[1].start)));
        QVERIFY(out[1].strength > 0.5);
    }

    // A vowel into a quieter voiced murmur (a nasal initial) at 0.5 s.
    void sonorantOnsetMovesToTheStep()
    {
        const Audio a = made(1.0, [&](double t) {
            if (t < 0.1)
                return 0.0;
            if (t < 0.5 || t >= 0.56)
                return vowel(t);
            return 0.3 * std::sin(2 * M_PI * 140 * t) * 0.15 + 0.05 * vowel(t);
        });
        const auto out = refine(a, input({0.1, 0.47}, {OnsetKind::Vowel, OnsetKind::Sonorant}, 0.95));
        QVERIFY2(std::abs(out[1].start - 0.5) <= 0.008, qPrintable(QString::number(out[1].start)));
    }

    // A vowel onset with no closure: the loudness dips smoothly to its lowest at 0.5 s.
    void vowelOnsetMovesToTheValley()
    {
        const Audio a = made(1.0, [&](double t) {
            if (t < 0.1)
                return 0.0;
            const double dip = 1.0 - 0.9 * std::exp(-std::pow((t - 0.5) / 0.03, 2));
            return vowel(t) * dip;
        });
        const auto out = refine(a, input({0.1, 0.525}, {OnsetKind::Vowel, OnsetKind::Vowel}, 0.95));
        QVERIFY2(std::abs(out[1].start - 0.5) <= 0.008, qPrintable(QString::number(out[1].start)));
    }

    // Sound out of a pause at 0.4 s, estimated 20 ms late.
    void onsetAfterAPauseMovesToTheRise()
    {
        QRandomGenerator rng(3);
        const Audio a = made(1.0, [&](double t) { return t < 0.4 ? 0.0003 * noise(rng) : vowel(t); });
        const auto out = refine(a, input({0.42}, {OnsetKind::Voiceless}, 0.95));
        QVERIFY2(std::abs(out[0].start - 0.4) <= 0.008, qPrintable(QString::number(out[0].start)));
    }

    // No landmark (a steady vowel): the onset stays where it was, with no strength.
    void steadySoundKeepsTheOnset()
    {
        const Audio a = made(1.0, [&](double t) { return t < 0.1 ? 0.0 : vowel(t); });
        const auto out = refine(a, input({0.1, 0.5}, {OnsetKind::Vowel, OnsetKind::Voiceless}, 0.95));
        QCOMPARE(out[1].start, 0.5);
        QCOMPARE(out[1].strength, 0.0);
    }

    // The window never takes a syllable under its least length: the previous syllable keeps
    // its minimum even when the landmark lies inside it.
    void windowKeepsTheMinimum()
    {
        QRandomGenerator rng(5);
        const Audio a = made(1.0, [&](double t) {
            if (t < 0.1)
                return 0.0003 * noise(rng);
            if (t < 0.45 || t >= 0.6)
                return vowel(t);
            return 0.02 * noise(rng);
        });
        BoundaryInput in = input({0.4, 0.47}, {OnsetKind::Vowel, OnsetKind::Voiceless}, 0.95);
        in.minSeconds = {0.06, 0.06};
        const auto out = refine(a, in);
        QVERIFY2(out[1].start >= 0.46 - 1e-9, qPrintable(QString::number(out[1].start)));
        // The next syllable's minimum bounds it from the right as well.
        in = input({0.1, 0.5, 0.55}, {OnsetKind::Vowel, OnsetKind::Voiceless, OnsetKind::Voiceless}, 0.95);
        in.minSeconds = {0.06, 0.04, 0.06};
        for (const RefinedBoundary &b : refine(a, in))
            QVERIFY(b.start >= 0);
        const auto bounded = refine(a, in);
        QVERIFY(bounded[1].start <= 0.55 - 0.04 + 1e-9);
    }

    // Synthetic speech in other voices and at other tempi than the reference (espeak-ng's
    // events give the exact onsets): the second pass brings the median onset error under
    // 6 ms (the first pass alone: 7-9 ms on these).
    void syntheticSpeechAtOtherTempi_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("voice");
        QTest::addColumn<int>("rate");
        QTest::newRow("f2 slow") << QStringLiteral("我爱北京天安门，天安门上太阳升。") << "cmn-latn-pinyin+f2" << 125;
        QTest::newRow("m3 fast") << QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。")
                                 << "cmn-latn-pinyin+m3" << 240;
        QTest::newRow("f4 ordinary") << QStringLiteral("这个问题很难回答，请你再说一遍。") << "cmn-latn-pinyin+f4"
                                     << 175;
    }
    void syntheticSpeechAtOtherTempi()
    {
        QFETCH(QString, text);
        QFETCH(QString, voice);
        QFETCH(int, rate);
        const Script script = mandarin(text);
        TtsOptions o;
        o.voice = voice;
        o.rate = rate;
        const TtsResult spoken = synthesize(script, o);
        QVERIFY2(spoken.ok(), qPrintable(spoken.error));
        // 0.3 s of quiet noise either side.
        Audio rec;
        rec.sampleRate = kSpeechSampleRate;
        const Audio speech = resampled(spoken.audio, kSpeechSampleRate);
        rec.samples.fill(0.0f, qsizetype(0.3 * kSpeechSampleRate));
        rec.samples += speech.samples;
        rec.samples += QVector<float>(qsizetype(0.3 * kSpeechSampleRate), 0.0f);
        QRandomGenerator rng {quint32(rate)};
        for (float &s : rec.samples)
            s += float(0.001 * noise(rng));
        std::vector<double> truth;
        for (const TtsUnit &u : spoken.units)
            truth.push_back(0.3 + u.start);
        AlignOptions refined;
        AlignOptions firstPass;
        firstPass.refineBoundaries = false;
        const AlignResult r = alignScript(rec, script, refined);
        const AlignResult before = alignScript(rec, script, firstPass);
        QVERIFY2(r.ok() && before.ok(), qPrintable(r.error + before.error));
        const double m = median(errors(r, truth)), m0 = median(errors(before, truth));
        qInfo("median onset error: %.1f ms refined, %.1f ms first pass", m, m0);
        // The refined onset is a fall's leading edge (the mouth may lead): on espeak-ng's
        // short transitions it lies within a frame of the phoneme's start.
        QVERIFY2(m <= 7, qPrintable(QStringLiteral("median %1 ms (first pass %2 ms)").arg(m).arg(m0)));
        QVERIFY(m < m0);
        // Every syllable keeps a plausible length.
        for (const AlignedSyllable &s : r.syllables)
            QVERIFY(s.end - s.start >= 0.04 - 1e-6);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestBoundaryRefine)
#include "tst_boundaryrefine.moc"
