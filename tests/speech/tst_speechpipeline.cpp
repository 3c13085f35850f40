#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/lipsync.h"
#include "speech/paceprobe.h"
#include "speech/referencefeatures.h"
#include "speech/samplerelay.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QProcess>
#include <QTest>
#include <QTextStream>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

using namespace toonface;

// The speech work spread over two cores (speech/samplerelay.h, speech/paceprobe.h): the same
// results as on one, whatever the order the threads run in.

namespace {

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

// Mandarin text of at least `syllables` syllables.
QString longText(int syllables)
{
    const QString sentence = QStringLiteral("今天天气很好，我们去公园散步吧。小明每天早上六点起床，然后去学校上课。");
    QString text;
    while (mandarin(text).syllables.size() < syllables)
        text += sentence;
    return text;
}

// `script` spoken in another voice than the reference's, at `rate`, with silence around it.
Audio recordingOf(const Script &script, int rate)
{
    TtsOptions voice;
    voice.voice = QStringLiteral("cmn-latn-pinyin+f2");
    voice.rate = rate;
    Audio a = resampled(synthesize(script, voice).audio, kSpeechSampleRate);
    a.samples = QVector<float>(6000, 0.0f) + a.samples + QVector<float>(6000, 0.0f);
    return a;
}

QByteArray digest(const SpeechFeatures &f)
{
    QCryptographicHash h(QCryptographicHash::Sha1);
    for (const std::vector<float> *v : {&f.vectors, &f.logEnergy, &f.loudness, &f.voicing, &f.silence})
        h.addData(QByteArrayView(reinterpret_cast<const char *>(v->data()), qsizetype(v->size() * sizeof(float))));
    return QByteArray::number(f.frames) + ' ' + h.result().toHex();
}

QByteArray digest(const TtsResult &r)
{
    QByteArray out;
    for (const TtsUnit &u : r.units)
        out += QByteArray::number(u.start, 'g', 17) + ' ' + QByteArray::number(u.end, 'g', 17) + ' ';
    return out;
}

QByteArray digest(const AlignResult &r)
{
    QByteArray out = QByteArray::number(int(r.status)) + ' ';
    for (const AlignedSyllable &s : r.syllables)
        out += QByteArray::number(s.start, 'g', 17) + ' ' + QByteArray::number(s.end, 'g', 17) + ' '
            + QByteArray::number(s.confidence, 'g', 17) + ' ';
    return out;
}

// espeak-ng carries state from one rendering to the next in a process (the first block of
// samples depends on what was rendered before): two ways of doing one job are compared each
// in a new process of this test, after the same renderings.
//   reference relay|direct: the reference's features computed on another thread or on this one
//   probe whole|direct: the pace probe of a short script, or its rendering at the probe's rate
//   align ahead|plain SYLLABLES RATE: a recording aligned with the probe made ahead or not
int child(const QStringList &args)
{
    const QString job = args.value(0), how = args.value(1);
    QByteArray out;
    if (job == QLatin1String("reference")) {
        const Script script = mandarin(QStringLiteral("我爱北京天安门，天安门上太阳升。"));
        TtsOptions tts;
        tts.rate = 175;
        SpeechFeatures features;
        TtsResult r;
        if (how == QLatin1String("relay")) {
            r = renderReference(script, tts, &features);
        } else {
            ReferenceListener here(ttsSampleRate(), nullptr);
            r = synthesize(script, tts, [&](const float *s, qsizetype n) { here.push(s, n); });
            features = here.finish();
        }
        out = digest(features) + ' ' + digest(r);
    } else if (job == QLatin1String("probe")) {
        const Script script = mandarin(QStringLiteral("我爱北京天安门"));
        if (how == QLatin1String("whole")) {
            PaceProbe probe(script, AlignOptions {}.reference);
            const QByteArray sample = digest(probe.sample(nullptr)); // waits for it
            out = sample + ' ' + digest(probe.features());
        } else {
            TtsOptions tts = AlignOptions {}.reference;
            tts.rate = kDefaultReferenceRate;
            SpeechFeatures features;
            const TtsResult r = renderReference(script, tts, &features);
            out = digest(r) + ' ' + digest(features);
        }
    } else if (job == QLatin1String("align")) {
        const Script script = mandarin(longText(args.value(2).toInt()));
        const Audio audio = recordingOf(script, args.value(3).toInt());
        if (how == QLatin1String("ahead")) {
            // The probe renders while the recording's features are computed, as while it is
            // decoded.
            PaceProbe probe(script, AlignOptions {}.reference);
            const SpeechFeatures recording = computeSpeechFeatures(audio);
            out = digest(alignScript(recording, probe, script));
        } else {
            out = digest(alignScript(computeSpeechFeatures(audio), script));
        }
    }
    QTextStream(stdout) << out;
    return out.isEmpty() ? 1 : 0;
}

// What `child` prints for `args`.
QByteArray childResult(const QStringList &args)
{
    QProcess p;
    p.start(QCoreApplication::applicationFilePath(),
        toonface::test::suiteArguments() + QStringList {QStringLiteral("--child")} + args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        return "failed: " + p.readAllStandardError();
    return p.readAllStandardOutput();
}

} // namespace

class TestSpeechPipeline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void relayHandsOnEveryBlockInOrder()
    {
        // A producer much faster than its sink: the queue fills, the producer waits, and the
        // sink still sees every block, whole and in order, on a thread of its own.
        std::vector<float> seen;
        std::vector<qsizetype> sizes;
        std::thread::id sinkThread;
        std::vector<float> made;
        std::vector<qsizetype> madeSizes;
        {
            SampleRelay relay([&](const float *s, qsizetype n) {
                sinkThread = std::this_thread::get_id();
                if (sizes.size() % 16 == 0)
                    std::this_thread::sleep_for(std::chrono::milliseconds(2));
                seen.insert(seen.end(), s, s + n);
                sizes.push_back(n);
            });
            std::vector<float> block;
            for (int k = 0; k < 200; ++k) {
                block.assign(size_t(1 + (k * 37) % 500), 0.0f);
                for (size_t i = 0; i < block.size(); ++i)
                    block[i] = float(k) + float(i) * 1e-3f;
                relay.push(block.data(), qsizetype(block.size()));
                made.insert(made.end(), block.begin(), block.end());
                madeSizes.push_back(qsizetype(block.size()));
                relay.push(block.data(), 0); // nothing to hand on
            }
            relay.finish();
            QVERIFY(seen == made);
            QVERIFY(sizes == madeSizes);
            QVERIFY(sinkThread != std::this_thread::get_id());
            relay.finish(); // a second finish does nothing
        }
        // The destructor hands on what is left.
        std::vector<float> late;
        {
            SampleRelay relay([&](const float *s, qsizetype n) { late.insert(late.end(), s, s + n); });
            const float three[] = {1, 2, 3};
            relay.push(three, 3);
        }
        QCOMPARE(late, (std::vector<float> {1, 2, 3}));
    }

