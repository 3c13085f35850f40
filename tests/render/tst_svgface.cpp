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
#include <QSet>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>
#include <QTransform>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

using namespace toonface;
using namespace toonface::svgfacetest;

Q_DECLARE_METATYPE(toonface::HeadPose)

// The SVG face: its structure, parts, poses, blinks, head motion and golden files.
class TestSvgFace : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void wellFormed_data()
    {
        QTest::addColumn<QString>("style");
        QTest::addColumn<QString>("pose");
        const FaceModel face = testFace();
        for (const QString &style : Style::presetNames()) {
            for (const QString &pose : namedPoses(face).keys())
                QTest::addRow("%s, %s", qPrintable(style), qPrintable(pose)) << style << pose;
        }
    }

    void wellFormed()
    {
        QFETCH(QString, style);
        QFETCH(QString, pose);
        const FaceModel face = testFace();
        const SvgFace svgFace(face, Style::preset(style));
        const QByteArray svg = svgFace.svg(namedPoses(face).value(pose));
        Node root;
        QString error;
        QVERIFY2(parseXml(svg, &root, &error), qPrintable(error));
        QCOMPARE(root.name, QStringLiteral("svg"));
        QVERIFY(QSvgRenderer(svg).isValid());
        // Compact: no number with more than two decimals, nothing non-finite.
        QVERIFY(!QString::fromUtf8(svg).contains(QRegularExpression(QStringLiteral("\\d\\.\\d{3}"))));
        QVERIFY(!svg.contains("nan") && !svg.contains("inf"));
    }

    void viewBoxIsThePhotoSize()
    {
        const FaceModel face = averageFace(QRectF(200, 100, 240, 280), QSize(640, 480));
        const Node root = parsed(SvgFace(face, Style()).svg());
        QCOMPARE(root.attribute(QStringLiteral("viewBox")), QStringLiteral("0 0 640 480"));
        QCOMPARE(root.attribute(QStringLiteral("width")), QStringLiteral("640"));
        QCOMPARE(root.attribute(QStringLiteral("height")), QStringLiteral("480"));
        QCOMPARE(root.attribute(QStringLiteral("version")), QStringLiteral("1.1"));
    }

    void viewBoxWithoutAPhotoHoldsThePoints()
    {
        const FaceModel face = averageFace(QRectF(50, 60, 200, 220), QSize());
        const QRectF b = face.bounds();
        const Node root = parsed(SvgFace(face, Style()).svg());
        QCOMPARE(root.attribute(QStringLiteral("viewBox")),
            QStringLiteral("0 0 %1 %2").arg(std::ceil(b.right() + b.left())).arg(std::ceil(b.bottom() + b.top())));
    }

    void layersAndComponentIds()
    {
        const Node root = parsed(SvgFace(testFace(), preset("normal")).svg());
        const Node *head = findId(root, QStringLiteral("head"));
        QVERIFY(head);
        QVERIFY(head->has(QStringLiteral("transform")));
        QCOMPARE(head->children.size(), 2);
        QCOMPARE(head->children[0].attribute(QStringLiteral("id")), QStringLiteral("static-layer"));
        QCOMPARE(head->children[1].attribute(QStringLiteral("id")), QStringLiteral("dynamic-layer"));
        const QStringList staticIds = idsUnder(head->children[0]);
        const QStringList dynamicIds = idsUnder(head->children[1]);
        // Drawing order matters: hair behind the ears behind the face; features on top.
        QCOMPARE(staticIds,
            (QStringList {QStringLiteral("hair"), QStringLiteral("ear-left"), QStringLiteral("ear-left-inner"),
                QStringLiteral("ear-right"), QStringLiteral("ear-right-inner"), QStringLiteral("face"),
                QStringLiteral("nose-bridge"), QStringLiteral("nose-bottom"), QStringLiteral("eyebrow-left"),
                QStringLiteral("eyebrow-right")}));
        for (const char *id :
            {"jaw", "mouth-inner", "mouth-upper-lip", "mouth-lower-lip", "eye-left", "eyeball-left", "pupil-left",
                "highlight-left", "eye-left-cover", "eye-left-line", "eye-right", "eyeball-right", "eye-right-line"})
            QVERIFY2(dynamicIds.contains(QLatin1StringView(id)), id);
        QVERIFY(dynamicIds.indexOf(QStringLiteral("jaw")) < dynamicIds.indexOf(QStringLiteral("mouth-inner")));
        QVERIFY(
            dynamicIds.indexOf(QStringLiteral("mouth-inner")) < dynamicIds.indexOf(QStringLiteral("mouth-upper-lip")));
        QVERIFY(dynamicIds.indexOf(QStringLiteral("eye-left")) < dynamicIds.indexOf(QStringLiteral("eyeball-left")));
        QVERIFY(
            dynamicIds.indexOf(QStringLiteral("eyeball-left")) < dynamicIds.indexOf(QStringLiteral("eye-left-cover")));
        QVERIFY(
            dynamicIds.indexOf(QStringLiteral("eye-left-cover")) < dynamicIds.indexOf(QStringLiteral("eye-left-line")));
        // Ids are unique across the document.
        const QStringList all = idsUnder(root);
        QCOMPARE(QSet<QString>(all.begin(), all.end()).size(), all.size());
    }

    void eyeballsAreClippedByTheEyeOutline()
    {
        const Node root = parsed(SvgFace(testFace(), preset("normal")).svg());
        for (const QString &side : {QStringLiteral("left"), QStringLiteral("right")}) {
            for (const QString &kind :
                {QStringLiteral("eyeball"), QStringLiteral("pupil"), QStringLiteral("highlight")}) {
                const Node *ball = findId(root, kind + QLatin1Char('-') + side);
                QVERIFY(ball);
                QCOMPARE(ball->name, QStringLiteral("circle"));
                QCOMPARE(ball->attribute(QStringLiteral("clip-path")), QStringLiteral("url(#clip-eye-%1)").arg(side));
            }
            const Node *clip = findId(root, QStringLiteral("clip-eye-") + side);
            QVERIFY(clip);
            QCOMPARE(clip->name, QStringLiteral("clipPath"));
            QCOMPARE(clip->children.size(), 1);
            QCOMPARE(clip->children[0].name, QStringLiteral("use"));
            QCOMPARE(clip->children[0].attribute(QStringLiteral("xlink:href")), QStringLiteral("#eye-") + side);
            QVERIFY(findId(root, QStringLiteral("eye-") + side));
        }
    }

    // The skin covers stand in for clipping in renderers without it; without them the drawing
    // is the same but for the two covers.
    // A frame around the head: square (or the aspect asked), whole pixels, holding every point
    // with room below for the jaw; the drawing's viewBox and size follow it.
    void headFrameHoldsTheHead_data()
    {
        QTest::addColumn<double>("aspect");
        QTest::newRow("square") << 1.0;
        QTest::newRow("portrait") << 0.8;
        QTest::newRow("wide") << 16.0 / 9.0;
    }
    void headFrameHoldsTheHead()
    {
        QFETCH(double, aspect);
        const FaceModel face = testFace();
        const QRectF frame = headFrame(face, aspect);
        const QRectF head = face.bounds();
        QVERIFY(frame.contains(head));
        QVERIFY(frame.bottom() - head.bottom() >= 0.2 * std::max(head.width(), head.height()) - 1);
        QVERIFY(std::abs(frame.width() / frame.height() - aspect) < 0.02);
        QCOMPARE(frame.x(), std::floor(frame.x()));
        QCOMPARE(frame.width(), std::floor(frame.width()));
        QVERIFY(frame.width() < 2 * std::max(head.width(), head.height()) * std::max(aspect, 1.0));

        SvgFace svgFace(face, preset("normal"));
        QCOMPARE(svgFace.frame(), QRectF(QPointF(0, 0), QSizeF(face.imageSize())));
        svgFace.setFrame(frame);
        const Node root = parsed(svgFace.svg());
        QCOMPARE(root.attribute(QStringLiteral("viewBox")),
            QStringLiteral("%1 %2 %3 %4").arg(frame.x()).arg(frame.y()).arg(frame.width()).arg(frame.height()));
        QCOMPARE(root.attribute(QStringLiteral("width")).toDouble(), frame.width());
        // Rendered, the face fills the picture: the frame's centre is skin, its top corner background
        // (the shoulders may reach the bottom ones).
        const QImage image = rasterizeSvg(svgFace.svg(), QSize(200, int(200 / aspect)), Qt::white);
        QVERIFY(image.pixelColor(image.width() / 2, image.height() / 2) != QColor(Qt::white));
        QCOMPARE(image.pixelColor(1, 1), QColor(Qt::white));
    }

    void eyeCoversCanBeLeftOut()
    {
        SvgFace svgFace(testFace(), preset("normal"));
        const Pose pose = mouthPose(testFace(), MouthShapeSet(), MouthShape::O);
        QVERIFY(svgFace.eyeCovers());
        const QVector<FacePart> with = svgFace.parts(pose);
        svgFace.setEyeCovers(false);
        const QVector<FacePart> without = svgFace.parts(pose);
        QStringList removed;
        for (const FacePart &p : with) {
            if (std::none_of(without.cbegin(), without.cend(), [&](const FacePart &q) { return q.id == p.id; }))
                removed.append(p.id);
        }
        QCOMPARE(removed, (QStringList {QStringLiteral("eye-left-cover"), QStringLiteral("eye-right-cover")}));
        QCOMPARE(without.size(), with.size() - 2);
        const Node root = parsed(svgFace.svg(pose));
        QVERIFY(!findId(root, QStringLiteral("eye-left-cover")));
        QVERIFY(findId(root, QStringLiteral("clip-eye-left")));
        QVERIFY(findId(root, QStringLiteral("eye-left-line")));
    }

    void mouthPoseMovesOnlyTheDynamicLayer()
    {
        const FaceModel face = testFace();
        const SvgFace svgFace(face, preset("normal"));
        const QByteArray neutral = svgFace.svg();
        const QByteArray open = svgFace.svg(mouthPose(face, MouthShapeSet(), MouthShape::A));
        QVERIFY(!staticLayer(neutral).isEmpty());
        QCOMPARE(staticLayer(open), staticLayer(neutral));
        const Node a = parsed(neutral), b = parsed(open);
        for (const char *id : {"mouth-inner", "mouth-lower-lip", "jaw"}) {
            const QString d0 = findId(a, QLatin1StringView(id))->attribute(QStringLiteral("d"));
            const QString d1 = findId(b, QLatin1StringView(id))->attribute(QStringLiteral("d"));
            QVERIFY2(d0 != d1, id);
        }
        // The open mouth has area; the chin drops by the lower lip's motion.
        const QRectF inner0
            = pathPoints(findId(a, QStringLiteral("mouth-inner"))->attribute(QStringLiteral("d"))).boundingRect();
        const QRectF inner1
            = pathPoints(findId(b, QStringLiteral("mouth-inner"))->attribute(QStringLiteral("d"))).boundingRect();
        QVERIFY(inner1.height() > inner0.height() + 0.5 * face.fapu().mns0);
        const double drop = MouthShapeSet().displacements(MouthShape::A, face)[MouthControl::Down].y();
        const QRectF jaw0 = pathPoints(findId(a, QStringLiteral("jaw"))->attribute(QStringLiteral("d"))).boundingRect();
        const QRectF jaw1 = pathPoints(findId(b, QStringLiteral("jaw"))->attribute(QStringLiteral("d"))).boundingRect();
        QVERIFY(std::abs((jaw1.bottom() - jaw0.bottom()) - drop) < 0.35 * drop);
        // The eyes did not move.
        QCOMPARE(findId(b, QStringLiteral("eye-left"))->attribute(QStringLiteral("d")),
            findId(a, QStringLiteral("eye-left"))->attribute(QStringLiteral("d")));
    }

    void teethAndTongueStayInsideTheMouth_data()
    {
        QTest::addColumn<QString>("pose");
        for (const QString &pose : namedPoses(testFace()).keys())
            QTest::newRow(qPrintable(pose)) << pose;
    }

    void teethAndTongueStayInsideTheMouth()
    {
        QFETCH(QString, pose);
        const FaceModel face = testFace();
        const QVector<FacePart> parts = SvgFace(face, preset("normal")).parts(namedPoses(face).value(pose));
        auto path = [&](const char *id) {
            return painterPath(partById(parts, QLatin1StringView(id))->geometry.value(QStringLiteral("d")));
        };
        const QPainterPath inner = path("mouth-inner");
        for (const char *id : {"mouth-teeth", "mouth-tongue"}) {
            const QPainterPath part = path(id);
            const double outside = area(part.subtracted(inner));
            QVERIFY2(outside < 0.5 + 0.02 * area(part),
                qPrintable(QStringLiteral("%1: %2 px² outside").arg(QLatin1StringView(id)).arg(outside)));
        }
        QVERIFY(area(path("mouth-teeth")) + area(path("mouth-tongue")) <= area(inner) + 1.0);
    }

    // Animation moves the pose a little at a time: the drawing must follow without jumps (a
    // curve fitted to a loose tolerance would pop by up to 2/3 px where its error crosses it).
    void movingPartsFollowThePoseContinuously_data()
    {
        QTest::addColumn<QString>("style");
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::newRow("m to a") << "normal"
                                << "mouth m"
                                << "mouth a";
        QTest::newRow("f to o, lips parting") << "normal"
                                              << "mouth f"
                                              << "mouth o";
        QTest::newRow("i to u, cute") << "cute"
                                      << "mouth i"
                                      << "mouth u";
        QTest::newRow("blink") << "bold"
                               << "neutral"
                               << "blink";
        QTest::newRow("brows, thick") << "bold"
                                      << "neutral"
                                      << "emotion surprise";
        QTest::newRow("brows, Bezier") << "soft"
                                       << "emotion sad"
                                       << "emotion angry";
    }

    void movingPartsFollowThePoseContinuously()
    {
        QFETCH(QString, style);
        QFETCH(QString, from);
        QFETCH(QString, to);
        const FaceModel face = testFace();
        const SvgFace svgFace(face, Style::preset(style));
        const QMap<QString, Pose> poses = namedPoses(face);
        constexpr int kSteps = 500;
        const QVector<FacePart> a = svgFace.parts(poses.value(from));
        const QVector<FacePart> b = svgFace.parts(poses.value(to));
        QVector<FacePart> previous = a;
        for (int step = 1; step <= kSteps; ++step) {
            const QVector<FacePart> now
                = svgFace.parts(Pose::lerp(poses.value(from), poses.value(to), double(step) / kSteps));
            for (qsizetype i = 0; i < now.size(); ++i) {
                for (auto it = now[i].geometry.cbegin(); it != now[i].geometry.cend(); ++it) {
                    if (it.value() == previous[i].geometry.value(it.key()))
                        continue;
                    const QList<double> x = numbers(previous[i].geometry.value(it.key()));
                    const QList<double> y = numbers(it.value());
                    const QList<double> whole0 = numbers(a[i].geometry.value(it.key()));
                    const QList<double> whole1 = numbers(b[i].geometry.value(it.key()));
                    QCOMPARE(y.size(), x.size());
                    for (qsizetype j = 0; j < y.size(); ++j) {
                        // A step moves a number by about its share of the whole move (more
                        // where the motion bends, as where the lips part); 0.02 is the
                        // rounding of two numbers to 0.01.
                        const double share = std::abs(whole1[j] - whole0[j]) / kSteps;
                        QVERIFY2(std::abs(y[j] - x[j]) <= 4 * share + 0.02,
                            qPrintable(QStringLiteral("%1 %2 number %3 jumps by %4 at step %5")
                                           .arg(now[i].id, it.key())
                                           .arg(j)
                                           .arg(y[j] - x[j])
                                           .arg(step)));
                    }
                }
            }
            previous = now;
        }
    }

    // Between two mouth shapes whose lips stay apart, every mouth part (teeth and tongue too)
    // moves linearly with the pose, so eased poses ease the drawing exactly.
    void mouthIsLinearInThePose()
    {
        const FaceModel face = testFace();
        const SvgFace svgFace(face, preset("normal"));
        const MouthShapeSet shapes;
        const Pose wide = mouthPose(face, shapes, MouthShape::A);
        const Pose narrow = mouthPose(face, shapes, MouthShape::I);
        const QVector<FacePart> from = svgFace.parts(wide);
        const QVector<FacePart> to = svgFace.parts(narrow);
        for (double s : {0.25, 0.5, 0.8}) {
            const QVector<FacePart> mid = svgFace.parts(Pose::lerp(wide, narrow, s));
            for (qsizetype i = 0; i < mid.size(); ++i) {
                if (!mid[i].id.startsWith(QLatin1StringView("mouth-")) && mid[i].id != QLatin1StringView("jaw"))
                    continue;
                const QList<double> x = numbers(from[i].geometry.value(QStringLiteral("d")));
                const QList<double> y = numbers(to[i].geometry.value(QStringLiteral("d")));
                const QList<double> m = numbers(mid[i].geometry.value(QStringLiteral("d")));
                for (qsizetype j = 0; j < m.size(); ++j)
                    QVERIFY2(std::abs(m[j] - (x[j] + (y[j] - x[j]) * s)) <= 0.02, qPrintable(mid[i].id));
            }
        }
    }

    void teethShowOnlyWhenTheMouthOpens()
    {
        const FaceModel face = testFace();
        const SvgFace svgFace(face, preset("normal"));
        auto teethArea = [&](const Pose &pose) {
            const QVector<FacePart> parts = svgFace.parts(pose);
            return area(
                painterPath(partById(parts, QStringLiteral("mouth-teeth"))->geometry.value(QStringLiteral("d"))));
        };
        // f tucks the lower lip up against the upper: the lips touch, no teeth show (they take
        // a share of the hairline between the lips' inner edges: on average under 0.1 px tall).
        QVERIFY(teethArea(mouthPose(face, MouthShapeSet(), MouthShape::F)) < 0.1 * face.fapu().mw0);
        const double open = teethArea(mouthPose(face, MouthShapeSet(), MouthShape::A));
        QVERIFY(open > 0.02 * face.fapu().es0 * face.fapu().mw0);
    }

    void partStructureIsPoseIndependent_data()
    {
        QTest::addColumn<QString>("style");
        QTest::addColumn<QString>("pose");
        const FaceModel face = testFace();
        for (const QString &style : Style::presetNames()) {
            for (const QString &pose : namedPoses(face).keys()) {
                if (pose != QLatin1StringView("neutral"))
                    QTest::addRow("%s, %s", qPrintable(style), qPrintable(pose)) << style << pose;
            }
        }
    }

    void partStructureIsPoseIndependent()
    {
        QFETCH(QString, style);
        QFETCH(QString, pose);
        const FaceModel face = testFace();
        const SvgFace svgFace(face, Style::preset(style));
        const QVector<FacePart> neutral = svgFace.parts();
        const QVector<FacePart> posed = svgFace.parts(namedPoses(face).value(pose));
        QCOMPARE(posed.size(), neutral.size());
        for (qsizetype i = 0; i < neutral.size(); ++i) {
            const FacePart &a = neutral[i];
            const FacePart &b = posed[i];
            QCOMPARE(b.id, a.id);
            QCOMPARE(b.layer, a.layer);
            QCOMPARE(b.element, a.element);
            QCOMPARE(b.styleKey, a.styleKey);
            QCOMPARE(b.clipPath, a.clipPath);
            QCOMPARE(b.geometry.keys(), a.geometry.keys());
            for (auto it = a.geometry.cbegin(); it != a.geometry.cend(); ++it) {
                const QString other = b.geometry.value(it.key());
                if (it.key() == QLatin1StringView("d"))
                    QCOMPARE(commandLetters(other), commandLetters(it.value()));
                QCOMPARE(numbers(other).size(), numbers(it.value()).size());
            }
        }
    }

    void posedGeometryIsThePartsThatMove_data() { partStructureIsPoseIndependent_data(); }

    void posedGeometryIsThePartsThatMove()
    {
        // The SMIL export samples posedGeometry() instead of parts(): they must agree.
        QFETCH(QString, style);
        QFETCH(QString, pose);
        const FaceModel face = testFace();
        SvgFace svgFace(face, Style::preset(style));
        for (bool covers : {true, false}) {
            svgFace.setEyeCovers(covers);
            const Pose p = namedPoses(face).value(pose);
            const QVector<FacePart> parts = svgFace.parts(p);
            const std::vector<SvgFace::PartGeometry> posed = svgFace.posedGeometry(p);
            const qsizetype still = svgFace.stillPartCount();
            QCOMPARE(still + qsizetype(posed.size()), parts.size());
            QVERIFY(!posed.empty());
            for (qsizetype i = 0; i < parts.size(); ++i) {
                // The still parts first (all of the static layer), the posed ones after them.
                if (i < still)
                    QCOMPARE(parts[i].layer, QStringLiteral("static"));
                if (i < still)
                    continue;
                const SvgFace::PartGeometry &g = posed[size_t(i - still)];
                QCOMPARE(QString::fromLatin1(g.id), parts[i].id);
                QCOMPARE(qsizetype(g.attributes.size()), parts[i].geometry.size());
                for (const auto &[name, value] : g.attributes)
                    QCOMPARE(QString::fromLatin1(value), parts[i].geometry.value(QString::fromLatin1(name)));
                // Asked for alone, a part comes the same, with fewer others (those drawn with it).
                const std::vector<SvgFace::PartGeometry> alone = svgFace.posedGeometry(p, {g.id});
                const auto it = std::find_if(alone.cbegin(), alone.cend(),
                    [&](const SvgFace::PartGeometry &a) { return std::strcmp(a.id, g.id) == 0; });
                QVERIFY(it != alone.cend());
                QVERIFY(it->attributes == g.attributes);
                QVERIFY(alone.size() < posed.size());
            }
        }
    }

    void hiddenComponentsLeaveEveryPose()
    {
        // Every component a pose draws, switched off in the style, is drawn in no pose.
        const FaceModel face = testFace();
        const Pose pose = mouthPose(face, MouthShapeSet(), MouthShape::A) + emotionPose(face, Emotion::Smile, 1.0);
        QSet<QString> keys;
        for (const FacePart &p : SvgFace(face, Style::preset(QStringLiteral("normal"))).parts(pose))
            keys.insert(p.styleKey);
        QVERIFY(keys.contains(QStringLiteral("jaw")) && keys.contains(QStringLiteral("eyebrows")));
        for (const QString &key : keys) {
            Style style = Style::preset(QStringLiteral("normal"));
            style.components[key].visible = false;
            const SvgFace svgFace(face, style);
            for (const Pose &p : {Pose {}, pose}) {
                for (const FacePart &part : svgFace.parts(p))
                    QVERIFY2(part.styleKey != key, qPrintable(key + QLatin1Char(' ') + part.id));
                const qsizetype still = svgFace.stillPartCount();
                QCOMPARE(still + qsizetype(svgFace.posedGeometry(p).size()), svgFace.parts(p).size());
            }
        }
    }

    void partsMatchTheSvg()
    {
        // The SMIL exporter animates the attributes parts() lists: they must be the SVG's own.
        const FaceModel face = testFace();
        const SvgFace svgFace(face, preset("cute"));
        const Pose pose = mouthPose(face, MouthShapeSet(), MouthShape::E) + emotionPose(face, Emotion::Sad, 0.7);
        const Node root = parsed(svgFace.svg(pose));
        const QVector<FacePart> parts = svgFace.parts(pose);
        QVERIFY(parts.size() > 20);
        for (const FacePart &p : parts) {
            const Node *n = findId(root, p.id);
            QVERIFY2(n, qPrintable(p.id));
            QCOMPARE(n->name, p.element);
            for (auto it = p.geometry.cbegin(); it != p.geometry.cend(); ++it)
                QCOMPARE(n->attribute(it.key()), it.value());
            QCOMPARE(n->attribute(QStringLiteral("clip-path")),
                p.clipPath.isEmpty() ? QString() : QStringLiteral("url(#%1)").arg(p.clipPath));
            QVERIFY(p.layer == QLatin1StringView("static") || p.layer == QLatin1StringView("dynamic"));
            QVERIFY(!p.styleKey.isEmpty());
        }
    }

    void blinkHidesTheEyeball_data()
    {
        QTest::addColumn<QString>("style");
        QTest::newRow("normal") << QStringLiteral("normal");
        QTest::newRow("cute") << QStringLiteral("cute");
    }

    void blinkHidesTheEyeball()
    {
        QFETCH(QString, style);
        const FaceModel face = testFace();
        const Style s = Style::preset(style);
        const SvgFace svgFace(face, s);
        const QColor iris = s.components.value(QStringLiteral("eyeballs")).fill;
        const QColor skin = s.components.value(QStringLiteral("face")).fill;
        const QColor white = s.components.value(QStringLiteral("eyes")).fill;

        // The eyeball as drawn: centre and radius from the SVG, so the style's rules apply.
        const QVector<FacePart> parts = svgFace.parts(); // kept: partById points into it
        const FacePart *ball = partById(parts, QStringLiteral("eyeball-left"));
        QVERIFY(ball);
        const QPointF centre(ball->geometry.value(QStringLiteral("cx")).toDouble(),
            ball->geometry.value(QStringLiteral("cy")).toDouble());
        const double r = ball->geometry.value(QStringLiteral("r")).toDouble();
        // A point of the iris: upper left of the pupil, clear of the highlight (upper right),
        // the lids and the line a shut eye becomes.
        const QPointF probeOffset(-0.6 * r, -0.45 * r);
        const QPointF probe = centre + probeOffset;

        const QImage open = rasterizeSvg(svgFace.svg(), kImage);
        QCOMPARE(open.size(), kImage);
        QVERIFY2(colourDistance(pixel(open, probe), iris) <= 12, qPrintable(pixel(open, probe).name()));

        Pose blink;
        blink.leftEyeOpen = 0;
        const QImage shut = rasterizeSvg(svgFace.svg(blink), kImage);
        const QColor c = pixel(shut, probe);
        QVERIFY2(colourDistance(c, skin) <= 12, qPrintable(c.name()));
        // The other eye still open.
        const FacePart *right = partById(parts, QStringLiteral("eyeball-right"));
        const QPointF rc = QPointF(right->geometry.value(QStringLiteral("cx")).toDouble(),
                               right->geometry.value(QStringLiteral("cy")).toDouble())
            + probeOffset;
        QVERIFY(colourDistance(pixel(shut, rc), iris) <= 12);

        // Never drawn outside the eye: an eyeball pushed up beyond the upper lid shows skin
        // above the lid, and the eye's white or iris below it.
        Pose up;
        up.offset[pt::idx("3.6")] = QPointF(0, -r);
        const QVector<FacePart> raisedParts = svgFace.parts(up);
        const FacePart *raisedBall = partById(raisedParts, QStringLiteral("eyeball-left"));
        const QPointF raisedCentre(raisedBall->geometry.value(QStringLiteral("cx")).toDouble(),
            raisedBall->geometry.value(QStringLiteral("cy")).toDouble());
        // The upper lid as drawn: the first segment of the eye outline, at its R3.
        const QList<double> d
            = numbers(partById(raisedParts, QStringLiteral("eye-left"))->geometry.value(QStringLiteral("d")));
        QVERIFY(d.size() >= 8);
        const QPointF lid
            = (QPointF(d[0], d[1]) + 3 * QPointF(d[2], d[3]) + 3 * QPointF(d[4], d[5]) + QPointF(d[6], d[7])) / 8.0;
        const QPointF aboveLid(lid.x(), lid.y() - 0.35 * r);
        QVERIFY(QLineF(aboveLid, raisedCentre).length() < 0.9 * r); // inside the raised eyeball
        const QImage raised = rasterizeSvg(svgFace.svg(up), kImage);
        QVERIFY2(colourDistance(pixel(raised, aboveLid), skin) <= 12, qPrintable(pixel(raised, aboveLid).name()));
        QVERIFY(colourDistance(pixel(raised, aboveLid), white) > 12);
    }

    void headTransform_data()
    {
        QTest::addColumn<HeadPose>("head");
        QTest::newRow("neutral") << HeadPose {};
        QTest::newRow("turned") << HeadPose {20, QPointF(0, 0), 1.0};
        QTest::newRow("moved and scaled") << HeadPose {-7.5, QPointF(14, -6), 1.25};
    }

    void headTransform()
    {
        QFETCH(HeadPose, head);
        const FaceModel face = testFace();
        Pose pose;
        pose.head = head;
        const SvgFace svgFace(face, Style());
        const Node root = parsed(svgFace.svg(pose));
        const QString attr = findId(root, QStringLiteral("head"))->attribute(QStringLiteral("transform"));
        QCOMPARE(svgFace.headTransform(head), attr);
        // Apply the SVG transform list left to right, as SVG composes it.
        QTransform t;
        static const QRegularExpression item(QStringLiteral("(\\w+)\\(([^)]*)\\)"));
        auto it = item.globalMatch(attr);
        int count = 0;
        while (it.hasNext()) {
            const auto m = it.next();
            const QList<double> v = numbers(m.captured(2));
            const QString op = m.captured(1);
            if (op == QLatin1StringView("translate"))
                t.translate(v.value(0), v.value(1));
            else if (op == QLatin1StringView("rotate"))
                t.rotate(v.value(0));
            else if (op == QLatin1StringView("scale"))
                t.scale(v.value(0), v.value(v.size() > 1 ? 1 : 0));
            else
                QFAIL(qPrintable(op));
            ++count;
        }
        QVERIFY(count >= 3);
        // About the face centre: it only moves by the translation; other points turn and scale.
        const QPointF c = face.bounds(PointGroup::Contour).center();
        QVERIFY(QLineF(t.map(c), c + head.translation).length() < 0.02);
        const QPointF p = face.point("2.1");
        QTransform expected;
        expected.translate(c.x() + head.translation.x(), c.y() + head.translation.y());
        expected.rotate(head.rotationDeg);
        expected.scale(head.scale, head.scale);
        expected.translate(-c.x(), -c.y());
        QVERIFY(QLineF(t.map(p), expected.map(p)).length() < 0.05);
        if (head == HeadPose {})
            QVERIFY(QLineF(t.map(p), p).length() < 0.02);
    }

    void degenerateFaceStillGivesValidSvg()
    {
        const FaceModel empty(QSize(100, 80));
        const QByteArray svg = SvgFace(empty, Style()).svg();
        Node root;
        QString error;
        QVERIFY2(parseXml(svg, &root, &error), qPrintable(error));
        QVERIFY(!svg.contains("nan") && !svg.contains("inf"));
        QCOMPARE(root.attribute(QStringLiteral("viewBox")), QStringLiteral("0 0 100 80"));
        FaceModel broken = testFace();
        broken.setPoint(pt::idx("3.2"), QPointF(qQNaN(), 5));
        const QByteArray svg2 = SvgFace(broken, Style()).svg();
        QVERIFY(parseXml(svg2, &root, &error));
        QVERIFY(!svg2.contains("nan"));
    }

    void concurrentUseGivesTheSameResult()
    {
        const FaceModel face = testFace();
        const SvgFace svgFace(face, preset("cute"));
        const Pose pose = mouthPose(face, MouthShapeSet(), MouthShape::O);
        const QByteArray expected = svgFace.svg(pose);
        std::vector<QByteArray> results(4);
        std::vector<std::thread> threads;
        for (int i = 0; i < 4; ++i) {
            threads.emplace_back([&, i] {
                for (int k = 0; k < 20; ++k)
                    results[i] = svgFace.svg(pose);
            });
        }
        for (auto &t : threads)
            t.join();
        for (const QByteArray &r : results)
            QCOMPARE(r, expected);
    }

    void rasterize()
    {
        QCOMPARE(rasterizeSvg("not svg at all", QSize(10, 10)), QImage());
        QCOMPARE(rasterizeSvg(SvgFace(testFace(), Style()).svg(), QSize()), QImage());
        // A 640x480 drawing in a square keeps its aspect, centred, transparent around.
        const FaceModel face = averageFace(QRectF(200, 100, 240, 280), QSize(640, 480));
        const QImage image = rasterizeSvg(SvgFace(face, Style()).svg(), QSize(200, 200), Qt::white);
        QCOMPARE(image.size(), QSize(200, 200));
        QCOMPARE(image.pixelColor(100, 5).alpha(), 0); // above the 200x150 drawing
        QCOMPARE(image.pixelColor(100, 195).alpha(), 0); // below it
        QCOMPARE(image.pixelColor(2, 100), QColor(Qt::white)); // background inside it
    }

    void golden_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("style");
        QTest::addColumn<QString>("pose");
        QTest::addColumn<bool>("layer");
        QTest::newRow("normal-neutral") << QStringLiteral("normal-neutral") << QStringLiteral("normal")
                                        << QStringLiteral("neutral") << false;
        QTest::newRow("cute-combined") << QStringLiteral("cute-combined") << QStringLiteral("cute")
                                       << QStringLiteral("combined") << false;
        QTest::newRow("bold-blink-layer")
            << QStringLiteral("bold-blink-layer") << QStringLiteral("bold") << QStringLiteral("blink") << true;
        QTest::newRow("soft-smile") << QStringLiteral("soft-smile") << QStringLiteral("soft")
                                    << QStringLiteral("emotion smile") << false;
        // With what a person wears: round glasses, moustache, beard and hat, the jaw dropped.
        QTest::newRow("normal-worn-surprise") << QStringLiteral("normal-worn-surprise") << QStringLiteral("normal+worn")
                                              << QStringLiteral("emotion surprise") << false;
        QTest::newRow("bold-bald-angry") << QStringLiteral("bold-bald-angry") << QStringLiteral("bold+bald")
                                         << QStringLiteral("emotion angry") << false;
    }

    // Golden SVGs, compared as parsed XML with numbers within 0.02. After an intended change
    // to the drawing, regenerate them with TOONFACE_UPDATE_GOLDEN=1 ./tst_svgface golden, look
    // at the new files (rasterized) and commit them.
    void golden()
    {
        QFETCH(QString, name);
        QFETCH(QString, style);
        QFETCH(QString, pose);
        QFETCH(bool, layer);
        const FaceModel face = testFace();
        Style drawing = Style::preset(style.section(QLatin1Char('+'), 0, 0));
        if (style.endsWith(QLatin1StringView("+worn")))
            drawing.appearance = {GlassesShape::Round, true, true, false, true, false, {}};
        if (style.endsWith(QLatin1StringView("+bald")))
            drawing.appearance = {GlassesShape::Rectangular, false, false, false, false, true, {}};
        SvgFace svgFace(face, drawing);
        if (layer)
            svgFace.addLayer(kShirtLayer);
        const QByteArray svg = svgFace.svg(namedPoses(face).value(pose));
        const QString path = goldenPath(name);
        if (qEnvironmentVariableIntValue("TOONFACE_UPDATE_GOLDEN") == 1) {
            QDir().mkpath(QFileInfo(path).absolutePath());
            QFile out(path);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(svg);
            qInfo("updated %s", qPrintable(path));
            return;
        }
        QFile in(path);
        QVERIFY2(in.open(QIODevice::ReadOnly), qPrintable(QStringLiteral("missing golden file %1").arg(path)));
        Node want, got;
        QString error;
        QVERIFY2(parseXml(in.readAll(), &want, &error), qPrintable(error));
        QVERIFY2(parseXml(svg, &got, &error), qPrintable(error));
        QString why;
        QVERIFY2(sameDocument(got, want, 0.02, QString(), &why), qPrintable(why));
    }

    // A headscarf: the cloth drawn around the face (behind it, in the hat's colour, past the chin)
    // instead of the hair, the crown and brim over it; a hat alone leaves the hair drawn.
    void wrapReplacesTheHair()
    {
        const FaceModel face = testFace();
        Style drawing = Style::preset(QStringLiteral("normal"));
        drawing.appearance.hat = true;
        const QByteArray capped = SvgFace(face, drawing).svg();
        QVERIFY(capped.contains("id=\"hair\""));
        QVERIFY(!capped.contains("id=\"hat-wrap\""));
        drawing.appearance.wrap = true;
        const SvgFace wrapped(face, drawing);
        const QByteArray svg = wrapped.svg();
        QVERIFY(!svg.contains("id=\"hair\""));
        QVERIFY(svg.contains("id=\"hat-wrap\""));
        QVERIFY(svg.contains("id=\"hat\""));
        QVERIFY(svg.indexOf("id=\"hat-wrap\"") < svg.indexOf("id=\"face\""));
        // The wrap reaches under the chin and out past the cheeks.
        for (const FacePart &part : wrapped.parts()) {
            if (part.id != QLatin1StringView("hat-wrap"))
                continue;
            QPolygonF shape;
            for (const QString &xy :
                part.geometry.value(QStringLiteral("points")).split(QLatin1Char(' '), Qt::SkipEmptyParts))
                shape << QPointF(
                    xy.section(QLatin1Char(','), 0, 0).toDouble(), xy.section(QLatin1Char(','), 1, 1).toDouble());
            const QRectF box = shape.boundingRect();
            QVERIFY(box.bottom() > face.point("2.1").y());
            QVERIFY(box.left() < face.point("5.2").x() && box.right() > face.point("5.1").x());
            return;
        }
        QFAIL("no hat-wrap part");
    }

    void goldenComparisonNoticesChanges()
    {
        // The comparison itself: tolerant of rounding, not of real changes.
        const Node a = parsed("<svg><path id=\"p\" d=\"M1,2C3,4 5,6 7,8\"/></svg>");
        const Node nearly = parsed("<svg><path id=\"p\" d=\"M1.01,2C3,4 5,6 7,7.99\"/></svg>");
        const Node moved = parsed("<svg><path id=\"p\" d=\"M1,2C3,4 5,6 7,8.5\"/></svg>");
        const Node other = parsed("<svg><path id=\"p\" d=\"M1,2L3,4\"/></svg>");
        QString why;
        QVERIFY(sameDocument(a, nearly, 0.02, QString(), &why));
        QVERIFY(!sameDocument(a, moved, 0.02, QString(), &why));
        QVERIFY(!sameDocument(a, other, 0.02, QString(), &why));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestSvgFace)
#include "tst_svgface.moc"
