#include "speech/pinyin.h"
#include "speech/syllableshapes.h"
#include "testmain.h"

#include <QFile>
#include <QSet>
#include <QTest>

using namespace toonface;

class TestSyllableShapes : public QObject
{
    Q_OBJECT

private:
    static QStringList standardSyllables()
    {
        QFile f(QStringLiteral(TOONFACE_TEST_DATA "/speech/mandarin-syllables.txt"));
        if (!f.open(QIODevice::ReadOnly))
            return {};
        QStringList out;
        for (const QString &line : QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'))) {
            if (line.startsWith(QLatin1Char('#')))
                continue;
            out += line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        }
        return out;
    }

private Q_SLOTS:
    void contractVectors_data()
    {
        QTest::addColumn<QString>("pinyin");
        QTest::addColumn<QString>("shapes");
        // Every test vector of face-model.md.
        QTest::newRow("您 nin") << "nin"
                                << "i n";
        QTest::newRow("好 hao") << "hao"
                                << "a u";
        QTest::newRow("夕 xi") << "xi"
                               << "i";
        QTest::newRow("陽 yang") << "yang"
                                 << "i a n h";
        QTest::newRow("喵 miao") << "miao"
                                 << "m i a u";
        QTest::newRow("忽 hu") << "hu"
                               << "u";
        QTest::newRow("是 shi") << "shi"
                                << "i h";
        QTest::newRow("風 feng") << "feng"
                                 << "f e n h";
        QTest::newRow("明 ming") << "ming"
                                 << "m i n h";
        QTest::newRow("貴 gui") << "gui"
                                << "u e i";
        QTest::newRow("六 liu") << "liu"
                                << "i o u";
        QTest::newRow("翁 weng") << "weng"
                                 << "u e n h";
        QTest::newRow("熊 xiong") << "xiong"
                                  << "i o n h";
        QTest::newRow("二 er") << "er"
                               << "e h";
        QTest::newRow("雲 yun") << "yun"
                                << "u e n";
        QTest::newRow("一 yi") << "yi"
                               << "i";
        QTest::newRow("我 wo") << "wo"
                               << "u o";
    }
    void contractVectors()
    {
        QFETCH(QString, pinyin);
        QFETCH(QString, shapes);
        QCOMPARE(shapeSpelling(syllableShapes(pinyin)), shapes);
    }

    void rules_data()
    {
        QTest::addColumn<QString>("pinyin");
        QTest::addColumn<QString>("shapes");
        // Each rule of face-model.md once more, on syllables the contract does not list.
        QTest::newRow("b p m -> m") << "ba"
                                    << "m a";
        QTest::newRow("p -> m") << "pu"
                                << "m u";
        QTest::newRow("m merges with nothing") << "mu"
                                               << "m u";
        QTest::newRow("f -> f") << "fa"
                                << "f a";
        QTest::newRow("h' dropped before vowel") << "da"
                                                 << "a";
        QTest::newRow("zh h' dropped") << "zhu"
                                       << "u";
        QTest::newRow("empty rime zi") << "zi"
                                       << "i h";
        QTest::newRow("empty rime ri") << "ri"
                                       << "i h";
        QTest::newRow("not empty rime li") << "li"
                                           << "i";
        QTest::newRow("y of yu spelling only") << "yu"
                                               << "u";
        QTest::newRow("yue") << "yue"
                             << "u e";
        QTest::newRow("yuan") << "yuan"
                              << "u a n";
        QTest::newRow("you glide") << "you"
                                   << "i o u";
        QTest::newRow("ye glide") << "ye"
                                  << "i e";
        QTest::newRow("yin merges") << "yin"
                                    << "i n";
        QTest::newRow("ying") << "ying"
                              << "i n h";
        QTest::newRow("yong") << "yong"
                              << "i o n h";
        QTest::newRow("wu merges") << "wu"
                                   << "u";
        QTest::newRow("wei") << "wei"
                             << "u e i";
        QTest::newRow("wen") << "wen"
                             << "u e n";
        QTest::newRow("ü after j") << "ju"
                                   << "u";
        QTest::newRow("jun = jüen") << "jun"
                                    << "u e n";
        QTest::newRow("xue") << "xue"
                             << "u e";
        QTest::newRow("qu") << "qu"
                            << "u";
        QTest::newRow("lü written v") << "lv"
                                      << "u";
        QTest::newRow("lüe") << "lüe"
                             << "u e";
        QTest::newRow("nü u:") << "nu:"
                               << "u";
        QTest::newRow("un -> uen") << "dun"
                                   << "u e n";
        QTest::newRow("ui -> uei") << "dui"
                                   << "u e i";
        QTest::newRow("iu -> iou") << "jiu"
                                   << "i o u";
        QTest::newRow("ao -> a u") << "bao"
                                   << "m a u";
        QTest::newRow("iao") << "jiao"
                             << "i a u";
        QTest::newRow("ong -> o n h") << "dong"
                                      << "o n h";
        QTest::newRow("ang") << "fang"
                             << "f a n h";
        QTest::newRow("uang") << "zhuang"
                              << "u a n h";
        QTest::newRow("ou") << "ou"
                            << "o u";
        QTest::newRow("ai") << "mai"
                            << "m a i";
        QTest::newRow("an") << "an"
                            << "a n";
        QTest::newRow("bin") << "bin"
                             << "m i n";
        QTest::newRow("mian four shapes") << "mian"
                                          << "m i a n";
        QTest::newRow("tone number ignored") << "hao3"
                                             << "a u";
        QTest::newRow("tone mark ignored") << QStringLiteral("hǎo") << "a u";
        QTest::newRow("ü tone mark") << QStringLiteral("lǜ") << "u";
        QTest::newRow("upper case") << "MING2"
                                    << "m i n h";
        QTest::newRow("erhua") << "nar"
                               << "a h";
    }
    void rules()
    {
        QFETCH(QString, pinyin);
        QFETCH(QString, shapes);
        QCOMPARE(shapeSpelling(syllableShapes(pinyin)), shapes);
    }

