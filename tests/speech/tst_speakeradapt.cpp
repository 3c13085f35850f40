#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/speakeradapt.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

// Features of `frames` frames, all speech, every channel `value`.
SpeechFeatures flat(int frames, float value)
{
    SpeechFeatures f;
    f.frames = frames;
    f.vectors.assign(size_t(frames) * SpeechFeatures::kDim, value);
    f.silence.assign(size_t(frames), 0.0f);
    return f;
}

// The script in `voice` with silence around it and white noise 25 dB under it; `truth` gets
// the onsets.
Audio spoken(const Script &script, const TtsOptions &voice, quint32 seed, std::vector<double> *truth, double snrDb = 25)
{
    const TtsResult r = synthesize(script, voice);
    const Audio speech = resampled(r.audio, kSpeechSampleRate);
    QRandomGenerator rng(seed);
    const double lead = 0.3 + 0.4 * rng.generateDouble();
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    out.samples += speech.samples;
    out.samples += QVector<float>(qsizetype(0.4 * kSpeechSampleRate), 0.0f);
    double power = 0;
    for (const float s : speech.samples)
        power += double(s) * s;
    const double sigma = std::sqrt(power / double(speech.samples.size()) / std::pow(10.0, snrDb / 10));
    for (float &s : out.samples) {
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        s += float(sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    truth->clear();
    for (const TtsUnit &u : r.units)
        truth->push_back(lead + u.start);
    return out;
}

// Absolute onset errors in ms.
std::vector<double> errorsMs(const AlignResult &r, const std::vector<double> &truth)
{
    std::vector<double> e;
    for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k)
        e.push_back(std::abs(r.syllables[k].start - truth[size_t(k)]) * 1000);
    return e;
}

double quantile(std::vector<double> v, double q)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 1e9 : v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

} // namespace

class TestSpeakerAdapt : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void framesAreClassedByInitialAndFinal()
    {
        // ba (stop b, final a) over frames 0-9 with its initial over 0-2; ma over 10-19.
        const Script s = mandarin(QStringLiteral("ba1 ma1"));
        SpeechFeatures f = flat(25, 0.0f);
        f.silence[22] = 1.0f;
        const std::vector<int> c
            = soundClasses(f, s, {f.time(0), f.time(10)}, {f.time(3), f.time(13)}, {f.time(10), f.time(23)});
        QVERIFY(c[0] != 0 && c[0] == c[2]); // b
        QVERIFY(c[3] != c[0]); // a
        QVERIFY(c[10] != c[0] && c[10] != c[3]); // m: a nasal, not a stop
        QCOMPARE(c[13], c[3]); // the same final
        QCOMPARE(c[22], 0); // quiet: silence
        QCOMPARE(c[24], 0); // outside every syllable
    }

    void theReferenceMovesTowardTheRecordingByItsShareOfFrames()
    {
        // One class, the recording 1 higher in every channel than the reference.
        const std::vector<int> classes(200, 5);
        const SpeechFeatures rec = flat(200, 1.0f);
        SpeechFeatures ref = flat(200, 0.0f);
        QCOMPARE(adaptReference(rec, classes, &ref, classes), 1);
        const double full = 200.0 / (200.0 + kPriorFrames);
        QVERIFY(std::abs(ref.vector(17)[3] - full) < 1e-5);
        // Few frames: a small share of the difference (a short recording barely adapts).
        const std::vector<int> few(5, 5);
        const SpeechFeatures shortRec = flat(5, 1.0f);
        SpeechFeatures shortRef = flat(5, 0.0f);
        adaptReference(shortRec, few, &shortRef, few);
        QVERIFY(shortRef.vector(0)[0] < 0.2f);
        QVERIFY(shortRef.vector(0)[0] > 0.0f);
    }

    void adaptationNeverWorsensHeldOutVoices()
    {
        // espeak-ng voices, rates and pitches no constant was chosen on, each reading four
        // sentences in one recording (68 syllables: enough to adapt). Allowed margin: the
        // adapted alignment's median and 90th percentile may exceed the plain one's by at most
        // 5 and 10 ms (a frame or so, within which both are the same alignment), and it may put
        // at most one more onset (of 272) more than 80 ms off; nor may it make a clean recording
        // (no noise) worse by more than that.
        const struct
        {
            const char *voice;
            int rate, pitch;
        } voices[] = {{"cmn-latn-pinyin+m2", 200, 45}, {"cmn-latn-pinyin+f3", 135, 80}};
        const Script s = mandarin(
            QStringLiteral("小明每天早上六点起床，然后去学校上课。我们一起去买一本书，好不好？"
                           "银行的工作人员说，明天下午三点以后可以来取钱。这个问题很难回答，请你再说一遍。"));
        QVERIFY(s.syllables.size() >= kAdaptMinSyllables);
        std::vector<double> plain, adapted;
        quint32 seed = 11;
        for (const auto &v : voices)
            for (const double snrDb : {25.0, 300.0}) { // noisy, clean
                std::vector<double> truth;
                TtsOptions o;
                o.voice = QString::fromLatin1(v.voice);
                o.rate = v.rate;
                o.pitch = v.pitch;
                const Audio rec = spoken(s, o, seed++, &truth, snrDb);
                AlignOptions off;
                off.adaptToSpeaker = false;
                const AlignResult a = alignScript(rec, s), p = alignScript(rec, s, off);
                QVERIFY2(a.ok() && p.ok(), qPrintable(a.error + p.error));
                const std::vector<double> ea = errorsMs(a, truth), ep = errorsMs(p, truth);
                adapted.insert(adapted.end(), ea.begin(), ea.end());
                plain.insert(plain.end(), ep.begin(), ep.end());
            }
        const QString figures = QStringLiteral("median %1 → %2 ms, p90 %3 → %4 ms")
                                    .arg(quantile(plain, 0.5))
                                    .arg(quantile(adapted, 0.5))
                                    .arg(quantile(plain, 0.9))
                                    .arg(quantile(adapted, 0.9));
        qInfo("%s", qPrintable(figures));
        QVERIFY2(quantile(adapted, 0.5) <= quantile(plain, 0.5) + 5, qPrintable(figures));
        QVERIFY2(quantile(adapted, 0.9) <= quantile(plain, 0.9) + 10, qPrintable(figures));
        auto farOff = [](const std::vector<double> &e) {
            return std::count_if(e.begin(), e.end(), [](double x) { return x > 80; });
        };
        QVERIFY2(farOff(adapted) <= farOff(plain) + 1,
            qPrintable(figures + QStringLiteral("; > 80 ms: %1 → %2").arg(farOff(plain)).arg(farOff(adapted))));
    }

    void aShortRecordingIsNotAdapted()
    {
        // One sentence says too little about the voice: the alignment is the plain one.
        const Script s = mandarin(QStringLiteral("我们一起去买一本书，好不好？"));
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f3");
        o.rate = 150;
        std::vector<double> truth;
        const Audio rec = spoken(s, o, 5, &truth);
        AlignOptions off;
        off.adaptToSpeaker = false;
        const AlignResult a = alignScript(rec, s), p = alignScript(rec, s, off);
        QVERIFY(a.ok() && p.ok());
        for (int k = 0; k < a.syllables.size(); ++k)
            QCOMPARE(a.syllables[k].start, p.syllables[k].start);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSpeakerAdapt)
#include "tst_speakeradapt.moc"