    void recordingFeaturesAreTheSameOnTwoCores()
    {
        // A recording's features computed two blocks at a time, one on a helper thread, fed in
        // pieces of every size: the same as on one thread.
        Audio audio;
        audio.sampleRate = kSpeechSampleRate;
        quint32 noise = 7;
        for (int i = 0; i < kSpeechSampleRate * 23 + 777; ++i) {
            noise = noise * 1664525u + 1013904223u;
            const double t = double(i) / kSpeechSampleRate;
            const double voiced
                = std::sin(2 * M_PI * (120 + 40 * std::sin(t)) * t) * (std::fmod(t, 0.4) < 0.25 ? 0.3 : 0.0);
            audio.samples.append(float(voiced + 0.01 * (double(noise >> 8) / double(1u << 24) - 0.5)));
        }
        SpeechFeatureStream two;
        two.useSecondCore();
        for (qsizetype at = 0, piece = 1; at < audio.samples.size(); at += piece, piece = piece * 3 % 9001 + 1)
            two.push(audio.samples.constData() + at, std::min(piece, audio.samples.size() - at));
        const SpeechFeatures twoCores = two.finish();
        QVERIFY(twoCores.frames > 2000);
        QCOMPARE(digest(twoCores), digest(computeSpeechFeatures(audio)));
    }

    void referenceFeaturesAreTheSameOnTwoCores()
    {
        // renderReference computes the features on another thread as espeak-ng speaks: they
        // must equal those computed on the speaking thread from the same blocks.
        const QByteArray relay = childResult({QStringLiteral("reference"), QStringLiteral("relay")});
        QVERIFY2(!relay.startsWith("failed") && !relay.startsWith("0 "), relay.constData());
        QCOMPARE(relay, childResult({QStringLiteral("reference"), QStringLiteral("direct")}));
    }

