// The user's SVG layers of a style (Style::layers): placed in face coordinates in front of or
// behind the head, drawn the same in the preview's renderer, the SMIL/HTML exports and the
// raster frames (MP4, GIF), and made inert and self-contained (render/svglayer.h).

#include "testmain.h"
#include "xmltree.h"

#include "anim/timeline.h"
#include "export/framerenderer.h"
#include "export/htmlplayer.h"
#include "export/smilexport.h"
#include "face/averageface.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "render/style.h"
#include "render/svgface.h"
#include "render/svglayer.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QTransform>

#include <cmath>

using namespace toonface;

namespace {

using test::findId;
using test::Node;
using test::parseXml;

// A green square 100 units wide: placed 1 ES0 wide, it covers a square of 1 ES0 about its centre.
const QByteArray kSquare = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-50 -50 100 100\">"
                           "<rect id=\"sq\" x=\"-50\" y=\"-50\" width=\"100\" height=\"100\" fill=\"#00ff00\"/></svg>";

FaceModel testFace()
{
    return averageFace(QRectF(106, 100, 300, 330), QSize(512, 640));
}

Node parsed(const QByteArray &svg)
{
    Node root;
    QString why;
    if (!parseXml(svg, &root, &why))
        qWarning("%s", qPrintable(why));
    return root;
}

int indexOfId(const Node &root, const QString &id)
{
    for (qsizetype i = 0; i < root.children.size(); ++i) {
        if (root.children[i].attribute(QStringLiteral("id")) == id)
            return int(i);
    }
    return -1;
}

StyleLayer square(QPointF offset, bool front)
{
    StyleLayer l;
    l.name = QStringLiteral("square.svg");
    l.svg = kSquare;
    l.offset = offset;
    l.width = 1.0;
    l.front = front;
    return l;
}

QPointF faceCentre(const FaceModel &face)
{
    return face.bounds(PointGroup::Contour).center();
}

bool green(QColor c)
{
    return c.green() > 230 && c.red() < 25 && c.blue() < 25;
}

} // namespace

