#include "io/textgrid.h"
#include "testmain.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

// Praat TextGrids in both text formats give the same intervals; a missing tier or file is an
// error naming the file.
class TestTextGrid : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &body)
    {
        QFile f(m_dir.filePath(name));
        if (f.open(QIODevice::WriteOnly))
            f.write(body);
        return f.fileName();
    }

private Q_SLOTS:
    void bothFormats_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::newRow("long") << QByteArray(
            "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\nxmin = 0\n"
            "xmax = 2.5\ntiers? <exists>\nsize = 2\nitem []:\n"
            "    item [1]:\n        class = \"IntervalTier\"\n        name = \"phones\"\n"
            "        xmin = 0\n        xmax = 2.5\n        intervals: size = 1\n"
            "        intervals [1]:\n            xmin = 0\n            xmax = 2.5\n"
            "            text = \"x\"\n"
            "    item [2]:\n        class = \"IntervalTier\"\n        name = \"syll\"\n"
            "        xmin = 0\n        xmax = 2.5\n        intervals: size = 3\n"
            "        intervals [1]:\n            xmin = 0\n            xmax = 0.75\n"
            "            text = \"\"\n"
            "        intervals [2]:\n            xmin = 0.75\n            xmax = 1.25\n"
            "            text = \"ni3\"\n"
            "        intervals [3]:\n            xmin = 1.25\n            xmax = 2.5\n"
            "            text = \"say \"\"hao\"\"\"\n");
        QTest::newRow("short") << QByteArray(
            "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n0\n2.5\n<exists>\n2\n"
            "\"IntervalTier\"\n\"phones\"\n0\n2.5\n1\n0\n2.5\n\"x\"\n"
            "\"IntervalTier\"\n\"syll\"\n0\n2.5\n3\n0\n0.75\n\"\"\n0.75\n1.25\n\"ni3\"\n"
            "1.25\n2.5\n\"say \"\"hao\"\"\"\n");
    }
    void bothFormats()
    {
        QFETCH(QByteArray, body);
        QString error;
        const QVector<TextGridInterval> syll
            = readTextGridTier(write(QStringLiteral("t.TextGrid"), body), QStringLiteral("syll"), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(syll.size(), 3);
        QCOMPARE(syll[1].start, 0.75);
        QCOMPARE(syll[1].end, 1.25);
        QCOMPARE(syll[1].text, QStringLiteral("ni3"));
        QCOMPARE(syll[2].end, 2.5);
        QVERIFY(syll[2].text.startsWith(QStringLiteral("say ")));
    }

    void errorsNameTheFile()
    {
        const QString path
            = write(QStringLiteral("one.TextGrid"), "\"IntervalTier\"\n\"words\"\n0\n1\n1\n0\n1\n\"a\"\n");
        QString error;
        QVERIFY(readTextGridTier(path, QStringLiteral("syll"), &error).isEmpty());
        QVERIFY(error.startsWith(path));
        QVERIFY(error.contains(QStringLiteral("syll")));
        const QString missing = m_dir.filePath(QStringLiteral("missing.TextGrid"));
        QVERIFY(readTextGridTier(missing, QStringLiteral("words"), &error).isEmpty());
        QVERIFY(error.startsWith(missing));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTextGrid)
#include "tst_textgrid.moc"
