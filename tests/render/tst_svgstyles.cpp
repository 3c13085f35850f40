#include "detect/labcolour.h"
#include "detect/photocolours.h"
#include "face/averageface.h"
#include "face/emotion.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "render/style.h"
#include "render/svgface.h"
#include "svgfacefixture.h"
#include "testmain.h"
#include "xmltree.h"

#include <QDir>
#include <QFile>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>
#include <QTransform>
#include <QXmlStreamReader>

#include <cmath>
#include <thread>

using namespace toonface;
using namespace toonface::svgfacetest;

Q_DECLARE_METATYPE(toonface::HeadPose)

// The SVG face's looks: styles and presets, variants, sampled colours and the user's own layers.
class TestSvgStyles : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stylesDifferAsSpecified()
    {
        const FaceModel face = testFace();
        const QVector<FacePart> normal = SvgFace(face, preset("normal")).parts();
        const QVector<FacePart> cute = SvgFace(face, preset("cute")).parts();
        auto radius = [](const QVector<FacePart> &parts) {
            return partById(parts, QStringLiteral("eyeball-left"))->geometry.value(QStringLiteral("r")).toDouble();
        };
        auto bounds = [](const QVector<FacePart> &parts, const char *id) {
            const FacePart *p = partById(parts, QLatin1StringView(id));
            return p ? pathPoints(p->geometry.value(QStringLiteral("d"))).boundingRect() : QRectF();
        };
        QVERIFY(radius(cute) > 1.3 * radius(normal)); // larger eyeballs
        QVERIFY(bounds(cute, "nose-bottom").width() < 0.8 * bounds(normal, "nose-bottom").width()); // smaller nose
        QVERIFY(bounds(cute, "jaw").bottom() < bounds(normal, "jaw").bottom() - 0.1 * face.fapu().jawH); // shorter jaw
        QVERIFY(bounds(cute, "eye-left").height() > bounds(normal, "eye-left").height());
        QVERIFY(partById(cute, QStringLiteral("cheek-left")));
        QVERIFY(!partById(normal, QStringLiteral("cheek-left")));
        // Rounder: the cute jaw's lower corner point sits further out from the chord 2.14-2.1.
        QVERIFY(bounds(cute, "jaw").width() >= bounds(normal, "jaw").width() - 1.0);
    }

    void eyebrowVariants()
    {
        const FaceModel face = testFace();
        Style s = preset("normal");
        s.eyebrows = EyebrowVariant::Polyline;
        const Node poly = parsed(SvgFace(face, s).svg());
        const Node *brow = findId(poly, QStringLiteral("eyebrow-left"));
        QCOMPARE(brow->name, QStringLiteral("polyline"));
        QCOMPARE(brow->attribute(QStringLiteral("fill")), QStringLiteral("none"));
        // Corner cutting at the style's depth: two interior corners of 2^(depth+1) + 1 points.
        QCOMPARE(
            numbers(brow->attribute(QStringLiteral("points"))).size(), 2 * (2 * (1 << (s.cornerCutDepth + 1)) + 3));

        s.eyebrows = EyebrowVariant::Bezier;
        const Node bez = parsed(SvgFace(face, s).svg());
        brow = findId(bez, QStringLiteral("eyebrow-left"));
        QCOMPARE(brow->name, QStringLiteral("path"));
        QCOMPARE(commandLetters(brow->attribute(QStringLiteral("d"))), QStringLiteral("MC"));
        QCOMPARE(brow->attribute(QStringLiteral("fill")), QStringLiteral("none"));

        s.eyebrows = EyebrowVariant::Thick;
        const Node thick = parsed(SvgFace(face, s).svg());
        brow = findId(thick, QStringLiteral("eyebrow-left"));
        QCOMPARE(brow->name, QStringLiteral("path"));
        QVERIFY(brow->attribute(QStringLiteral("d")).endsWith(QLatin1Char('Z')));
        QCOMPARE(brow->attribute(QStringLiteral("fill")), s.components.value(QStringLiteral("eyebrows")).fill.name());

        for (EyebrowVariant v : {EyebrowVariant::Polyline, EyebrowVariant::Bezier, EyebrowVariant::Thick}) {
            EyebrowVariant back {};
            QVERIFY(eyebrowVariantFromName(eyebrowVariantName(v), &back));
            QCOMPARE(back, v);
        }
        EyebrowVariant unused {};
        QVERIFY(!eyebrowVariantFromName(QStringLiteral("bushy"), &unused));
    }

    void noseVariants()
    {
        const FaceModel face = testFace();
        Style s = preset("normal");
        auto ids = [&](NoseVariant v) {
            s.nose = v;
            QStringList out;
            for (const FacePart &p : SvgFace(face, s).parts()) {
                if (p.styleKey == QLatin1StringView("nose"))
                    out << p.id;
            }
            return out;
        };
        QCOMPARE(ids(NoseVariant::Full), (QStringList {QStringLiteral("nose-bridge"), QStringLiteral("nose-bottom")}));
        QCOMPARE(ids(NoseVariant::Simple), (QStringList {QStringLiteral("nose-bottom")}));
        QCOMPARE(ids(NoseVariant::Tip), (QStringList {QStringLiteral("nose-tip")}));
        for (NoseVariant v : {NoseVariant::Full, NoseVariant::Simple, NoseVariant::Tip}) {
            NoseVariant back {};
            QVERIFY(noseVariantFromName(noseVariantName(v), &back));
            QCOMPARE(back, v);
        }
        NoseVariant unused {};
        QVERIFY(!noseVariantFromName(QStringLiteral("roman"), &unused));
    }

    void presets()
    {
        const QStringList names = Style::presetNames();
        QVERIFY(names.contains(QStringLiteral("normal")));
        QVERIFY(names.contains(QStringLiteral("cute")));
        for (const QString &name : names) {
            bool ok = false;
            const Style s = Style::preset(name, &ok);
            QVERIFY(ok);
            QCOMPARE(s.name, name);
            for (const char *key :
                {"hair", "face", "jaw", "ears", "nose", "eyebrows", "eyes", "eyeballs", "lips", "mouth-inner"})
                QVERIFY2(s.components.contains(QLatin1StringView(key)), key);
        }
        QVERIFY(Style::preset(QStringLiteral("cute")).cute);
        QVERIFY(!Style::preset(QStringLiteral("normal")).cute);
        bool ok = true;
        Style::preset(QStringLiteral("no such style"), &ok);
        QVERIFY(!ok);
        // A default-constructed style draws like "normal" (missing components take its values).
        QCOMPARE(SvgFace(testFace(), Style()).svg(), SvgFace(testFace(), preset("normal")).svg());
    }

    void strokeWidthsScaleWithTheFace()
    {
        // Widths are in ES0/100: a face twice as large has lines twice as thick.
        const FaceModel small = averageFace(QRectF(50, 50, 150, 165), QSize(256, 256));
        const FaceModel large = averageFace(QRectF(100, 100, 300, 330), QSize(512, 512));
        const Node a = parsed(SvgFace(small, preset("normal")).svg());
        const Node b = parsed(SvgFace(large, preset("normal")).svg());
        const double wa = findId(a, QStringLiteral("face"))->attribute(QStringLiteral("stroke-width")).toDouble();
        const double wb = findId(b, QStringLiteral("face"))->attribute(QStringLiteral("stroke-width")).toDouble();
        const double es0 = large.fapu().es0;
        QVERIFY(
            std::abs(wb - preset("normal").components.value(QStringLiteral("face")).strokeWidth * es0 / 100) < 0.01);
        QVERIFY(std::abs(wb - 2 * wa) < 0.02);
    }

    // Long hair (its ends below the cheeks) fills the side of the face down to its ends; short
    // hair does not grow down beside the jaw.
    void longHairFillsBesideTheJaw()
    {
        Style s = preset("normal");
        s.components[QStringLiteral("hair")].fill = QColor(0, 200, 0);
        s.components[QStringLiteral("ears")].visible = false;
        const FaceModel shortHair = testFace();
        auto P = [&](const char *id) { return shortHair.point(pt::idx(id)); };
        const double width = P("5.1").x() - P("5.2").x();
        FaceModel longHair = shortHair;
        for (int side = 0; side < 2; ++side) {
            const double sx = side == 0 ? -1.0 : 1.0;
            const QPointF cheek = P(side == 0 ? "5.2" : "5.1");
            const double x = cheek.x() + sx * 0.3 * width;
            const std::array<const char *, 3> ids
                = side == 0 ? std::array {"h.3", "h.2", "h.1"} : std::array {"h.17", "h.18", "h.19"};
            const std::array<double, 3> ys {cheek.y(), (cheek.y() + P("2.1").y()) / 2, P("2.1").y()};
            for (int k = 0; k < 3; ++k)
                longHair.setPoint(pt::idx(ids[k]), QPointF(x, ys[k]));
        }
        auto hairBesideTheJaw = [&](const FaceModel &face) {
            const QImage image = rasterizeSvg(SvgFace(face, s).svg(), kImage, Qt::white);
            int hair = 0;
            for (const auto &[id, sx] : {std::pair {"2.14", -1.0}, std::pair {"2.13", 1.0}}) {
                const QPointF q = P(id) + QPointF(sx * 0.08 * width, 0);
                hair += image.pixelColor(q.toPoint()) == QColor(0, 200, 0) ? 1 : 0;
            }
            return hair;
        };
        QCOMPARE(hairBesideTheJaw(longHair), 2);
        QCOMPARE(hairBesideTheJaw(shortHair), 0);
    }

    void componentStylesAreApplied()
    {
        Style s = preset("normal");
        s.components[QStringLiteral("lips")].fill = QColor(10, 200, 30);
        s.components[QStringLiteral("lips")].stroke = QColor();
        s.components[QStringLiteral("hair")].fill = QColor(250, 0, 0, 128);
        s.components[QStringLiteral("ears")].visible = false;
        const Node root = parsed(SvgFace(testFace(), s).svg());
        const Node *lip = findId(root, QStringLiteral("mouth-upper-lip"));
        QCOMPARE(lip->attribute(QStringLiteral("fill")), QStringLiteral("#0ac81e"));
        QCOMPARE(lip->attribute(QStringLiteral("stroke")), QStringLiteral("none"));
        QVERIFY(!lip->has(QStringLiteral("stroke-width")));
        const Node *hair = findId(root, QStringLiteral("hair"));
        QCOMPARE(hair->attribute(QStringLiteral("fill")), QStringLiteral("#fa0000"));
        QVERIFY(std::abs(hair->attribute(QStringLiteral("fill-opacity")).toDouble() - 0.5) < 0.01);
        QVERIFY(!findId(root, QStringLiteral("ear-left")));
        QVERIFY(!findId(root, QStringLiteral("ear-right-inner")));
    }

    void sampleColours_data()
    {
        QTest::addColumn<QColor>("skin");
        QTest::addColumn<QColor>("hair");
        QTest::addColumn<QColor>("lips");
        QTest::addColumn<QColor>("iris");
        QTest::newRow("light skin, brown hair, blue eyes")
            << QColor(232, 190, 160) << QColor(90, 60, 35) << QColor(200, 90, 90) << QColor(60, 90, 140);
        QTest::newRow("dark skin, black hair, dark eyes")
            << QColor(110, 70, 50) << QColor(25, 20, 20) << QColor(120, 50, 55) << QColor(40, 25, 20);
        QTest::newRow("blond") << QColor(240, 205, 180) << QColor(215, 180, 110) << QColor(210, 110, 110)
                               << QColor(70, 110, 80);
    }

    void sampleColours()
    {
        QFETCH(QColor, skin);
        QFETCH(QColor, hair);
        QFETCH(QColor, lips);
        QFETCH(QColor, iris);
        const FaceModel face = testFace();
        const QImage photo = syntheticPhoto(face, skin, hair, lips, iris, true);
        Style s = preset("normal");
        toonface::sampleColours(photo, face, &s);
        for (const char *key : {"face", "jaw", "ears"}) {
            const QColor got = s.components.value(QLatin1StringView(key)).fill;
            QVERIFY2(colourDistance(got, skin) <= 3,
                qPrintable(QStringLiteral("%1 %2").arg(QLatin1StringView(key), got.name())));
        }
        QVERIFY2(colourDistance(s.components.value(QStringLiteral("hair")).fill, hair) <= 3,
            qPrintable(s.components.value(QStringLiteral("hair")).fill.name()));
        QVERIFY2(colourDistance(s.components.value(QStringLiteral("lips")).fill, lips) <= 3,
            qPrintable(s.components.value(QStringLiteral("lips")).fill.name()));
        // A dark iris is drawn as it is; a blue or green one in its hue, lighter and clearer
        // (photocolours.cpp, drawnIris).
        const QColor eyes = s.components.value(QStringLiteral("eyeballs")).fill;
        const LabColour seen = labOf(iris), drawn = labOf(eyes);
        if (seen.l < 30) {
            QVERIFY2(colourDistance(eyes, iris) <= 3, qPrintable(eyes.name()));
        } else {
            const double turn = std::remainder(std::atan2(drawn.b, drawn.a) - std::atan2(seen.b, seen.a), 2 * M_PI);
            QVERIFY2(std::abs(turn) < 0.15 && drawn.l >= 49.5
                    && std::hypot(drawn.a, drawn.b) > std::hypot(seen.a, seen.b) - 1,
                qPrintable(eyes.name()));
        }
        // Brows follow the hair: darker, same family.
        const QColor brow = s.components.value(QStringLiteral("eyebrows")).stroke;
        QVERIFY(brow.valueF() <= hair.valueF() + 1e-6);
    }

    void sampleColoursFallsBackOnImplausibleSamples()
    {
        const FaceModel face = testFace();
        const Style base = preset("normal");
        // No hair in the photo (the hair outline surrounds background): the preset's hair stays.
        {
            Style s = base;
            toonface::sampleColours(
                syntheticPhoto(face, QColor(230, 185, 155), QColor(), QColor(200, 90, 90), QColor(60, 40, 30), false),
                face, &s);
            QCOMPARE(
                s.components.value(QStringLiteral("hair")).fill, base.components.value(QStringLiteral("hair")).fill);
            QVERIFY(colourDistance(s.components.value(QStringLiteral("face")).fill, QColor(230, 185, 155)) <= 3);
        }
        // A green face is not skin, but it is as light as the person: drawn as a natural skin of
        // that lightness (not the preset's pale one, which drew dark-skinned faces pink); lips the
        // colour of the skin are no lips; a white iris is no iris: the preset's (or a lip colour
        // derived from the skin) is used instead.
        {
            Style s = base;
            toonface::sampleColours(syntheticPhoto(face, QColor(0, 220, 0), QColor(40, 30, 20), QColor(0, 220, 0),
                                        QColor(250, 250, 250), true),
                face, &s);
            const QColor skin = s.components.value(QStringLiteral("face")).fill;
            QVERIFY2(skin.red() > skin.green() && skin.green() > skin.blue(), qPrintable(skin.name()));
            QVERIFY2(std::abs(qGray(skin.rgb()) - qGray(QColor(0, 220, 0).rgb())) < 30, qPrintable(skin.name()));
            QCOMPARE(s.components.value(QStringLiteral("eyeballs")).fill,
                base.components.value(QStringLiteral("eyeballs")).fill);
            const QColor lip = s.components.value(QStringLiteral("lips")).fill;
            QVERIFY(colourDistance(lip, QColor(0, 220, 0)) > 60);
            QVERIFY(lip.red() > lip.green());
        }
        // A black-and-white photo: natural colours from its tones (issue 12), not the preset's:
        // a warm skin as light as the photo's, lips from the skin, hair a dark natural shade.
        {
            Style s = base;
            const QImage grey = syntheticPhoto(
                face, QColor(180, 180, 180), QColor(90, 90, 90), QColor(140, 140, 140), QColor(60, 60, 60), true)
                                    .convertToFormat(QImage::Format_Grayscale8);
            QVERIFY(grey.allGray());
            toonface::sampleColours(grey, face, &s);
            const QColor skin = s.components.value(QStringLiteral("face")).fill;
            QVERIFY2(skin.hsvSaturationF() > 0.15 && std::abs(skin.lightness() - 180) < 40, qPrintable(skin.name()));
            const QColor lips = s.components.value(QStringLiteral("lips")).fill;
            QVERIFY(lips.red() > lips.green() + 30);
            const QColor hair = s.components.value(QStringLiteral("hair")).fill;
            QVERIFY2(hair.lightness() < 110 && hair.red() >= hair.blue(), qPrintable(hair.name()));
        }
        // A null photo changes nothing.
        {
            Style s = base;
            toonface::sampleColours(QImage(), face, &s);
            QCOMPARE(s, base);
        }
    }

    void extraLayers()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString good = dir.filePath(QStringLiteral("shirt.svg"));
        {
            QFile f(good);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(kShirtLayer);
        }
        const FaceModel face = testFace();
        SvgFace svgFace(face, preset("normal"));
        QString error;
        QVERIFY2(svgFace.addLayerFile(good, &error), qPrintable(error));
        svgFace.addLayer("<svg xmlns=\"http://www.w3.org/2000/svg\"><circle id=\"badge\" cx=\"150\" cy=\"490\" "
                         "r=\"12\" fill=\"#ffcc00\"/></svg>");
        const QByteArray svg = svgFace.svg();
        const Node root = parsed(svg);
        QVERIFY(QSvgRenderer(svg).isValid());
        // Layers come after the head, in the order they were added, holding the files' children.
        QCOMPARE(root.children.last().attribute(QStringLiteral("id")), QStringLiteral("layer-2"));
        QCOMPARE(root.children[root.children.size() - 2].attribute(QStringLiteral("id")), QStringLiteral("layer-1"));
        const Node *layer1 = findId(root, QStringLiteral("layer-1"));
        QCOMPARE(layer1->children.size(), 3);
        // Their ids are prefixed with the layer's, references too, so they never clash with the face's.
        QCOMPARE(layer1->children[1].attribute(QStringLiteral("id")), QStringLiteral("layer-1-shirt"));
        QCOMPARE(layer1->children[2].attribute(QStringLiteral("xlink:href")), QStringLiteral("#layer-1-shirt"));
        QVERIFY(findId(*findId(root, QStringLiteral("layer-2")), QStringLiteral("layer-2-badge")));
        const QImage image = rasterizeSvg(svg, kImage);
        QVERIFY(colourDistance(image.pixelColor(256, 500), QColor(0x33, 0x66, 0xcc)) <= 2);
        QVERIFY(colourDistance(image.pixelColor(150, 490), QColor(0xff, 0xcc, 0x00)) <= 2);
    }

    // A layer file is drawing only: scripts, event handlers, javascript: links and foreign
    // content are left out, and its text stays text, so the exported animation opened in a
    // browser runs nothing of it.
    void layersAreInert()
    {
        SvgFace svgFace(testFace(), preset("normal"));
        svgFace.addLayer(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
            "onload=\"alert(1)\">"
            "<script>alert(2)</script>"
            "<circle id=\"kept\" cx=\"150\" cy=\"490\" r=\"12\" fill=\"#ffcc00\" onclick=\"alert(3)\" "
            "ONMOUSEOVER=\"alert(4)\"/>"
            "<a xlink:href=\" JavaScript:alert(5)\"><rect id=\"link\" width=\"5\" height=\"5\"/></a>"
            "<a href=\"data:text/html,&lt;script&gt;alert(6)&lt;/script&gt;\"><rect width=\"5\" height=\"5\"/></a>"
            "<foreignObject><div xmlns=\"http://www.w3.org/1999/xhtml\"><iframe src=\"x\"/></div></foreignObject>"
            "<g><script type=\"text/ecmascript\"><![CDATA[alert(7)]]></script><circle id=\"deep\" r=\"2\"/></g>"
            "<text id=\"words\">&lt;/script&gt;&lt;script&gt;alert(8)&lt;/script&gt; ]]&gt;</text>"
            "</svg>");
        const QByteArray svg = svgFace.svg();
        const Node root = parsed(svg);
        QVERIFY(QSvgRenderer(svg).isValid());
        const Node *layer = findId(root, QStringLiteral("layer-1"));
        QVERIFY(layer);
        QVERIFY(findId(*layer, QStringLiteral("layer-1-kept")));
        QVERIFY(findId(*layer, QStringLiteral("layer-1-link"))); // the drawing inside the link stays
        QVERIFY(findId(*layer, QStringLiteral("layer-1-deep")));
        for (const char *active : {"<script", "alert(1)", "alert(2)", "alert(3)", "alert(4)", "alert(5)", "alert(6)",
                 "alert(7)", "foreignObject", "iframe", "javascript", "JavaScript", "data:text", "onload", "onclick",
                 "ONMOUSEOVER", "]]>"})
            QVERIFY2(!svg.contains(active), active);
        // The text is still there, as text.
        QVERIFY(svg.contains("&lt;/script&gt;&lt;script&gt;alert(8)&lt;/script&gt; ]]&gt;"));
    }

    // Found by fuzz_layer: a javascript: URL with white space inside its scheme (browsers skip
    // tabs and line breaks there), and one put into a link by an animation's values or to.
    void layersAreInertAgainstHiddenSchemes()
    {
        SvgFace svgFace(testFace(), preset("normal"));
        svgFace.addLayer("<svg xmlns=\"http://www.w3.org/2000/svg\">"
                         "<a href=\"java\tscript:alert(1)\"><rect id=\"tab\" width=\"5\" height=\"5\"/></a>"
                         "<a href=\"java&#x0A;script:alert(2)\"><rect width=\"5\" height=\"5\"/></a>"
                         "<a><animate id=\"anim\" attributeName=\"href\" values=\"#x;javascript:alert(3)\"/>"
                         "<set attributeName=\"href\" to=\"vbscript:alert(4)\"/><rect width=\"5\" height=\"5\"/></a>"
                         "<circle id=\"moving\" r=\"4\"><animate attributeName=\"r\" values=\"4;8;4\" dur=\"1s\"/>"
                         "</circle></svg>");
        const QByteArray svg = svgFace.svg();
        const Node root = parsed(svg);
        const Node *layer = findId(root, QStringLiteral("layer-1"));
        QVERIFY(layer);
        QVERIFY(findId(*layer, QStringLiteral("layer-1-tab")));
        QVERIFY(!findId(*layer, QStringLiteral("layer-1-anim"))); // an animated link is left out whole
        for (const char *active : {"alert(1)", "alert(2)", "alert(3)", "alert(4)", "script:"})
            QVERIFY2(!svg.contains(active), active);
        // A layer is static drawing: the circle stays, its animation goes (allow-lists, issue 24).
        QVERIFY(findId(*layer, QStringLiteral("layer-1-moving")));
        QVERIFY(!svg.contains("values=\"4;8;4\""));
    }

    void badLayerFiles_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<bool>("create");
        QTest::newRow("missing") << QByteArray() << false;
        QTest::newRow("empty") << QByteArray() << true;
        QTest::newRow("malformed") << QByteArray("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect></svg>") << true;
        QTest::newRow("not svg") << QByteArray("<html><body/></html>") << true;
        QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0\0", 11) << true;
    }

    void badLayerFiles()
    {
        QFETCH(QByteArray, content);
        QFETCH(bool, create);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("layer.svg"));
        if (create) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(content);
        }
        SvgFace svgFace(testFace(), Style());
        const QByteArray before = svgFace.svg();
        QString error;
        QVERIFY(!svgFace.addLayerFile(path, &error));
        QVERIFY2(error.contains(path), qPrintable(error));
        QCOMPARE(svgFace.svg(), before); // nothing was added
        QVERIFY(!svgFace.addLayerFile(path)); // no error pointer: no crash
    }

    void invalidLayerContentKeepsNumbering()
    {
        SvgFace svgFace(testFace(), Style());
        svgFace.addLayer("<svg><unclosed></svg>");
        svgFace.addLayer("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect id=\"r\" width=\"1\" height=\"1\"/></svg>");
        const Node root = parsed(svgFace.svg());
        QVERIFY(findId(root, QStringLiteral("layer-1")));
        QCOMPARE(findId(root, QStringLiteral("layer-1"))->children.size(), 0);
        QVERIFY(findId(*findId(root, QStringLiteral("layer-2")), QStringLiteral("layer-2-r")));
    }