class TestStyleLayers : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void placedInFaceCoordinates()
    {
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        Style style = Style::preset(QStringLiteral("normal"));
        // In front on the forehead's right, behind well below the right shoulder's top.
        style.layers = {square(QPointF(0.3, -0.6), true), square(QPointF(1.6, 2.4), false)};
        const QByteArray svg = SvgFace(face, style).svg();
        const Node root = parsed(svg);
        const int front = indexOfId(root, QStringLiteral("style-layer-1"));
        const int behind = indexOfId(root, QStringLiteral("style-layer-2"));
        const int head = indexOfId(root, QStringLiteral("head"));
        QVERIFY(front > head);
        QVERIFY(behind < head && behind > indexOfId(root, QStringLiteral("body")));
        // Their ids are their own.
        QVERIFY(findId(root, QStringLiteral("style-layer-1-sq")));
        QVERIFY(findId(root, QStringLiteral("style-layer-2-sq")));

        const QImage image = rasterizeSvg(svg, face.imageSize());
        const QPointF c = faceCentre(face);
        const QPointF onFront = c + QPointF(0.3, -0.6) * es0;
        QVERIFY(green(image.pixelColor(onFront.toPoint())));
        QVERIFY(green(image.pixelColor((onFront + QPointF(0.45, 0.45) * es0).toPoint())));
        QVERIFY(!green(image.pixelColor((onFront + QPointF(0.56, 0) * es0).toPoint()))); // 1 ES0 wide
        QVERIFY(green(image.pixelColor((c + QPointF(1.6, 2.4) * es0).toPoint())));

        // Behind: the face hides it.
        style.layers = {square(QPointF(0.3, -0.6), false)};
        QVERIFY(!green(rasterizeSvg(SvgFace(face, style).svg(), face.imageSize()).pixelColor(onFront.toPoint())));
        // Hidden: not drawn at all.
        style.layers = {square(QPointF(0.3, -0.6), true)};
        style.layers[0].visible = false;
        QVERIFY(!SvgFace(face, style).svg().contains("style-layer-1"));
    }

    // A layer that follows the head is drawn in the head's group: it moves with the head's
    // translation and turn, in the preview's drawing and the SMIL export (whose head animation is
    // on that group); one that does not stays where it was.
    void followsTheHead()
    {
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        Style style = Style::preset(QStringLiteral("normal"));
        style.layers = {square(QPointF(0.3, -0.6), true), square(QPointF(-1.4, 1.6), true)};
        style.layers[0].followsHead = true;
        const Node root = parsed(SvgFace(face, style).svg());
        const Node *head = findId(root, QStringLiteral("head"));
        QVERIFY(head);
        QVERIFY(findId(*head, QStringLiteral("style-layer-1")));
        QVERIFY(!findId(*head, QStringLiteral("style-layer-2")));
        QVERIFY(indexOfId(root, QStringLiteral("style-layer-2")) > indexOfId(root, QStringLiteral("head")));
        // In front of the face's parts: the last of the head's group.
        QCOMPARE(head->children.last().attribute(QStringLiteral("id")), QStringLiteral("style-layer-1"));

        // The head moved 0.8 ES0 right and turned: the first square moved with it, the second did not.
        Pose pose;
        pose.head.translation = QPointF(0.8 * es0, 0);
        pose.head.rotationDeg = 10;
        const QImage moved = rasterizeSvg(SvgFace(face, style).svg(pose), face.imageSize());
        const QPointF c = faceCentre(face);
        const QPointF was = c + QPointF(0.3, -0.6) * es0;
        QVERIFY(!green(moved.pixelColor((was - QPointF(0.4, 0) * es0).toPoint())));
        // Where the head's transform takes the square's centre.
        QTransform t;
        t.translate(c.x() + 0.8 * es0, c.y());
        t.rotate(10);
        t.translate(-c.x(), -c.y());
        QVERIFY(green(moved.pixelColor(t.map(was).toPoint())));
        QVERIFY(green(moved.pixelColor((c + QPointF(-1.4, 1.6) * es0).toPoint())));

        // The SMIL export animates the head's group: the layer is in it.
        QString error;
        AnimationExportOptions options;
        Timeline timeline;
        const QByteArray smil = exportSmilSvg(face, style, timeline, MouthShapeSet(), options, &error);
        const Node exported = parsed(smil);
        const Node *exportedHead = findId(exported, QStringLiteral("head"));
        QVERIFY2(exportedHead && findId(*exportedHead, QStringLiteral("style-layer-1-sq")), qPrintable(error));
    }

    // Anything that could run or fetch is left out; references inside the layer keep working.
    void sanitised()
    {
        const QByteArray content
            = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
              "width=\"30px\" height=\"20\" onload=\"alert(1)\">"
              "<style>@import url(http://evil.example/x.css);</style>"
              "<style>.k{fill:url(#grad)}</style>"
              "<defs><linearGradient id=\"grad\"/></defs>"
              "<image xlink:href=\"http://evil.example/track.png\" width=\"5\" height=\"5\"/>"
              "<image href=\"file:///etc/passwd\" width=\"5\" height=\"5\"/>"
              "<image href=\"data:image/png;base64,iVBORw0KGgo=\" width=\"5\" height=\"5\"/>"
              "<use xlink:href=\"other.svg#part\"/>"
              "<rect id=\"r\" fill=\"url(#grad)\" style=\"fill:url('https://evil.example/a')\" "
              "width=\"3\" height=\"3\"/>"
              "<use xlink:href=\"#r\" x=\"4\"/>"
              "<a><set attributeName=\"xlink:href\" to=\"https://evil.example/b\"/></a>"
              "<object data=\"x.html\"/><embed src=\"y.swf\"/>"
              "</svg>";
        LayerDrawing drawing;
        QString error;
        QVERIFY2(readLayerSvg(content, QStringLiteral("p-"), &drawing, &error), qPrintable(error));
        const QByteArray f = drawing.fragment;
        for (const char *gone : {"evil.example", "@import", "file:", "other.svg", "onload", "<object", "<embed"})
            QVERIFY2(!f.contains(gone), gone);
        QVERIFY(f.contains("data:image/png")); // an embedded picture is kept
        QVERIFY(f.contains("id=\"p-r\""));
        QVERIFY(f.contains("fill=\"url(#p-grad)\""));
        QVERIFY(f.contains("href=\"#p-r\""));
        QVERIFY(f.contains(".k{fill:url(#p-grad)}"));
        QCOMPARE(drawing.viewBox, QRectF(0, 0, 30, 20));
    }

    void badFilesNamed_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("problem");
        QTest::newRow("not svg") << QByteArray("<html/>")
                                 << QStringLiteral("is not a valid SVG file: the root element");
        QTest::newRow("broken") << QByteArray("<svg><g></svg>") << QStringLiteral("is not a valid SVG file: line 1");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("is not a valid SVG file");
    }

    void badFilesNamed()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, problem);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("hat.svg"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        StyleLayer layer;
        QString error;
        QVERIFY(!loadLayerFile(path, &layer, &error));
        QVERIFY2(error.contains(path) && error.contains(problem), qPrintable(error));
        QVERIFY(!loadLayerFile(dir.filePath(QStringLiteral("missing.svg")), &layer, &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot read layer file "))
                && error.contains(QStringLiteral("missing.svg")),
            qPrintable(error));
    }

    // The same layers in every export: SMIL (both modes), HTML and the raster frames of MP4 and GIF.
    void drawnInExports()
    {
        const FaceModel face = testFace();
        Style style = Style::preset(QStringLiteral("normal"));
        style.layers = {square(QPointF(0.3, -0.6), true), square(QPointF(1.6, 2.4), false)};
        Timeline timeline;
        timeline.addEmotionClip({0.0, 0.5, Emotion::Smile, 1.0, 0.1, 0.1});
        const MouthShapeSet shapes;
        QString error;
        AnimationExportOptions options;
        for (auto mode : {AnimationExportOptions::Mode::Smil, AnimationExportOptions::Mode::Frames}) {
            options.mode = mode;
            const QByteArray smil = exportSmilSvg(face, style, timeline, shapes, options, &error);
            QVERIFY2(!smil.isEmpty(), qPrintable(error));
            for (const char *id : {"style-layer-1-sq", "style-layer-2-sq", "id=\"neck\"", "id=\"shoulders\""})
                QVERIFY2(smil.contains(id), id);
        }
        const QByteArray html = exportHtmlPlayer(face, style, timeline, shapes, {}, &error);
        QVERIFY2(html.contains("style-layer-1-sq") && html.contains("style-layer-2-sq"), qPrintable(error));

        const FrameRenderer frames(SvgFace(face, style), timeline, shapes, face.imageSize());
        const QImage frame = frames.render(0);
        const double es0 = face.fapu().es0;
        QVERIFY(green(frame.pixelColor((faceCentre(face) + QPointF(0.3, -0.6) * es0).toPoint())));
        QVERIFY(green(frame.pixelColor((faceCentre(face) + QPointF(1.6, 2.4) * es0).toPoint())));
    }
};

TOONFACE_TEST_MAIN(TestStyleLayers)
#include "tst_stylelayers.moc"