    void paceProbeRendersThePartTheAlignerNeeds()
    {
        TtsOptions fixed;
        fixed.rate = 160;
        QVERIFY(!PaceProbe(mandarin(QStringLiteral("你好")), fixed).needed());
        QVERIFY(!PaceProbe(Script {}, TtsOptions {}).needed());

        // A short script: all of it, with its features (it may be the reference itself).
        const Script shortScript = mandarin(QStringLiteral("我爱北京天安门"));
        PaceProbe whole(shortScript, AlignOptions {}.reference);
        QVERIFY(whole.needed());
        QVERIFY(whole.whole());
        QCOMPARE(whole.syllables(), 7);
        QVERIFY(whole.sample(nullptr).ok());
        QCOMPARE(whole.sample(nullptr).units.size(), 7);
        QVERIFY(whole.features().frames > 50);
        // The same as the reference rendered at the probe's rate.
        const QByteArray probed = childResult({QStringLiteral("probe"), QStringLiteral("whole")});
        QVERIFY2(!probed.startsWith("failed"), probed.constData());
        QCOMPARE(probed, childResult({QStringLiteral("probe"), QStringLiteral("direct")}));

        // A long one: its first syllables only, their times alone.
        const Script longScript = mandarin(longText(PaceProbe::kProbeSyllables + 30));
        PaceProbe part(longScript, AlignOptions {}.reference);
        QVERIFY(!part.whole());
        QCOMPARE(part.syllables(), PaceProbe::kProbeSyllables);
        QCOMPARE(part.sample(nullptr).units.size(), PaceProbe::kProbeSyllables);
        QCOMPARE(part.features().frames, 0);
    }

    void alignmentWithAProbeMadeAheadIsTheSame_data()
    {
        QTest::addColumn<int>("syllables");
        QTest::addColumn<int>("rate");
        QTest::newRow("short, the probe is the reference") << 14 << 165;
        QTest::newRow("short, another pace") << 14 << 120;
        QTest::newRow("long, the probe measures the pace") << PaceProbe::kProbeSyllables + 40 << 160;
    }

    void alignmentWithAProbeMadeAheadIsTheSame()
    {
        QFETCH(int, syllables);
        QFETCH(int, rate);
        const QStringList args = {QString::number(syllables), QString::number(rate)};
        const QByteArray ahead = childResult(QStringList {QStringLiteral("align"), QStringLiteral("ahead")} + args);
        QVERIFY2(ahead.startsWith(QByteArray::number(int(AlignStatus::Ok)) + ' '), ahead.constData());
        QCOMPARE(ahead, childResult(QStringList {QStringLiteral("align"), QStringLiteral("plain")} + args));
    }

    void cancelStopsTheProbe()
    {
        const Script script = mandarin(longText(PaceProbe::kProbeSyllables + 10));
        const SpeechFeatures recording
            = computeSpeechFeatures(recordingOf(mandarin(QStringLiteral("今天天气很好")), 160));
        std::atomic_bool cancel {true};
        PaceProbe probe(script, AlignOptions {}.reference);
        QCOMPARE(alignScript(recording, probe, script, {}, {}, &cancel).status, AlignStatus::Cancelled);
        // Abandoned at once when no longer wanted (the destructor stops it, never hangs).
        {
            PaceProbe dropped(script, AlignOptions {}.reference);
        }
    }

    void unreadableRecordingFailsWhileTheProbeRenders()
    {
        const LipsyncOutcome out = lipsyncRecording(QStringLiteral("/nonexistent/speech.wav"),
            mandarin(longText(PaceProbe::kProbeSyllables + 10)), QStringLiteral("script.txt"));
        QVERIFY(!out.ok());
        QVERIFY2(out.error.contains(QLatin1String("/nonexistent/speech.wav")), qPrintable(out.error));
    }
};

namespace {

int suiteMain(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    if (argc > 2 && qstrcmp(argv[1], "--child") == 0)
        return child(app.arguments().mid(2));
    TestSpeechPipeline test;
    return QTest::qExec(&test, argc, argv);
}

} // namespace

TOONFACE_TEST_REGISTER(suiteMain)
#include "tst_speechpipeline.moc"
