#include "svgfacefixture.h"
#include "testmain.h"

#include <QTest>

using namespace toonface;
using namespace toonface::svgfacetest;

namespace {

// A green square as a user's layer.
const QByteArray kSquare = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-50 -50 100 100\">"
                           "<rect id=\"sq\" x=\"-50\" y=\"-50\" width=\"100\" height=\"100\" fill=\"#00ff00\"/></svg>";

// Everything a drawing may hold: the worn things and style layers in each of the four places.
Style fullStyle(const QString &preset)
{
    Style style = Style::preset(preset);
    style.appearance.glasses = GlassesShape::Round;
    style.appearance.moustache = true;
    style.appearance.beard = true;
    style.appearance.hat = true;
    for (const bool front : {false, true}) {
        for (const bool follows : {false, true}) {
            StyleLayer l;
            l.name = QStringLiteral("square.svg");
            l.svg = kSquare;
            l.offset = QPointF(front ? 1.5 : -1.5, follows ? -1.0 : 1.2);
            l.width = 0.6;
            l.front = front;
            l.followsHead = follows;
            style.layers.append(l);
        }
    }
    return style;
}

} // namespace

// SvgFace::svgPasses(): the under pass rasterized and the over pass drawn on it are the whole
// drawing's pixels, which video export relies on when it reuses the under pass.
class TestSvgPasses : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void passesDrawTheWhole_data()
    {
        QTest::addColumn<QString>("style");
        QTest::addColumn<QString>("pose");
        const FaceModel face = testFace();
        for (const QString &style : {QStringLiteral("normal"), QStringLiteral("cute")}) {
            for (const QString &pose : namedPoses(face).keys())
                QTest::addRow("%s, %s", qPrintable(style), qPrintable(pose)) << style << pose;
        }
    }

    void passesDrawTheWhole()
    {
        QFETCH(QString, style);
        QFETCH(QString, pose);
        const FaceModel face = testFace();
        SvgFace svgFace(face, fullStyle(style));
        svgFace.addLayer(kSquare);
        const Pose p = namedPoses(face).value(pose);
        const QByteArray whole = svgFace.svg(p);
        const SvgFace::Passes passes = svgFace.svgPasses(p);
        for (const QColor &background : {QColor(Qt::white), QColor(Qt::transparent)}) {
            const QSize size(160, 200);
            QImage layered = rasterizeSvg(passes.under, size, background);
            QVERIFY(drawSvg(passes.over, &layered));
            QCOMPARE(layered, rasterizeSvg(whole, size, background));
        }
    }

    // Each element is in exactly one pass: the head's static layer under, its dynamic layer over.
    void eachPartInOnePass()
    {
        const FaceModel face = testFace();
        SvgFace svgFace(face, fullStyle(QStringLiteral("normal")));
        svgFace.addLayer(kSquare);
        const Pose p = namedPoses(face).value(QStringLiteral("combined"));
        const SvgFace::Passes passes = svgFace.svgPasses(p);
        const QStringList whole = idsUnder(parsed(svgFace.svg(p)));
        const QStringList under = idsUnder(parsed(passes.under));
        const QStringList over = idsUnder(parsed(passes.over));
        QVERIFY(under.contains(QStringLiteral("hair")) && under.contains(QStringLiteral("hat")));
        QVERIFY(under.contains(QStringLiteral("shoulders")) && !over.contains(QStringLiteral("hair")));
        QVERIFY(over.contains(QStringLiteral("mouth-upper-lip")) && over.contains(QStringLiteral("glasses")));
        QVERIFY(!under.contains(QStringLiteral("glasses")) && !under.contains(QStringLiteral("layer-1")));
        QCOMPARE(under.count(QStringLiteral("head")), 1);
        QCOMPARE(over.count(QStringLiteral("head")), 1);
        QStringList both = under + over;
        both.removeOne(QStringLiteral("head"));
        both.sort();
        QStringList expected = whole;
        expected.sort();
        QCOMPARE(both, expected);
    }

    // What does not parse, or no image, is refused and leaves the image as it was.
    void brokenOverPassIsAnError()
    {
        QImage image(20, 20, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        const QImage before = image;
        QVERIFY(!drawSvg("<svg", &image));
        QCOMPARE(image, before);
        QImage null;
        QVERIFY(!drawSvg(SvgFace(testFace(), Style()).svg(), &null));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSvgPasses)
#include "tst_svgpasses.moc"
