#include "io/imageio.h"
#include "testmain.h"

#include <QBuffer>
#include <QColorSpace>
#include <QFile>
#include <QImageReader>
#include <QTemporaryDir>
#include <QTest>

#include <cstdlib>

using namespace toonface;

namespace {

quint32 crc32(const QByteArray &data)
{
    quint32 crc = 0xFFFFFFFFu;
    for (char c : data) {
        crc ^= quint8(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

QByteArray be32(quint32 v)
{
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i)
        b[i] = char((v >> (24 - 8 * i)) & 0xFF);
    return b;
}

QByteArray pngChunk(const char *type, const QByteArray &payload)
{
    const QByteArray body = QByteArray(type) + payload;
    return be32(quint32(payload.size())) + body + be32(crc32(body));
}

// A valid PNG whose header claims a width x height RGB image, with (far too little) pixel data:
// a tiny file that would need gigabytes once decoded.
QByteArray pngClaiming(quint32 width, quint32 height)
{
    QByteArray ihdr = be32(width) + be32(height);
    ihdr += QByteArray("\x08\x02\x00\x00\x00", 5); // 8 bits, RGB, deflate, no filter, no interlace
    const QByteArray emptyZlibStream("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
    return QByteArray("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", emptyZlibStream)
        + pngChunk("IEND", {});
}

QByteArray encode(const QImage &image, const char *format, int quality = -1)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, format, quality);
    return bytes;
}

// An EXIF APP1 segment holding only the Orientation tag (0x0112, SHORT) in a big-endian TIFF.
QByteArray exifOrientationSegment(quint16 orientation)
{
    QByteArray tiff("MM\x00\x2a", 4);
    tiff += be32(8); // offset of IFD0
    tiff += QByteArray("\x00\x01", 2); // one entry
    tiff += QByteArray("\x01\x12\x00\x03", 4) + be32(1); // Orientation, SHORT, count 1
    tiff += char(orientation >> 8);
    tiff += char(orientation & 0xFF);
    tiff += QByteArray(2, 0); // value padded to 4 bytes
    tiff += be32(0); // no next IFD
    const QByteArray payload = QByteArray("Exif\x00\x00", 6) + tiff;
    const int length = int(payload.size()) + 2;
    return QByteArray("\xff\xe1", 2) + char(length >> 8) + char(length & 0xFF) + payload;
}

// 40 x 20: the left half red, the right half blue.
QImage leftRedRightBlue()
{
    QImage image(40, 20, QImage::Format_RGB32);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            image.setPixel(x, y, x < 20 ? qRgb(230, 20, 20) : qRgb(20, 20, 230));
    return image;
}

QImage detailed(int w, int h)
{
    QImage image(w, h, QImage::Format_RGB32);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.setPixel(x, y, qRgb((x * 7) % 256, (y * 5) % 256, ((x ^ y) * 3) % 256));
    return image;
}

bool near(QRgb a, QRgb b, int tol)
{
    return std::abs(qRed(a) - qRed(b)) <= tol && std::abs(qGreen(a) - qGreen(b)) <= tol
        && std::abs(qBlue(a) - qBlue(b)) <= tol;
}

QString rgb(QRgb c)
{
    return QStringLiteral("(%1, %2, %3)").arg(qRed(c)).arg(qGreen(c)).arg(qBlue(c));
}

} // namespace

class TestImageIo : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            qFatal("cannot write a fixture");
        return path;
    }

    QString writeImage(const QString &name, const QImage &image, const char *format)
    {
        return write(name, encode(image, format));
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void grayscalePng()
    {
        QImage gray(32, 16, QImage::Format_Grayscale8);
        for (int y = 0; y < gray.height(); ++y)
            for (int x = 0; x < gray.width(); ++x)
                gray.scanLine(y)[x] = uchar(x * 8);
        const QString path = writeImage(QStringLiteral("gray.png"), gray, "png");
        QCOMPARE(QImageReader(path).read().format(), QImage::Format_Grayscale8);
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.format(), QImage::Format_RGB32);
        QCOMPARE(image.size(), QSize(32, 16));
        for (int x = 0; x < 32; ++x)
            QCOMPARE(image.pixel(x, 7), qRgb(x * 8, x * 8, x * 8));
    }

    void alphaIsCompositedOnWhite()
    {
        QImage rgba(4, 1, QImage::Format_ARGB32);
        rgba.setPixel(0, 0, qRgba(200, 10, 20, 255)); // opaque
        rgba.setPixel(1, 0, qRgba(0, 0, 0, 0)); // fully transparent
        rgba.setPixel(2, 0, qRgba(0, 0, 0, 128)); // half-transparent black
        rgba.setPixel(3, 0, qRgba(0, 0, 255, 64)); // a quarter of blue
        const QString path = writeImage(QStringLiteral("rgba.png"), rgba, "png");
        QVERIFY(QImageReader(path).read().hasAlphaChannel());
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.format(), QImage::Format_RGB32);
        // White shows through by (255 - alpha); tolerance 1 for premultiplication rounding.
        const QRgb expected[] = {qRgb(200, 10, 20), qRgb(255, 255, 255), qRgb(127, 127, 127), qRgb(191, 191, 255)};
        for (int x = 0; x < 4; ++x)
            QVERIFY2(near(image.pixel(x, 0), expected[x], 1), qPrintable(rgb(image.pixel(x, 0))));
    }

    void sixteenBitPngs()
    {
        QImage gray16(8, 4, QImage::Format_Grayscale16);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x)
                reinterpret_cast<quint16 *>(gray16.scanLine(y))[x] = quint16(x * 0x2000);
        const QString grayPath = writeImage(QStringLiteral("gray16.png"), gray16, "png");
        QCOMPARE(QImageReader(grayPath).read().format(), QImage::Format_Grayscale16);

        QImage rgba64(3, 1, QImage::Format_RGBA64);
        rgba64.setPixelColor(0, 0, QColor::fromRgba64(0xFFFF, 0x8000, 0x0000, 0xFFFF));
        rgba64.setPixelColor(1, 0, QColor::fromRgba64(0, 0, 0, 0));
        rgba64.setPixelColor(2, 0, QColor::fromRgba64(0, 0, 0, 0x8000));
        const QString rgbaPath = writeImage(QStringLiteral("rgba64.png"), rgba64, "png");
        QCOMPARE(QImageReader(rgbaPath).read().format(), QImage::Format_RGBA64);

        QString error;
        const QImage g = loadPhoto(grayPath, &error);
        QVERIFY2(!g.isNull(), qPrintable(error));
        QCOMPARE(g.format(), QImage::Format_RGB32);
        for (int x = 0; x < 8; ++x) {
            const int v = x * 0x2000 / 257;
            QVERIFY2(near(g.pixel(x, 2), qRgb(v, v, v), 1), qPrintable(rgb(g.pixel(x, 2))));
        }
        const QImage c = loadPhoto(rgbaPath, &error);
        QVERIFY2(!c.isNull(), qPrintable(error));
        QCOMPARE(c.format(), QImage::Format_RGB32);
        QVERIFY2(near(c.pixel(0, 0), qRgb(255, 128, 0), 1), qPrintable(rgb(c.pixel(0, 0))));
        QVERIFY2(near(c.pixel(1, 0), qRgb(255, 255, 255), 1), qPrintable(rgb(c.pixel(1, 0))));
        QVERIFY2(near(c.pixel(2, 0), qRgb(127, 127, 127), 1), qPrintable(rgb(c.pixel(2, 0))));
    }

    void exifOrientationIsApplied()
    {
        const QByteArray plain = encode(leftRedRightBlue(), "jpg", 95);
        QVERIFY(plain.startsWith("\xff\xd8"));
        const QString plainPath = write(QStringLiteral("plain.jpg"), plain);
        // Orientation 6: the stored image must be turned 90 degrees clockwise to be upright,
        // so its left column becomes the top row.
        const QString rotatedPath
            = write(QStringLiteral("exif6.jpg"), plain.left(2) + exifOrientationSegment(6) + plain.mid(2));

        QString error;
        const QImage upright = loadPhoto(plainPath, &error);
        QVERIFY2(!upright.isNull(), qPrintable(error));
        QCOMPARE(upright.size(), QSize(40, 20));
        QVERIFY2(near(upright.pixel(5, 10), qRgb(230, 20, 20), 40), qPrintable(rgb(upright.pixel(5, 10))));
        QVERIFY2(near(upright.pixel(35, 10), qRgb(20, 20, 230), 40), qPrintable(rgb(upright.pixel(35, 10))));

        const QImage rotated = loadPhoto(rotatedPath, &error);
        QVERIFY2(!rotated.isNull(), qPrintable(error));
        QCOMPARE(rotated.format(), QImage::Format_RGB32);
        QCOMPARE(rotated.size(), QSize(20, 40));
        QVERIFY2(near(rotated.pixel(10, 5), qRgb(230, 20, 20), 40), qPrintable(rgb(rotated.pixel(10, 5))));
        QVERIFY2(near(rotated.pixel(10, 35), qRgb(20, 20, 230), 40), qPrintable(rgb(rotated.pixel(10, 35))));
    }

    void colourProfileIsConvertedToSrgb()
    {
        // A Display P3 photo (as phones take them): the same numbers mean more saturated colours.
        QImage p3(2, 1, QImage::Format_RGB32);
        p3.setPixel(0, 0, qRgb(200, 100, 50));
        p3.setPixel(1, 0, qRgb(40, 160, 90));
        p3.setColorSpace(QColorSpace(QColorSpace::DisplayP3));
        const QString path = writeImage(QStringLiteral("p3.png"), p3, "png");
        QCOMPARE(QImageReader(path).read().colorSpace(), QColorSpace(QColorSpace::DisplayP3));
        const QImage expected = p3.convertedToColorSpace(QColorSpace(QColorSpace::SRgb));

        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.colorSpace(), QColorSpace(QColorSpace::SRgb));
        for (int x = 0; x < 2; ++x) {
            QVERIFY2(!near(image.pixel(x, 0), p3.pixel(x, 0), 3), qPrintable(rgb(image.pixel(x, 0))));
            QVERIFY2(near(image.pixel(x, 0), expected.pixel(x, 0), 1), qPrintable(rgb(image.pixel(x, 0))));
        }
    }

    void contentDecidesNotTheName()
    {
        const QString path = writeImage(QStringLiteral("really-a-png.jpg"), leftRedRightBlue(), "png");
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.pixel(5, 5), qRgb(230, 20, 20));
    }

    void dataAfterTheJpegEndIsIgnored()
    {
        // Multi-picture and motion-photo JPEGs carry more data after the end marker; stray
        // marker-like bytes there must not make the photo look truncated.
        const QByteArray jpeg = encode(detailed(64, 48), "jpg", 90);
        const QString path
            = write(QStringLiteral("trailer.jpg"), jpeg + QByteArray("\xff\xda\x00\x08trailing video data", 24));
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.size(), QSize(64, 48));
    }

    void badFiles_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QStringList>("expected");

        const QByteArray jpeg = encode(detailed(400, 300), "jpg", 90);
        const QByteArray png = encode(detailed(400, 300), "png");
        // Cut inside the entropy-coded data: libjpeg would pad the rest with grey.
        QTest::newRow("truncated jpeg") << QStringLiteral("truncated.jpg") << jpeg.left(jpeg.size() / 2)
                                        << QStringList {QStringLiteral("the JPEG image is truncated")};
        QTest::newRow("jpeg cut in its header") << QStringLiteral("header.jpg") << jpeg.left(300)
                                                << QStringList {QStringLiteral("the JPEG image is truncated")};
        QTest::newRow("truncated png") << QStringLiteral("truncated.png") << png.left(png.size() / 2)
                                       << QStringList {QStringLiteral("the PNG image is corrupt or truncated")};
        // Found by fuzz_image: a text chunk claiming 2 GB in a file of a few hundred bytes made
        // libpng take that much memory (1.9 GB, 3 s).
        QByteArray lying = png.left(33); // the signature and the header chunk
        lying += QByteArray("\x7f\x00\x00\x00tEXtComment\0hello", 21) + png.mid(33);
        QTest::newRow("png chunk claiming 2 GB")
            << QStringLiteral("lying.png") << lying
            << QStringList {QStringLiteral("the PNG image is corrupt or truncated"),
                   QStringLiteral("its tEXt chunk claims 2130706432 bytes")};
        QTest::newRow("text named .jpg") << QStringLiteral("notes.jpg")
                                         << QByteArray("Dear diary,\nthis is not a photo.\n")
                                         << QStringList {QStringLiteral("text, not an image"),
                                                QStringLiteral("Dear diary, this is not")};
        QTest::newRow("pdf") << QStringLiteral("scan.png") << QByteArray("%PDF-1.7\n%\xe2\xe3\xcf\xd3\n1 0 obj\n")
                             << QStringList {QStringLiteral("a PDF document, not an image")};
        QTest::newRow("binary noise") << QStringLiteral("noise.jpg")
                                      << QByteArray("\x00\x01\x02\x03\xfe\xfd\x10\x11\x12", 9)
                                      << QStringList {
                                             QStringLiteral("unrecognised data starting with 00 01 02 03 fe fd 10 11")};
        QTest::newRow("empty") << QStringLiteral("empty.jpg") << QByteArray()
                               << QStringList {QStringLiteral("the file is empty")};
        QTest::newRow("png claiming 20000x20000")
            << QStringLiteral("huge.png") << pngClaiming(20000, 20000)
            << QStringList {QStringLiteral("too large: 20000 × 20000 pixels (400 megapixels)"),
                   QStringLiteral("the limit is 100 megapixels")};
        QByteArray hugeJpeg = jpeg;
        const qsizetype sof = hugeJpeg.indexOf("\xff\xc0");
        QVERIFY(sof > 0);
        hugeJpeg[sof + 5] = char(0x4e); // height 20000
        hugeJpeg[sof + 6] = char(0x20);
        hugeJpeg[sof + 7] = char(0x4e); // width 20000
        hugeJpeg[sof + 8] = char(0x20);
        QTest::newRow("jpeg claiming 20000x20000") << QStringLiteral("huge.jpg") << hugeJpeg
                                                   << QStringList {QStringLiteral("too large: 20000 × 20000 pixels")};
    }

    void badFiles()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(QStringList, expected);
        const QString path = write(name, bytes);
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY(image.isNull());
        QVERIFY2(error.startsWith(path + QStringLiteral(": ")), qPrintable(error));
        for (const QString &e : expected)
            QVERIFY2(error.contains(e), qPrintable(error));
    }

    void everyCutOfAJpegIsRefused()
    {
        const QByteArray jpeg = encode(detailed(120, 90), "jpg", 90);
        QVERIFY(jpeg.endsWith("\xff\xd9"));
        for (qsizetype n = 1; n < jpeg.size() - 1; n += 37) {
            const QString path = write(QStringLiteral("cut%1.jpg").arg(n), jpeg.left(n));
            QString error;
            QVERIFY2(loadPhoto(path, &error).isNull(), qPrintable(QString::number(n)));
            QVERIFY2(error.startsWith(path + QStringLiteral(": ")), qPrintable(error));
        }
        QString error;
        QVERIFY2(!loadPhoto(write(QStringLiteral("whole.jpg"), jpeg), &error).isNull(), qPrintable(error));
    }

    void everyCutOfAPngIsRefused()
    {
        const QByteArray png = encode(detailed(120, 90), "png");
        for (qsizetype n = 1; n < png.size() - 12; n += 53) { // the last 12 bytes are IEND
            const QString path = write(QStringLiteral("cut%1.png").arg(n), png.left(n));
            QString error;
            QVERIFY2(loadPhoto(path, &error).isNull(), qPrintable(QString::number(n)));
            QVERIFY2(error.startsWith(path + QStringLiteral(": ")), qPrintable(error));
        }
    }

    void missingFileAndFolder()
    {
        const QString path = m_dir.filePath(QStringLiteral("nowhere.jpg"));
        QString error;
        QVERIFY(loadPhoto(path, &error).isNull());
        QCOMPARE(error, path + QStringLiteral(": no such file"));
        QVERIFY(loadPhoto(m_dir.path(), &error).isNull());
        QCOMPARE(error, m_dir.path() + QStringLiteral(": is a folder, not an image"));
    }

    void publicDomainPortrait()
    {
        const QString path = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
        if (!QFile::exists(path))
            QSKIP("grace_hopper.jpg is absent (package python-matplotlib-data)");
        QString error;
        const QImage image = loadPhoto(path, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(image.format(), QImage::Format_RGB32);
        QCOMPARE(image.size(), QImageReader(path).size());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestImageIo)
#include "tst_imageio.moc"
