#include "shareddata.h"
#include "testmain.h"

#include "speech/audio.h"
#include "speech/lipsync.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

bool writeText(const QString &path, const QString &text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text.toUtf8()) >= 0;
}

struct Run
{
    int code = -1;
    QByteArray out, err;
};

Run cli(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    p.waitForFinished(120000);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
        p.readAllStandardError()};
}

} // namespace

class TestLipsync : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    // A recording of `text` in a voice other than the aligner's reference, as a WAV file.
    QString recordingOf(const QString &text, const char *name)
    {
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f2");
        o.rate = 150;
        const TtsResult r = synthesize(parseScript(text).script, o);
        Audio a = resampled(r.audio, kSpeechSampleRate);
        a.samples = QVector<float>(8000, 0.0f) + a.samples + QVector<float>(8000, 0.0f);
        QString error;
        const QString p = path(name);
        return writeAudio(p, a, &error) ? p : QString();
    }

private Q_SLOTS:
    void cuesCoverTheAudio()
    {
        using S = MouthShape;
        QVector<LipsyncSyllable> syl(3);
        syl[0] = {QStringLiteral("好"), QStringLiteral("hao"), 3, 0.5, 0.8, 1, {{S::A, 0.5}, {S::U, 0.743}}};
        // 50 ms later: a short gap holds u.
        syl[1] = {QStringLiteral("喵"), QStringLiteral("miao"), 1, 0.85, 1.2, 1,
            {{S::M, 0.85}, {S::I, 0.94}, {S::A, 1.01}, {S::U, 1.1}}};
        // 400 ms later: silence, the mouth closes.
        syl[2] = {QStringLiteral("一"), QStringLiteral("yi"), 1, 1.6, 1.9, 1, {{S::I, 1.6}}};
        const QVector<MouthCue> cues = mouthCues(syl, 2.5);
        const QVector<MouthCue> expected
            = {{0, 0.5, S::M}, {0.5, 0.743, S::A}, {0.743, 0.85, S::U}, {0.85, 0.94, S::M}, {0.94, 1.01, S::I},
                {1.01, 1.1, S::A}, {1.1, 1.2, S::U}, {1.2, 1.6, S::M}, {1.6, 1.9, S::I}, {1.9, 2.5, S::M}};
        QCOMPARE(cues.size(), expected.size());
        for (int k = 0; k < cues.size(); ++k) {
            QCOMPARE(cues[k].shape, expected[k].shape);
            QVERIFY(std::abs(cues[k].start - expected[k].start) < 1e-9);
            QVERIFY(std::abs(cues[k].end - expected[k].end) < 1e-9);
        }
    }

    void equalNeighboursMerge()
    {
        using S = MouthShape;
        QVector<LipsyncSyllable> syl(2);
        syl[0] = {QStringLiteral("一"), QStringLiteral("yi"), 1, 0.0, 0.2, 1, {{S::I, 0.0}}};
        syl[1] = {QStringLiteral("夕"), QStringLiteral("xi"), 1, 0.2, 0.4, 1, {{S::I, 0.2}}};
        const QVector<MouthCue> cues = mouthCues(syl, 0.4);
        QCOMPARE(cues.size(), 1);
        QCOMPARE(cues[0], (MouthCue {0.0, 0.4, S::I}));
    }

    void resultOfSynthesizedSpeechUsesTheContractFractions()
    {
        const Script script = parseScript(QStringLiteral("喵，好")).script;
        const TtsResult spoken = synthesize(script);
        QVERIFY(spoken.ok());
        const LipsyncResult r = lipsyncResult(script, spoken);
        QCOMPARE(r.syllables.size(), 2);
        const LipsyncSyllable &miao = r.syllables[0];
        QCOMPARE(miao.shapes.size(), 4);
        const double T = miao.end - miao.start;
        QVERIFY(std::abs(miao.shapes[3].start - (miao.start + 0.7153 * T)) < 1e-9);
        QCOMPARE(r.mouthCues.front().start, 0.0);
        QVERIFY(std::abs(r.mouthCues.back().end - r.duration) < 1e-9);

        const QJsonObject json = lipsyncToJson(r);
        QCOMPARE(json[QStringLiteral("format")].toString(), QStringLiteral("toonface.lipsync/1"));
        QCOMPARE(json[QStringLiteral("language")].toString(), QStringLiteral("cmn"));
        const QJsonObject s0 = json[QStringLiteral("syllables")].toArray()[0].toObject();
        QCOMPARE(s0[QStringLiteral("text")].toString(), QStringLiteral("喵"));
        QCOMPARE(s0[QStringLiteral("pinyin")].toString(), QStringLiteral("miao"));
        QCOMPARE(s0[QStringLiteral("shapes")].toArray().size(), 4);
        QCOMPARE(s0[QStringLiteral("shapes")].toArray()[0].toObject()[QStringLiteral("shape")].toString(),
            QStringLiteral("m"));
        for (const QString &key : {QStringLiteral("start"), QStringLiteral("end"), QStringLiteral("confidence")})
            QVERIFY(s0.contains(key));
        const QJsonArray cues = json[QStringLiteral("mouthCues")].toArray();
        QCOMPARE(cues.size(), r.mouthCues.size());

        const QList<QByteArray> lines = lipsyncToTsv(r).split('\n');
        QCOMPARE(lines.size(), r.mouthCues.size() + 1); // trailing newline
        QCOMPARE(lines[0], QByteArray("0.000\tm"));
    }

    void englishResultUsesPhonemes()
    {
        const Script script = parseScript(QStringLiteral("map"), Language::English).script;
        const LipsyncResult r = lipsyncResult(script, synthesize(script));
        QCOMPARE(r.syllables.size(), 1);
        QCOMPARE(shapeSpelling(
                     {r.syllables[0].shapes[0].shape, r.syllables[0].shapes[1].shape, r.syllables[0].shapes[2].shape}),
            QStringLiteral("m a m"));
        QCOMPARE(lipsyncToJson(r)[QStringLiteral("language")].toString(), QStringLiteral("en"));
    }

    void filesEndToEnd()
    {
        const QString wav = recordingOf(QStringLiteral("今天天气很好"), "ok.wav");
        QVERIFY(!wav.isEmpty());
        QVERIFY(writeText(path("ok.txt"), QStringLiteral("今天天气很好\n")));
        const LipsyncOutcome out = lipsyncFiles(wav, path("ok.txt"));
        QVERIFY2(out.ok(), qPrintable(out.error));
        QCOMPARE(out.result.syllables.size(), 6);
        QVERIFY(out.result.syllables[0].start > 0.4); // after the half second of silence
    }

    void fileErrors()
    {
        QVERIFY(writeText(path("s.txt"), QStringLiteral("你好")));
        const LipsyncOutcome noAudio = lipsyncFiles(path("none.wav"), path("s.txt"));
        QCOMPARE(noAudio.status, LipsyncStatus::BadInput);
        QVERIFY(noAudio.error.contains(path("none.wav")));
        const QString wav = recordingOf(QStringLiteral("你好"), "short.wav");
        const LipsyncOutcome noScript = lipsyncFiles(wav, path("none.txt"));
        QCOMPARE(noScript.status, LipsyncStatus::BadInput);
        QVERIFY(noScript.error.contains(path("none.txt")));
        QString longText;
        for (int i = 0; i < 12; ++i)
            longText += QStringLiteral("我们明天早上八点在学校门口见面。");
        QVERIFY(writeText(path("long.txt"), longText));
        const LipsyncOutcome tooLong = lipsyncFiles(wav, path("long.txt"));
        QCOMPARE(tooLong.status, LipsyncStatus::CannotAlign);
    }

    void recordingWithAScriptInMemory()
    {
        const QString wav = recordingOf(QStringLiteral("你好"), "memory.wav");
        QVERIFY(!wav.isEmpty());
        const LipsyncOutcome ok
            = lipsyncRecording(wav, parseScript(QStringLiteral("你好")).script, QStringLiteral("the script"));
        QVERIFY2(ok.ok(), qPrintable(ok.error));
        QCOMPARE(ok.result.syllables.size(), 2);
        QString longText;
        for (int i = 0; i < 12; ++i)
            longText += QStringLiteral("我们明天早上八点在学校门口见面。");
        const LipsyncOutcome tooLong
            = lipsyncRecording(wav, parseScript(longText).script, QStringLiteral("the typed script"));
        QCOMPARE(tooLong.status, LipsyncStatus::CannotAlign);
        QVERIFY(tooLong.error.contains(wav));
        QVERIFY(tooLong.error.contains(QStringLiteral("the typed script")));
    }

    void cliLipsync()
    {
        const QString wav = recordingOf(QStringLiteral("春眠不觉晓"), "cli.wav");
        QVERIFY(writeText(path("cli.txt"), QStringLiteral("春眠不觉晓")));
        const Run json = cli(
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"), path("cli.txt")});
        QCOMPARE(json.code, 0);
        const QJsonObject o = QJsonDocument::fromJson(json.out).object();
        QCOMPARE(o[QStringLiteral("format")].toString(), QStringLiteral("toonface.lipsync/1"));
        QCOMPARE(o[QStringLiteral("syllables")].toArray().size(), 5);

        const Run tsv = cli({QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
            path("cli.txt"), QStringLiteral("-o"), path("cli.tsv")});
        QCOMPARE(tsv.code, 0);
        QFile f(path("cli.tsv"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QVERIFY(lines.size() >= 6);
        for (const QByteArray &line : lines)
            QCOMPARE(line.split('\t').size(), 2);
    }

    void cliLipsyncErrors()
    {
        QVERIFY(writeText(path("e.txt"), QStringLiteral("你好")));
        QVERIFY(writeText(path("bad.wav"), QStringLiteral("not a sound file at all")));
        const Run bad = cli({QStringLiteral("lipsync"), QStringLiteral("--audio"), path("bad.wav"),
            QStringLiteral("--script"), path("e.txt")});
        QCOMPARE(bad.code, 3);
        QVERIFY(bad.err.startsWith("toonface-cli: error: "));
        QVERIFY(bad.err.contains("bad.wav"));
        QCOMPARE(bad.err.count('\n'), 1);

        const QString wav = recordingOf(QStringLiteral("你好"), "e.wav");
        QString longText;
        for (int i = 0; i < 12; ++i)
            longText += QStringLiteral("我们明天早上八点在学校门口见面。");
        QVERIFY(writeText(path("elong.txt"), longText));
        const Run cannot = cli(
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"), path("elong.txt")});
        QCOMPARE(cannot.code, 5);
        QVERIFY(cannot.err.contains("could not be aligned"));

        QVERIFY(writeText(path("unknown.txt"), QStringLiteral("你好☃")));
        QCOMPARE(cli({QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
                         path("unknown.txt")})
                     .code,
            3);
        QCOMPARE(cli({QStringLiteral("lipsync"), QStringLiteral("--audio"), wav}).code, 2);
        QCOMPARE(cli({QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
                         path("e.txt"), QStringLiteral("--lang"), QStringLiteral("xx")})
                     .code,
            2);
    }

    void cliSay()
    {
        const Run r = cli({QStringLiteral("say"), QStringLiteral("你好，世界"), QStringLiteral("-o"), path("say.wav"),
            QStringLiteral("--timings"), path("say.json")});
        QCOMPARE(r.code, 0);
        const AudioResult a = loadAudio(path("say.wav"));
        QVERIFY2(a.ok(), qPrintable(a.error));
        QFile f(path("say.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        QCOMPARE(o[QStringLiteral("format")].toString(), QStringLiteral("toonface.lipsync/1"));
        const QJsonArray syl = o[QStringLiteral("syllables")].toArray();
        QCOMPARE(syl.size(), 4);
        QVERIFY(std::abs(o[QStringLiteral("duration")].toDouble() - a.audio.duration()) < 0.02);
        for (int k = 1; k < syl.size(); ++k)
            QVERIFY(syl[k].toObject()[QStringLiteral("start")].toDouble()
                >= syl[k - 1].toObject()[QStringLiteral("end")].toDouble());

        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("hello there"), QStringLiteral("--lang"),
                         QStringLiteral("en"), QStringLiteral("-o"), path("en.mp3")})
                     .code,
            0);
        QVERIFY(loadAudio(path("en.mp3")).ok());
        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("你好☃"), QStringLiteral("-o"), path("x.wav")}).code, 3);
        QCOMPARE(cli({QStringLiteral("say"), QStringLiteral("你好")}).code, 2);
    }

    // The same recording and script give the same timing every time within one process (the
    // editor lip-syncs again and again), also after other recordings were aligned between.
    void sameInputSameTimingInOneProcess()
    {
        const QDir speech(QDir(testing::sharedDataDir()).filePath(QStringLiteral("speech")));
        const QStringList names = {QStringLiteral("BAC009S0002W0122"), QStringLiteral("p2fa_test1")};
        for (const QString &name : names) {
            if (!speech.exists(name + QStringLiteral(".wav")) || !speech.exists(name + QStringLiteral(".txt")))
                QSKIP("the shared speech recordings are absent (../shared/data/speech)");
        }
        auto run = [&](const QString &name) {
            return lipsyncFiles(
                speech.filePath(name + QStringLiteral(".wav")), speech.filePath(name + QStringLiteral(".txt")));
        };
        QVector<LipsyncOutcome> first;
        for (const QString &name : names) {
            first.append(run(name));
            QVERIFY2(first.last().ok(), qPrintable(first.last().error));
        }
        for (int round = 0; round < 2; ++round) {
            for (int i = 0; i < names.size(); ++i) {
                const LipsyncOutcome again = run(names[i]);
                QVERIFY2(again.ok(), qPrintable(again.error));
                QCOMPARE(again.result.syllables.size(), first[i].result.syllables.size());
                for (int k = 0; k < again.result.syllables.size(); ++k) {
                    const LipsyncSyllable &a = first[i].result.syllables[k];
                    const LipsyncSyllable &b = again.result.syllables[k];
                    QVERIFY2(a == b,
                        qPrintable(QStringLiteral("%1 syllable %2 (%3): %4-%5 s, then %6-%7 s")
                                       .arg(names[i])
                                       .arg(k)
                                       .arg(a.text)
                                       .arg(a.start, 0, 'f', 4)
                                       .arg(a.end, 0, 'f', 4)
                                       .arg(b.start, 0, 'f', 4)
                                       .arg(b.end, 0, 'f', 4)));
                }
                QCOMPARE(again.result.mouthCues.size(), first[i].result.mouthCues.size());
            }
        }
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestLipsync)
#include "tst_lipsync.moc"