    void rejectsNonSyllables_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("empty") << "";
        QTest::newRow("english") << "strength";
        QTest::newRow("bad final") << "bx";
        QTest::newRow("j with a") << "ja";
        QTest::newRow("g with i") << "gi";
        QTest::newRow("digit only") << "3";
        QTest::newRow("han character") << QStringLiteral("好");
    }
    void rejectsNonSyllables()
    {
        QFETCH(QString, text);
        QVERIFY(syllableShapes(text).isEmpty());
    }

    void everyStandardSyllableGivesOneToFourShapes()
    {
        const QStringList all = standardSyllables();
        QVERIFY2(all.size() >= 400, qPrintable(QStringLiteral("syllable table has %1 entries").arg(all.size())));
        QCOMPARE(QSet<QString>(all.begin(), all.end()).size(), all.size());
        for (const QString &s : all) {
            const QVector<MouthShape> shapes = syllableShapes(s);
            QVERIFY2(shapes.size() >= 1 && shapes.size() <= 4,
                qPrintable(s + QStringLiteral(" -> ") + shapeSpelling(shapes)));
            for (int k = 1; k < shapes.size(); ++k)
                QVERIFY2(shapes[k] != shapes[k - 1], qPrintable(s + QStringLiteral(" has equal neighbours")));
            // h' never survives in a standard syllable: the first shape is never an open h
            // unless the syllable itself starts with a vowel.
            QVERIFY2(shapes.first() != MouthShape::H, qPrintable(s));
        }
    }

    void timingFractions_data()
    {
        QTest::addColumn<int>("count");
        QTest::addColumn<QVector<double>>("fractions");
        QTest::newRow("1") << 1 << QVector<double> {0};
        QTest::newRow("2") << 2 << QVector<double> {0, 0.8095};
        QTest::newRow("3") << 3 << QVector<double> {0, 0.4337, 0.8312};
        QTest::newRow("4") << 4 << QVector<double> {0, 0.245, 0.4565, 0.7153};
    }
    void timingFractions()
    {
        QFETCH(int, count);
        QFETCH(QVector<double>, fractions);
        for (int k = 0; k < count; ++k)
            QVERIFY(qAbs(shapeStartFraction(count, k) - fractions[k]) < 1e-9);
        // Keys of a syllable at t0 = 2 s lasting 0.5 s start at t0 + f_k·T.
        QVector<MouthShape> shapes(count, MouthShape::A);
        const QVector<ShapeKey> keys = syllableShapeKeys(shapes, 2.0, 0.5);
        QCOMPARE(keys.size(), count);
        for (int k = 0; k < count; ++k)
            QVERIFY(qAbs(keys[k].start - (2.0 + fractions[k] * 0.5)) < 1e-9);
    }

    void miaoKeys()
    {
        const QVector<ShapeKey> keys = syllableShapeKeys(syllableShapes(QStringLiteral("miao")), 1.0, 0.4);
        QCOMPARE(keys.size(), 4);
        QCOMPARE(keys[0].shape, MouthShape::M);
        QCOMPARE(keys[3].shape, MouthShape::U);
        QVERIFY(qAbs(keys[3].start - (1.0 + 0.7153 * 0.4)) < 1e-9);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSyllableShapes)
#include "tst_syllableshapes.moc"
