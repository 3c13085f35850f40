#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/syllableduration.h"
#include "speech/tts.h"
#include "spokenrecordings.h"
#include "testmain.h"

#include <QTest>

using namespace toonface;
using namespace toonface::testing;

// How long the aligner's syllables come out: never shorter than their least plausible length
// (the duration model), whatever pulls two onsets together.
class TestAlignerLengths : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Where the warp brings two onsets within a few milliseconds of each other (here: a
    // reference whose syllable times say so), the onsets kept from the warp squeezed the
    // syllable between them to 10-20 ms; the search keeps every syllable's least length.
    void warpedOnsetsTooCloseKeepTheMinimum_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QList<int>>("squeezed");
        QTest::newRow("dui") << QStringLiteral("这绝对不行，我们去公园散步吧。") << QList<int> {2, 8};
        QTest::newRow("ming") << QStringLiteral("小明每天早上六点起床，然后去学校上课。") << QList<int> {1, 6, 12};
    }
    void warpedOnsetsTooCloseKeepTheMinimum()
    {
        QFETCH(QString, text);
        QFETCH(QList<int>, squeezed);
        const Script script = mandarin(text);
        std::vector<double> truth;
        const Audio rec = pieces({{script, 170}}, QStringLiteral("cmn-latn-pinyin+f2"), 0.5, 0, 40, 30, 3, &truth);
        TtsOptions o;
        o.rate = 170;
        TtsResult reference = synthesize(script, o);
        QVERIFY(reference.ok());
        for (int k : squeezed) {
            // Syllable k lasts 10 ms in the reference: the next starts right after it.
            reference.units[k + 1].start = reference.units[k].start + 0.01;
            reference.units[k].end = reference.units[k + 1].start;
        }
        const AlignResult r = alignToReference(rec, script, reference);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(script.syllables.size()), rec.duration());
        for (int k = 0; k < script.syllables.size(); ++k) {
            const AlignedSyllable &a = r.syllables[k];
            const ScriptSyllable &syl = script.syllables[k];
            QVERIFY2(a.end - a.start >= kShortestSyllable - 1e-6,
                qPrintable(QStringLiteral("%1 %2: %3 ms").arg(syl.text, syl.pinyin).arg((a.end - a.start) * 1000)));
        }
    }

    // The duration model holds inside the search: no syllable comes out shorter than its
    // least plausible length, whatever pulls two onsets together (a speaker who speeds up
    // within a phrase, long pauses the script does not mark).
    void noSyllableIsSqueezed_data()
    {
        QTest::addColumn<QStringList>("texts");
        QTest::addColumn<QList<int>>("rates");
        QTest::addColumn<double>("gap");
        QTest::newRow("slow then fast") << QStringList {QStringLiteral("小明每天早上"),
            QStringLiteral("六点起床然后去学校上课")}
                                        << QList<int> {100, 320} << 0.0;
        QTest::newRow("fast then slow") << QStringList {QStringLiteral("银行的工作人员说明天"),
            QStringLiteral("下午三点以后可以来取钱")}
                                        << QList<int> {330, 110} << 0.0;
        QTest::newRow("long pauses") << QStringList {QStringLiteral("这绝对不行"), QStringLiteral("自己明白"),
            QStringLiteral("我爱北京")}
                                     << QList<int> {200, 200, 200} << 1.2;
        QTest::newRow("fast throughout, pauses") << QStringList {QStringLiteral("今天天气很好，我们去公园散步吧。"),
            QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。"),
            QStringLiteral("你不要一天到晚想这个问题。")}
                                                 << QList<int> {300, 320, 340} << 0.5;
    }
    void noSyllableIsSqueezed()
    {
        QFETCH(QStringList, texts);
        QFETCH(QList<int>, rates);
        QFETCH(double, gap);
        QVector<QPair<Script, int>> parts;
        Script whole = mandarin(texts.join(QString()));
        for (int p = 0; p < texts.size(); ++p)
            parts.append({mandarin(texts[p]), rates[p]});
        std::vector<double> truth;
        const Audio rec = pieces(parts, QStringLiteral("cmn-latn-pinyin+f4"), 0.5, gap, 40, 30, 7, &truth);
        const AlignResult r = alignScript(rec, whole);
        QVERIFY2(r.ok(), qPrintable(r.error));
        checkWellFormed(r, int(whole.syllables.size()), rec.duration());
        checkNotSqueezed(r);
        const auto [median, p90] = onsetErrors(r, truth);
        QVERIFY2(median <= 45 && p90 <= 150, qPrintable(QStringLiteral("%1 / %2 ms").arg(median).arg(p90)));
    }

    // A fast voice (espeak-ng's klatt3 at 260 words a minute), sentence after sentence with a
    // pause the script does not mark: the shortest syllable was 50 ms (under the 40 ms floor
    // and a frame's rounding of its end).
    void fastVoiceKeepsSixtyMilliseconds()
    {
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+klatt3");
        o.rate = 260;
        o.pitch = 60;
        double shortest = 1e9;
        quint32 seed = 1;
        for (const QString &text : {QStringLiteral("今天天气很好，我们去公园散步吧。"),
                 QStringLiteral("我爱北京天安门，天安门上太阳升。"), QStringLiteral("这个问题很难回答，请你再说一遍。"),
                 QStringLiteral("小明每天早上六点起床，然后去学校上课。"),
                 QStringLiteral("春眠不觉晓，处处闻啼鸟。夜来风雨声，花落知多少。"),
                 QStringLiteral("银行的工作人员说，明天下午三点以后可以来取钱。"),
                 QStringLiteral("我们一起去买一本书，好不好？"), QStringLiteral("你不要一天到晚想这个问题。"),
                 QStringLiteral("老李很少给小马打电话。"), QStringLiteral("一个人不是一座孤岛。")}) {
            const Script script = mandarin(text);
            std::vector<double> truth;
            const Audio rec = recording(script, o, 20, seed++, &truth);
            const AlignResult r = alignScript(rec, script);
            QVERIFY2(r.ok(), qPrintable(r.error));
            shortest = std::min(shortest, shortestSyllable(r));
        }
        QVERIFY2(shortest >= 0.060 - 1e-6, qPrintable(QStringLiteral("shortest %1 ms").arg(shortest * 1000)));
    }

    void durationModel()
    {
        // Longer initials and finals need more time; the neutral tone less; a fast speaker less.
        QVERIFY(minimumSyllableSeconds(QStringLiteral("chuang"), 1, 1.0)
            > minimumSyllableSeconds(QStringLiteral("ba"), 1, 1.0));
        // (At a slow pace: at an ordinary one both are at the floor.)
        QVERIFY(minimumSyllableSeconds(QStringLiteral("shi"), 4, 1.4)
            > minimumSyllableSeconds(QStringLiteral("di"), 4, 1.4));
        QVERIFY(minimumSyllableSeconds(QStringLiteral("xiao"), 5, 1.0)
            < minimumSyllableSeconds(QStringLiteral("xiao"), 3, 1.0));
        QVERIFY(minimumSyllableSeconds(QStringLiteral("xiao"), 3, 0.7)
            < minimumSyllableSeconds(QStringLiteral("xiao"), 3, 1.0));
        QVERIFY(minimumSyllableSeconds(QStringLiteral("xiao"), 3, 1.4)
            > minimumSyllableSeconds(QStringLiteral("xiao"), 3, 1.0));
        // Never below the floor, however fast, and the floor for what is not pinyin.
        QCOMPARE(minimumSyllableSeconds(QStringLiteral("de"), 5, 0.1), kShortestSyllable);
        QCOMPARE(minimumSyllableSeconds(QString(), 0, 1.0), kShortestSyllable);
        QCOMPARE(minimumSyllableSeconds(QStringLiteral("hello"), 0, 1.0), kShortestSyllable);
        // An ordinary syllable's least length is well under an ordinary syllable.
        QVERIFY(minimumSyllableSeconds(QStringLiteral("zhuang"), 4, 1.0) < 0.6 * kOrdinarySyllable);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestAlignerLengths)
#include "tst_alignerlengths.moc"
