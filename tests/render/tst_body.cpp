// Neck and shoulders (render/svgbody.h): drawn behind the head in the clothes' colour sampled from
// the photo, attached to the head when it turns and nods, off when hidden or when the photo has
// no room under the chin.

#include "detect/photocolours.h"
#include "drawnface.h"
#include "testmain.h"
#include "xmltree.h"

#include "face/fapu.h"
#include "face/pose.h"
#include "render/style.h"
#include "render/svgface.h"

#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

using test::findId;
using test::Node;
using test::parseXml;

FaceModel testFace()
{
    return averageFace(QRectF(106, 100, 300, 330), QSize(512, 640));
}

int indexOfId(const Node &root, const char *id)
{
    for (qsizetype i = 0; i < root.children.size(); ++i) {
        if (root.children[i].attribute(QStringLiteral("id")) == QLatin1StringView(id))
            return int(i);
    }
    return -1;
}

double colourDistance(QColor a, QColor b)
{
    return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
}

} // namespace

class TestBody : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void drawnBehindTheHead()
    {
        Style style = Style::preset(QStringLiteral("normal"));
        style.components[QStringLiteral("body")].fill = QColor(20, 120, 60);
        const FaceModel face = testFace();
        Node root;
        QString why;
        QVERIFY2(parseXml(SvgFace(face, style).svg(), &root, &why), qPrintable(why));
        const int body = indexOfId(root, "body");
        QVERIFY(body >= 0);
        QVERIFY(body < indexOfId(root, "head"));
        const Node *shoulders = findId(root, QStringLiteral("shoulders"));
        const Node *neck = findId(root, QStringLiteral("neck"));
        QVERIFY(shoulders && neck);
        QCOMPARE(shoulders->attribute(QStringLiteral("fill")), QStringLiteral("#14783c"));
        QCOMPARE(neck->attribute(QStringLiteral("fill")), style.components.value(QStringLiteral("face")).fill.name());

        // Under the chin the drawing shows the neck, and lower down the clothes.
        const QImage image = rasterizeSvg(SvgFace(face, style).svg(), face.imageSize());
        const QPointF chin = face.point("2.1");
        const double es0 = face.fapu().es0;
        QVERIFY(colourDistance(image.pixelColor((chin + QPointF(0, 0.2 * es0)).toPoint()),
                    style.components.value(QStringLiteral("face")).fill)
            < 3);
        QVERIFY(colourDistance(image.pixelColor((chin + QPointF(0.9 * es0, 1.6 * es0)).toPoint()), QColor(20, 120, 60))
            < 3);

        // Hidden: neither neck nor shoulders.
        style.components[QStringLiteral("body")].visible = false;
        QVERIFY2(parseXml(SvgFace(face, style).svg(), &root, &why), qPrintable(why));
        QCOMPARE(indexOfId(root, "body"), -1);
        QVERIFY(!findId(root, QStringLiteral("neck")));
    }

    // When the head rolls or nods, no background shows between the jaw and the neck, and the
    // shoulders stay where they are.
    void neckStaysAttached_data()
    {
        QTest::addColumn<double>("rotation");
        QTest::addColumn<QPointF>("move"); // in ES0
        QTest::addColumn<double>("jawDrop"); // in ES0
        QTest::newRow("roll left") << -12.0 << QPointF() << 0.0;
        QTest::newRow("roll right") << 12.0 << QPointF() << 0.0;
        QTest::newRow("nod up") << 0.0 << QPointF(0, -0.08) << 0.0;
        QTest::newRow("nod down") << 0.0 << QPointF(0, 0.08) << 0.0;
        QTest::newRow("turned and shouting") << 10.0 << QPointF(0.05, -0.05) << 0.4;
    }

    void neckStaysAttached()
    {
        QFETCH(double, rotation);
        QFETCH(QPointF, move);
        QFETCH(double, jawDrop);
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        Style style = Style::preset(QStringLiteral("normal"));
        const QColor skin(240, 200, 170);
        for (const char *key : {"face", "jaw", "ears"})
            style.components[QLatin1StringView(key)].fill = skin;
        style.components[QStringLiteral("body")].fill = QColor(20, 60, 160);
        Pose pose;
        pose.head.rotationDeg = rotation;
        pose.head.translation = move * es0;
        pose.offset[pt::idx("8.2")] = QPointF(0, jawDrop * es0);
        const SvgFace svg(face, style);
        const QImage image = rasterizeSvg(svg.svg(pose), face.imageSize(), Qt::white);
        // Columns across the neck, from the middle of the face down to the neckline: never the
        // white background.
        const QPointF chin = face.point("2.1");
        const double width = face.point("2.13").x() - face.point("2.14").x();
        for (double share : {-0.25, -0.12, 0.0, 0.12, 0.25}) {
            const int x = int(std::lround(chin.x() + share * width));
            for (int y = int(face.point("8.2").y()); y < int(chin.y() + 0.5 * es0); ++y) {
                const QColor c = image.pixelColor(x, y);
                QVERIFY2(
                    colourDistance(c, Qt::white) > 40, qPrintable(QStringLiteral("background at %1,%2").arg(x).arg(y)));
            }
        }
        // The shoulders do not move with the head.
        const QPoint shoulder = (chin + QPointF(0.9 * width, 1.6 * es0)).toPoint();
        QVERIFY(colourDistance(image.pixelColor(shoulder), QColor(20, 60, 160)) < 3);
    }

    // The clothes' colour comes from the photo under the chin; a photo cut off at the chin has no
    // room for a body, and none is drawn.
    void sampledFromThePhoto()
    {
        const FaceModel face = testing::drawnFaceModel();
        QImage photo = testing::drawnFace({}, face);
        const QColor shirt(150, 40, 50);
        {
            QPainter p(&photo);
            const QPointF chin = face.point("2.1");
            p.fillRect(QRectF(0, chin.y() + 0.5 * face.fapu().es0, photo.width(), photo.height()), shirt);
        }
        Style style = Style::preset(QStringLiteral("normal"));
        sampleColours(photo, face, &style);
        const ComponentStyle body = style.components.value(QStringLiteral("body"));
        QVERIFY(body.visible);
        QVERIFY2(colourDistance(body.fill, shirt) < 40, qPrintable(body.fill.name()));
        // The expression lines are a shade of the sampled skin, half as light or less.
        const QColor skin = style.components.value(QStringLiteral("face")).fill;
        const QColor crease = style.components.value(QStringLiteral("creases")).fill;
        QVERIFY(crease.lightness() < skin.lightness() * 0.6);
        QVERIFY(std::abs(crease.hslHue() - skin.hslHue()) < 12);

        const int cut = int(face.point("2.1").y() + 0.2 * face.fapu().es0);
        Style cropped = Style::preset(QStringLiteral("normal"));
        sampleColours(photo.copy(0, 0, photo.width(), cut), face, &cropped);
        QVERIFY(!cropped.components.value(QStringLiteral("body")).visible);
        QVERIFY(!SvgFace(face, cropped).svg().contains("id=\"neck\""));
    }
};

TOONFACE_TEST_MAIN(TestBody)
#include "tst_body.moc"
