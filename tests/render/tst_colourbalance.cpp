#include "detect/detector.h"
#include "drawnface.h"
#include "render/colourbalance.h"
#include "render/style.h"

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
    s.sampleColours(photo, face);
    return s.components.value(QStringLiteral("face")).fill;
}

} // namespace

class TestColourBalance : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void castIsTakenOut_data()
    {
        QTest::addColumn<double>("r");
        QTest::addColumn<double>("g");
        QTest::addColumn<double>("b");
        QTest::newRow("warm (tungsten)") << 1.0 << 0.85 << 0.6;
        QTest::newRow("cold (shade)") << 0.75 << 0.9 << 1.0;
        QTest::newRow("green (fluorescent)") << 0.8 << 1.0 << 0.8;
        QTest::newRow("magenta") << 1.0 << 0.75 << 1.0;
    }

    void castIsTakenOut()
    {
        QFETCH(double, r);
        QFETCH(double, g);
        QFETCH(double, b);
        const FaceModel face = testing::drawnFaceModel();
        for (const QColor &skin : {QColor(236, 200, 178), QColor(180, 125, 95), QColor(100, 66, 48)}) {
            DrawnFaceOptions o;
            o.skin = skin;
            const QImage plain = testing::drawnFace(o, face);
            const QImage cast = withCast(plain, r, g, b);
            const QColor uncastSkin = skinOf(plain, face);
            const QColor castSkin = skinOf(cast, face);
            // The cast is real (raw skin hues differ) and taken out (drawn hues agree).
            const QColor rawCast(std::min(255, int(skin.red() * r)), std::min(255, int(skin.green() * g)),
                std::min(255, int(skin.blue() * b)));
            QVERIFY(hueDistance(rawCast, skin) > 2 * kHueTolerance
                || std::abs(rawCast.hsvSaturationF() - skin.hsvSaturationF()) > 0.1);
            QVERIFY2(hueDistance(castSkin, uncastSkin) < kHueTolerance,
                qPrintable(QStringLiteral("%1 vs %2").arg(castSkin.name(), uncastSkin.name())));
            QVERIFY2(std::abs(castSkin.hsvSaturationF() - uncastSkin.hsvSaturationF()) < 0.1,
                qPrintable(QStringLiteral("%1 vs %2").arg(castSkin.name(), uncastSkin.name())));
        }
    }

    void realPhotoCast()
    {
        const QImage photo(QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg"));
        if (photo.isNull())
            QSKIP("grace_hopper.jpg is not installed (python3-matplotlib-data)");
        const DetectionResult r = detectFace(photo);
        if (r.status == DetectStatus::ModelMissing)
            QSKIP("the landmark model is not installed");
        QCOMPARE(r.status, DetectStatus::Ok);
        const QColor uncast = skinOf(photo, r.face);
        for (const auto &cast : {std::array {1.0, 0.85, 0.6}, std::array {0.75, 0.9, 1.0}}) {
            const QColor c = skinOf(withCast(photo, cast[0], cast[1], cast[2]), r.face);
            QVERIFY2(hueDistance(c, uncast) < kHueTolerance, qPrintable(c.name() + QLatin1Char('/') + uncast.name()));
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
            s.sampleColours(grey, face);
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

QTEST_MAIN(TestColourBalance)
#include "tst_colourbalance.moc"
