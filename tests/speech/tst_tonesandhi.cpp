#include "speech/script.h"
#include "speech/tonesandhi.h"
#include "testmain.h"

#include <QTest>

using namespace toonface;

namespace {

// The spoken tones of a Mandarin script, as "yi2 ge4"-style text.
QString spoken(const QString &text)
{
    const ScriptParse p = parseScript(text, Language::Mandarin);
    if (!p.ok())
        return p.error;
    const QVector<int> tones = spokenTones(p.script);
    QStringList out;
    for (qsizetype k = 0; k < p.script.syllables.size(); ++k)
        out.append(p.script.syllables[k].pinyin + QString::number(tones[k]));
    return out.join(QLatin1Char(' '));
}

} // namespace

class TestToneSandhi : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void yiChangesWithTheNextTone()
    {
        QCOMPARE(spoken(QStringLiteral("一个")), QStringLiteral("yi2 ge4"));
        QCOMPARE(spoken(QStringLiteral("一天")), QStringLiteral("yi4 tian1"));
        QCOMPARE(spoken(QStringLiteral("一年")), QStringLiteral("yi4 nian2"));
        QCOMPARE(spoken(QStringLiteral("一起")), QStringLiteral("yi4 qi3"));
    }

    void yiKeepsItsToneWhenCountingOrLast()
    {
        QCOMPARE(spoken(QStringLiteral("第一")), QStringLiteral("di4 yi1"));
        QCOMPARE(spoken(QStringLiteral("十一")), QStringLiteral("shi2 yi1"));
        QCOMPARE(spoken(QStringLiteral("一二三")), QStringLiteral("yi1 er4 san1"));
        // A phrase break ends the context: 一 before the comma is not changed by 天.
        QCOMPARE(spoken(QStringLiteral("一，天")), QStringLiteral("yi1 tian1"));
    }

    void buRisesBeforeAFourthTone()
    {
        QCOMPARE(spoken(QStringLiteral("不是")), QStringLiteral("bu2 shi4"));
        QCOMPARE(spoken(QStringLiteral("不对")), QStringLiteral("bu2 dui4"));
        QCOMPARE(spoken(QStringLiteral("不来")), QStringLiteral("bu4 lai2"));
    }

    void repeatedWordsMakeTheMiddleNeutral()
    {
        QCOMPARE(spoken(QStringLiteral("看一看")), QStringLiteral("kan4 yi5 kan4"));
        QCOMPARE(spoken(QStringLiteral("是不是")), QStringLiteral("shi4 bu5 shi4"));
    }

    void thirdBeforeThirdRises()
    {
        QCOMPARE(spoken(QStringLiteral("你好")), QStringLiteral("ni2 hao3"));
        // All but the last of a run; pinyin scripts too.
        QCOMPARE(spoken(QStringLiteral("wo3 ye3 hen3 hao3")), QStringLiteral("wo2 ye2 hen2 hao3"));
        QCOMPARE(spoken(QStringLiteral("ni3, hao3")), QStringLiteral("ni3 hao3"));
    }

    // Polyphonic characters read as the word around them has them, before the sandhi: the
    // phrase dictionaries list some words twice (不好 also as bú hào) and the usual reading must
    // win; outside any word the particles take their grammatical reading.
    void polyphonesReadInContext_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        const char *rows[][2] = {
            {"不好", "bu4 hao3"},
            {"好不好", "hao3 bu5 hao3"},
            {"很好", "hen2 hao3"},
            {"好人", "hao3 ren2"},
            {"爱好", "ai4 hao4"},
            {"好奇", "hao4 qi2"},
            {"银行", "yin2 hang2"},
            {"行人", "xing2 ren2"},
            {"不行", "bu4 xing2"},
            {"长城", "chang2 cheng2"},
            {"长大", "zhang3 da4"},
            {"校长", "xiao4 zhang3"},
            {"了解", "liao2 jie3"},
            {"走了", "zou3 le5"},
            {"得到", "de2 dao4"},
            {"觉得", "jue2 de5"},
            {"跑得快", "pao3 de5 kuai4"},
            {"都是", "dou1 shi4"},
            {"首都", "shou3 du1"},
            {"还是", "hai2 shi4"},
            {"还书", "huan2 shu1"},
            {"重要", "zhong4 yao4"},
            {"重新", "chong2 xin1"},
            {"因为", "yin1 wei4"},
            {"认为", "ren4 wei2"},
            {"为什么", "wei4 shen2 me5"},
            {"看着", "kan4 zhe5"},
            {"着急", "zhao2 ji2"},
            {"地方", "di4 fang1"},
            {"慢慢地", "man4 man4 de5"},
            {"我的", "wo3 de5"},
            {"获得", "huo4 de2"},
            {"记得", "ji4 de5"},
            {"长得很高", "zhang3 de5 hen3 gao1"},
            {"不长", "bu4 chang2"},
            {"好好地", "hao2 hao3 de5"},
            {"土地", "tu3 di4"},
            {"目的", "mu4 di4"},
        };
        for (const auto &r : rows)
            QTest::newRow(r[0]) << QString::fromUtf8(r[0]) << QString::fromUtf8(r[1]);
    }
    void polyphonesReadInContext()
    {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        QCOMPARE(spoken(text), expected);
    }

    void englishIsLeftAlone()
    {
        const Script s = parseScript(QStringLiteral("hello world"), Language::English).script;
        QCOMPARE(spokenTones(s), (QVector<int> {0, 0}));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestToneSandhi)
#include "tst_tonesandhi.moc"
