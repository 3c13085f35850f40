#include "export/cartoonfile.h"
#include "face/averageface.h"
#include "render/style.h"
#include "render/svgface.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

// A still cartoon written to a file: SVG as it is, other suffixes drawn; a failure leaves no
// partial file and the older file intact.
class TestCartoonFile : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QByteArray m_svg;

    QStringList entries() const { return QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_svg = SvgFace(averageFace(QRectF(60, 80, 200, 240), QSize(320, 400)), Style::preset(QStringLiteral("normal")))
                    .svg();
        QVERIFY(m_svg.startsWith("<?xml") || m_svg.contains("<svg"));
    }

    void svgAsItIs()
    {
        const QString path = m_dir.filePath(QStringLiteral("face.svg"));
        QString error;
        QVERIFY2(writeCartoonFile(m_svg, QSize(320, 400), path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), m_svg);
    }

    void rasterBySuffixOrFormat()
    {
        QString error;
        const QString png = m_dir.filePath(QStringLiteral("face.png"));
        QVERIFY2(writeCartoonFile(m_svg, QSize(160, 200), png, &error), qPrintable(error));
        const QImage image(png);
        QCOMPARE(image.size(), QSize(160, 200));
        // The face is drawn: not one colour.
        QVERIFY(image.pixel(80, 100) != image.pixel(2, 2));
        // A forced format whatever the name.
        const QString noSuffix = m_dir.filePath(QStringLiteral("face-picture"));
        QVERIFY2(writeCartoonFile(m_svg, QSize(80, 100), noSuffix, &error, "png"), qPrintable(error));
        QCOMPARE(QImage(noSuffix, "PNG").size(), QSize(80, 100));
    }

    void failuresLeaveNothingAndNameTheFile()
    {
        const QString path = m_dir.filePath(QStringLiteral("keep.png"));
        QString error;
        QVERIFY(writeCartoonFile(m_svg, QSize(40, 50), path, &error));
        QFile before(path);
        QVERIFY(before.open(QIODevice::ReadOnly));
        const QByteArray old = before.readAll();
        before.close();
        const QStringList files = entries();
        // An unknown format, and a picture that cannot be drawn: the old file stays as it was.
        QVERIFY(!writeCartoonFile(m_svg, QSize(40, 50), path, &error, "nosuchformat"));
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(!writeCartoonFile("not svg at all", QSize(40, 50), path, &error));
        QVERIFY2(error.contains(path), qPrintable(error));
        QFile after(path);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), old);
        QCOMPARE(entries(), files); // no temporary file left
        // No suffix and no format; a folder that does not exist.
        QVERIFY(!writeCartoonFile(m_svg, QSize(40, 50), m_dir.filePath(QStringLiteral("bare")), &error));
        QVERIFY2(error.contains(QStringLiteral("bare")), qPrintable(error));
        const QString missing = m_dir.filePath(QStringLiteral("no/such/folder/face.svg"));
        QVERIFY(!writeCartoonFile(m_svg, QSize(40, 50), missing, &error));
        QVERIFY2(error.contains(missing), qPrintable(error));
    }
};

TOONFACE_TEST_MAIN(TestCartoonFile)
#include "tst_cartoonfile.moc"
