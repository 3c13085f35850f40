#include "speech/script.h"
#include "speech/tonesandhi.h"

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

    void englishIsLeftAlone()
    {
        const Script s = parseScript(QStringLiteral("hello world"), Language::English).script;
        QCOMPARE(spokenTones(s), (QVector<int> {0, 0}));
    }
};

QTEST_GUILESS_MAIN(TestToneSandhi)
#include "tst_tonesandhi.moc"