private:
    static QImage syntheticPhoto(
        const FaceModel &face, QColor skin, QColor hair, QColor lips, QColor iris, bool withHair)
    {
        QImage img(kImage, QImage::Format_RGB32);
        img.fill(QColor(190, 215, 250));
        QPainter p(&img);
        p.setPen(Qt::NoPen);
        auto poly = [&](std::initializer_list<const char *> ids) {
            QPolygonF pg;
            for (const char *id : ids)
                pg << face.point(id);
            return pg;
        };
        if (withHair) {
            QPolygonF h;
            for (int i = 0; i < 19; ++i)
                h << face.point(i);
            h << face.point("5.1") << face.point("5.2");
            p.setBrush(hair);
            p.drawPolygon(h);
        }
        p.setBrush(skin);
        p.drawPolygon(poly({"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"}));
        p.setBrush(lips);
        p.drawPolygon(poly({"8.4", "8.9", "8.1", "8.10", "8.3", "8.2"}));
        p.setBrush(Qt::white);
        p.drawPolygon(poly({"3.12", "3.2", "3.8", "3.4"}));
        p.drawPolygon(poly({"3.11", "3.1", "3.7", "3.3"}));
        p.setBrush(iris);
        const double r = 0.09 * face.fapu().es0;
        p.drawEllipse(face.point("3.6"), r, r);
        p.drawEllipse(face.point("3.5"), r, r);
        p.end();
        return img;
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSvgStyles)
#include "tst_svgstyles.moc"
