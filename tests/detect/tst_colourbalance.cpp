#include "detect/colourbalance.h"
#include "detect/detector.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "render/style.h"
#include "testmain.h"

#include <QFileInfo>
#include <QTest>

using namespace toonface;
using testing::DrawnFaceOptions;

namespace {

// The stated tolerance: a cast photo's skin is drawn within this hue of the uncast photo's.
constexpr double kHueTolerance = 6.0;

QImage withCast(const QImage &photo, double r, double g, double b)
{
    QImage out = photo.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < out.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            const QRgb c = line[x];
            line[x] = qRgb(
                std::min(255, int(qRed(c) * r)), std::min(255, int(qGreen(c) * g)), std::min(255, int(qBlue(c) * b)));
        }
    }
    return out;
}

double hueDistance(const QColor &a, const QColor &b)
{
    const double d = std::abs(a.hsvHueF() - b.hsvHueF()) * 360.0;
    return std::min(d, 360.0 - d);
}

QColor skinOf(const QImage &photo, const FaceModel &face)
{
    Style s = Style::preset(QStringLiteral("normal"));
    sampleColours(photo, face, &s);
    return s.components.value(QStringLiteral("face")).fill;
}

} // namespace

class TestColourBalance : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A photo under a coloured light gives the skin of the same photo under white light (the
    // Debian portraits, cast by channel gains as tungsten, shade, fluorescent and magenta light).
    void castIsTakenOut_data()
    {
        QTest::addColumn<QString>("photo");
        QTest::addColumn<double>("r");
        QTest::addColumn<double>("g");
        QTest::addColumn<double>("b");
        const QString photos[] = {QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg"),
            QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png")};
        for (const QString &photo : photos) {
            const QString name = QFileInfo(photo).baseName();
            auto row = [&](const char *cast, double r, double g, double b) {
                QTest::newRow(qPrintable(name + QLatin1Char(' ') + QLatin1StringView(cast))) << photo << r << g << b;
            };
            row("warm (tungsten)", 1.0, 0.85, 0.6);
            row("cold (shade)", 0.75, 0.9, 1.0);
            row("green (fluorescent)", 0.8, 1.0, 0.8);
            row("magenta", 1.0, 0.8, 1.0);
        }
    }

    void castIsTakenOut()
    {
        QFETCH(QString, photo);
        QFETCH(double, r);
        QFETCH(double, g);
        QFETCH(double, b);
        const QImage plain(photo);
        if (plain.isNull())
            QSKIP(qPrintable(photo + QStringLiteral(" is not installed")));
        const DetectionResult found = detectFace(plain);
        if (found.status == DetectStatus::ModelMissing)
            QSKIP("the landmark model is not installed");
        QCOMPARE(found.status, DetectStatus::Ok);
        const QColor uncast = skinOf(plain, found.face);
        const QColor cast = skinOf(withCast(plain, r, g, b), found.face);
        // The cast is real: the raw skin moves by more than the tolerance.
        const QColor raw(std::min(255, int(uncast.red() * r)), std::min(255, int(uncast.green() * g)),
            std::min(255, int(uncast.blue() * b)));
        QVERIFY(
            hueDistance(raw, uncast) > kHueTolerance || std::abs(raw.hsvSaturationF() - uncast.hsvSaturationF()) > 0.1);
        QVERIFY2(hueDistance(cast, uncast) < kHueTolerance, qPrintable(cast.name() + QLatin1Char('/') + uncast.name()));
        QVERIFY2(std::abs(cast.hsvSaturationF() - uncast.hsvSaturationF()) < 0.12,
            qPrintable(cast.name() + QLatin1Char('/') + uncast.name()));
    }

    // A face on flat colour fields (a backdrop, a drawing) keeps its colours: the fields are the
    // scene's colours, not a cast, so nothing is corrected.
    void flatColoursAreKept()
    {
        const FaceModel face = testing::drawnFaceModel();
        for (const QColor &skin : {QColor(236, 200, 178), QColor(180, 125, 95), QColor(100, 66, 48)}) {
            DrawnFaceOptions o;
            o.skin = skin;
            const QImage photo = testing::drawnFace(o, face);
            const ColourBalance balance = ColourBalance::measure(photo);
            for (double gain : balance.gain)
                QVERIFY2(std::abs(gain - 1.0) < 0.02, qPrintable(QString::number(gain)));
            const QColor drawn = skinOf(photo, face);
            QVERIFY2(hueDistance(drawn, skin) < 3 && std::abs(drawn.value() - skin.value()) < 8,
                qPrintable(drawn.name() + QLatin1Char('/') + skin.name()));
        }
    }

    // A greyscale photo gets natural colours from its tones: warm skin as light as the photo's,
    // grey hair kept grey.
    void greyscalePhoto()
    {
        const FaceModel face = testing::drawnFaceModel();
        QColor previous;
        for (const QColor &skin : {QColor(240, 210, 190), QColor(180, 125, 95), QColor(95, 62, 45)}) {
            DrawnFaceOptions o;
            o.skin = skin;
            o.hair = QColor(236, 236, 232); // white hair
            const QImage grey = testing::drawnFace(o, face).convertToFormat(QImage::Format_Grayscale8);
            QVERIFY(ColourBalance::measure(grey).greyscale);
            Style s = Style::preset(QStringLiteral("normal"));
            sampleColours(grey, face, &s);
            const QColor drawn = s.components.value(QStringLiteral("face")).fill;
            const double hue = drawn.hsvHueF() * 360.0;
            QVERIFY2(hue > 10 && hue < 40 && drawn.hsvSaturationF() > 0.15, qPrintable(drawn.name()));
            QVERIFY(drawn != Style::preset(QStringLiteral("normal")).components.value(QStringLiteral("face")).fill);
            if (previous.isValid())
                QVERIFY(drawn.lightness() < previous.lightness()); // darker tones, darker skin
            previous = drawn;
            const QColor hair = s.components.value(QStringLiteral("hair")).fill;
            QVERIFY2(hair.hsvSaturationF() < 0.1 && hair.value() > 150, qPrintable(hair.name()));
        }
    }

    void colourPhotoIsNotGreyscale()
    {
        QVERIFY(!ColourBalance::measure(testing::drawnFace({})).greyscale);
        QVERIFY(ColourBalance().isIdentity());
        QCOMPARE(ColourBalance::measure(QImage()).greyscale, false);
    }

    void gainsAreBounded()
    {
        QImage red(64, 64, QImage::Format_RGB32);
        red.fill(QColor(200, 40, 40));
        for (int i = 0; i < 64; i += 8)
            red.setPixel(i, i, qRgb(250, 60, 60));
        const ColourBalance b = ColourBalance::measure(red);
        for (double g : b.gain) {
            QVERIFY(g <= ColourBalance::kMaxGain * 1.01);
            QVERIFY(g >= 1.0 / ColourBalance::kMaxGain / 1.01);
        }
    }
};

TOONFACE_TEST_MAIN(TestColourBalance)
#include "tst_colourbalance.moc"
