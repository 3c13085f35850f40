#include "shareddata.h"
#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/englishshapes.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QFile>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

QString spelling(const QVector<ShapeKey> &keys)
{
    QVector<MouthShape> shapes;
    for (const ShapeKey &k : keys)
        shapes.append(k.shape);
    return shapeSpelling(shapes);
}

} // namespace

class TestEnglishShapes : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void phonemeTable_data()
    {
        QTest::addColumn<QString>("phoneme");
        QTest::addColumn<QString>("shapes");
        QTest::addColumn<bool>("hPrime");
        QTest::newRow("p") << "p"
                           << "m" << false;
        QTest::newRow("b") << "b"
                           << "m" << false;
        QTest::newRow("m") << "m"
                           << "m" << false;
        QTest::newRow("f") << "f"
                           << "f" << false;
        QTest::newRow("v") << "v"
                           << "f" << false;
        QTest::newRow("w") << "w"
                           << "u" << false;
        QTest::newRow("goose") << "u:"
                               << "u" << false;
        QTest::newRow("foot") << "U"
                              << "u" << false;
        QTest::newRow("sh") << "S"
                            << "u" << false;
        QTest::newRow("lot") << "0"
                             << "o" << false;
        QTest::newRow("goat") << "oU"
                              << "o u" << false;
        QTest::newRow("trap") << "a"
                              << "a" << false;
        QTest::newRow("strut") << "V"
                               << "a" << false;
        QTest::newRow("price") << "aI"
                               << "a i" << false;
        QTest::newRow("mouth") << "aU"
                               << "a u" << false;
        QTest::newRow("dress") << "E"
                               << "e" << false;
        QTest::newRow("face") << "eI"
                              << "e i" << false;
        QTest::newRow("fleece") << "i:"
                                << "i" << false;
        QTest::newRow("yes j") << "j"
                               << "i" << false;
        QTest::newRow("n") << "n"
                           << "n" << false;
        QTest::newRow("ng") << "N"
                            << "n" << false;
        QTest::newRow("schwa") << "@"
                               << "h" << false;
        QTest::newRow("t") << "t"
                           << "h" << true;
        QTest::newRow("s") << "s"
                           << "h" << true;
        QTest::newRow("stress marks ignored") << "'aI"
                                              << "a i" << false;
        QTest::newRow("pause") << "_:"
                               << "" << false;
    }
    void phonemeTable()
    {
        QFETCH(QString, phoneme);
        QFETCH(QString, shapes);
        QFETCH(bool, hPrime);
        bool h = false;
        QCOMPARE(shapeSpelling(englishPhonemeShapes(phoneme, &h)), shapes);
        QCOMPARE(h, hPrime);
    }

    void wordKeys()
    {
        // h' dropped before a vowel, kept at the end; diphthongs split halfway; neighbours merge.
        const QVector<TtsPhoneme> five
            = {{QStringLiteral("f"), 1.0}, {QStringLiteral("aI"), 1.1}, {QStringLiteral("v"), 1.3}};
        const QVector<ShapeKey> k = englishWordKeys(five, 1.0, 1.4);
        QCOMPARE(spelling(k), QStringLiteral("f a i f"));
        QVERIFY(std::abs(k[2].start - 1.2) < 1e-9);
        const QVector<TtsPhoneme> see = {{QStringLiteral("s"), 2.0}, {QStringLiteral("i:"), 2.08}};
        QCOMPARE(spelling(englishWordKeys(see, 2.0, 2.3)), QStringLiteral("i"));
        QCOMPARE(englishWordKeys(see, 2.0, 2.3).first().start, 2.0);
        const QVector<TtsPhoneme> yes
            = {{QStringLiteral("j"), 0}, {QStringLiteral("E"), 0.05}, {QStringLiteral("s"), 0.2}};
        QCOMPARE(spelling(englishWordKeys(yes, 0, 0.3)), QStringLiteral("i e h"));
        const QVector<TtsPhoneme> mm = {{QStringLiteral("m"), 0}, {QStringLiteral("b"), 0.05}};
        QCOMPARE(spelling(englishWordKeys(mm, 0, 0.1)), QStringLiteral("m"));
        QCOMPARE(spelling(englishWordKeys({}, 0, 0.1)), QStringLiteral("h"));
    }

    void wordsThroughEspeak_data()
    {
        QTest::addColumn<QString>("word");
        QTest::addColumn<QString>("shapes");
        QTest::newRow("map") << "map"
                             << "m a m";
        QTest::newRow("five") << "five"
                              << "f a i f";
        QTest::newRow("who") << "who"
                             << "u";
        QTest::newRow("boy") << "boy"
                             << "m o i";
        QTest::newRow("wow") << "wow"
                             << "u a u";
    }
    void wordsThroughEspeak()
    {
        QFETCH(QString, word);
        QFETCH(QString, shapes);
        const ScriptParse p = parseScript(word, Language::English);
        QVERIFY(p.ok());
        const TtsResult r = synthesize(p.script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(spelling(englishWordKeys(r.units[0].phonemes, r.units[0].start, r.units[0].end)), shapes);
    }

    void gridSentenceIsAligned()
    {
        // GRID clip with hand-checked word intervals (units of 1/25000 s).
        const QString dir = testing::sharedDataDir() + QStringLiteral("/video/");
        if (!QFile::exists(dir + QStringLiteral("swwp2s.align")))
            QSKIP("shared data (video/swwp2s.align) not present");
        QFile f(dir + QStringLiteral("swwp2s.align"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QStringList words;
        std::vector<double> truth;
        for (const QString &line : QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
            const QStringList cols = line.trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (cols.size() == 3 && cols[2] != QLatin1String("sil")) {
                words.append(cols[2]);
                truth.push_back(cols[0].toDouble() / 25000.0);
            }
        }
        const AudioResult audio = loadAudio(dir + QStringLiteral("id2_vcd_swwp2s.mpg"));
        QVERIFY2(audio.ok(), qPrintable(audio.error));
        const ScriptParse script = parseScript(words.join(QLatin1Char(' ')));
        QCOMPARE(script.script.language, Language::English);
        const AlignResult r = alignScript(audio.audio, script.script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        std::vector<double> e;
        for (int k = 0; k < r.syllables.size(); ++k)
            e.push_back(std::abs(r.syllables[k].start - truth[size_t(k)]) * 1000);
        std::sort(e.begin(), e.end());
        // Word onsets of a different language and method: looser than the Mandarin targets.
        QVERIFY2(e[e.size() / 2] <= 60, qPrintable(QStringLiteral("median %1 ms").arg(e[e.size() / 2])));
        QVERIFY2(e.back() <= 200, qPrintable(QStringLiteral("max %1 ms").arg(e.back())));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestEnglishShapes)
#include "tst_englishshapes.moc"
