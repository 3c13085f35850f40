#include "face/averageface.h"
#include "face/emotion.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "render/style.h"
#include "render/svgface.h"
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

Q_DECLARE_METATYPE(toonface::HeadPose)

namespace {

using test::findId;
using test::Node;
using test::parseXml;

Node parsed(const QByteArray &data)
{
    Node root;
    QString error;
    if (!parseXml(data, &root, &error))
        qWarning("XML does not parse: %s", qPrintable(error));
    return root;
}

QStringList idsUnder(const Node &n)
{
    QStringList ids;
    for (const Node &c : n.children) {
        if (c.has(QStringLiteral("id")))
            ids << c.attribute(QStringLiteral("id"));
        ids << idsUnder(c);
    }
    return ids;
}

const QRegularExpression &numberPattern()
{
    static const QRegularExpression re(QStringLiteral("-?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?"));
    return re;
}

QList<double> numbers(const QString &s)
{
    QList<double> out;
    auto it = numberPattern().globalMatch(s);
    while (it.hasNext())
        out << it.next().captured().toDouble();
    return out;
}

QString skeleton(const QString &s)
{
    QString copy = s;
    return copy.replace(numberPattern(), QStringLiteral("#"));
}

QString commandLetters(const QString &d)
{
    QString letters;
    for (QChar c : d) {
        if (c.isLetter() && c != QLatin1Char('e') && c != QLatin1Char('E'))
            letters += c;
    }
    return letters;
}

// Compares two documents: the same elements and attributes in the same order; attribute
// values equal once numbers are masked, and every number within `tolerance`.
bool sameDocument(const Node &a, const Node &b, double tolerance, const QString &path, QString *why)
{
    const QString here = path + QLatin1Char('/') + a.name
        + (a.has(QStringLiteral("id")) ? QLatin1Char('#') + a.attribute(QStringLiteral("id")) : QString());
    if (a.name != b.name) {
        *why = QStringLiteral("%1: element <%2> vs <%3>").arg(here, a.name, b.name);
        return false;
    }
    if (a.attributes.size() != b.attributes.size()) {
        *why = QStringLiteral("%1: %2 vs %3 attributes").arg(here).arg(a.attributes.size()).arg(b.attributes.size());
        return false;
    }
    for (qsizetype i = 0; i < a.attributes.size(); ++i) {
        const auto &[an, av] = a.attributes[i];
        const auto &[bn, bv] = b.attributes[i];
        if (an != bn || skeleton(av) != skeleton(bv)) {
            *why = QStringLiteral("%1: %2=\"%3\" vs %4=\"%5\"").arg(here, an, av.left(80), bn, bv.left(80));
            return false;
        }
        const QList<double> x = numbers(av), y = numbers(bv);
        for (qsizetype k = 0; k < x.size(); ++k) {
            if (std::abs(x[k] - y[k]) > tolerance) {
                *why = QStringLiteral("%1: %2 number %3: %4 vs %5").arg(here, an).arg(k).arg(x[k]).arg(y[k]);
                return false;
            }
        }
    }
    if (a.children.size() != b.children.size()) {
        *why = QStringLiteral("%1: %2 vs %3 children").arg(here).arg(a.children.size()).arg(b.children.size());
        return false;
    }
    for (qsizetype i = 0; i < a.children.size(); ++i) {
        if (!sameDocument(a.children[i], b.children[i], tolerance, here, why))
            return false;
    }
    return true;
}

// ---- fixtures ----

const QSize kImage(512, 512);

FaceModel testFace()
{
    return averageFace(QRectF(106, 130, 300, 330), kImage);
}

Style preset(const char *name)
{
    bool ok = false;
    Style s = Style::preset(QString::fromLatin1(name), &ok);
    Q_ASSERT(ok);
    return s;
}

Pose scaled(Pose p, double k)
{
    for (QPointF &o : p.offset)
        o *= k;
    return p;
}

QMap<QString, Pose> namedPoses(const FaceModel &face)
{
    const MouthShapeSet shapes;
    QMap<QString, Pose> poses;
    poses.insert(QStringLiteral("neutral"), Pose());
    for (MouthShape s : kAllMouthShapes)
        poses.insert(QStringLiteral("mouth %1").arg(mouthShapeName(s)), mouthPose(face, shapes, s));
    for (Emotion e : kAllEmotions)
        poses.insert(QStringLiteral("emotion %1").arg(emotionName(e)), emotionPose(face, e, 1.0));
    Pose blink;
    blink.leftEyeOpen = 0;
    blink.rightEyeOpen = 0;
    poses.insert(QStringLiteral("blink"), blink);
    Pose gaze;
    gaze.offset[pt::idx("3.6")] = QPointF(-30, 4);
    gaze.offset[pt::idx("3.5")] = QPointF(30, -4);
    poses.insert(QStringLiteral("gaze far"), gaze);
    Pose head;
    head.head = {15, QPointF(12, -8), 0.8};
    poses.insert(QStringLiteral("head"), head);
    Pose all = mouthPose(face, shapes, MouthShape::A) + emotionPose(face, Emotion::Surprise, 1.0) + head;
    all.leftEyeOpen = 0.2;
    poses.insert(QStringLiteral("combined"), all);
    poses.insert(QStringLiteral("exaggerated"),
        scaled(mouthPose(face, shapes, MouthShape::O) + emotionPose(face, Emotion::Angry, 1.0), 3.0));
    return poses;
}

QPolygonF pathPoints(const QString &d)
{
    const QList<double> n = numbers(d);
    QPolygonF p;
    for (qsizetype i = 0; i + 1 < n.size(); i += 2)
        p << QPointF(n[i], n[i + 1]);
    return p;
}

// The paths this renderer writes: absolute M, L, H, V, C, Z.
QPainterPath painterPath(const QString &d)
{
    QPainterPath path;
    static const QRegularExpression token(QStringLiteral("([MLHVCZ])([^MLHVCZ]*)"));
    auto it = token.globalMatch(d);
    while (it.hasNext()) {
        const auto m = it.next();
        const QChar c = m.captured(1).at(0);
        const QList<double> v = numbers(m.captured(2));
        if (c == QLatin1Char('M'))
            path.moveTo(v[0], v[1]);
        else if (c == QLatin1Char('L'))
            path.lineTo(v[0], v[1]);
        else if (c == QLatin1Char('H'))
            path.lineTo(v[0], path.currentPosition().y());
        else if (c == QLatin1Char('V'))
            path.lineTo(path.currentPosition().x(), v[0]);
        else if (c == QLatin1Char('C'))
            path.cubicTo(v[0], v[1], v[2], v[3], v[4], v[5]);
        else
            path.closeSubpath();
    }
    return path;
}

double area(const QPainterPath &path)
{
    double total = 0;
    for (const QPolygonF &poly : path.toFillPolygons()) {
        double a = 0;
        for (qsizetype i = 0; i < poly.size(); ++i) {
            const QPointF p = poly[i], q = poly[(i + 1) % poly.size()];
            a += p.x() * q.y() - q.x() * p.y();
        }
        total += std::abs(a) / 2;
    }
    return total;
}

const FacePart *partById(const QVector<FacePart> &parts, const QString &id)
{
    for (const FacePart &p : parts) {
        if (p.id == id)
            return &p;
    }
    return nullptr;
}
// A pointer into a temporary list would dangle (AddressSanitizer found one).
const FacePart *partById(QVector<FacePart> &&parts, const QString &id) = delete;

QByteArray staticLayer(const QByteArray &svg)
{
    const qsizetype start = svg.indexOf("<g id=\"static-layer\">");
    const qsizetype end = svg.indexOf("</g>", start);
    return start >= 0 && end > start ? svg.mid(start, end - start) : QByteArray();
}

int colourDistance(QColor a, QColor b)
{
    return std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()), std::abs(a.blue() - b.blue())});
}

QColor pixel(const QImage &image, QPointF p)
{
    return image.pixelColor(int(std::floor(p.x())), int(std::floor(p.y())));
}

QString goldenPath(const QString &name)
{
    return QStringLiteral(TOONFACE_TEST_DATA "/render/%1.svg").arg(name);
}

const char kShirtLayer[]
    = "<?xml version=\"1.0\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"512\" height=\"512\">\n"
      "  <defs><linearGradient id=\"cloth\"><stop offset=\"0\" stop-color=\"#3366cc\"/></linearGradient></defs>\n"
      "  <rect id=\"shirt\" x=\"100\" y=\"470\" width=\"312\" height=\"42\" fill=\"#3366cc\"/>\n"
      "  <use xlink:href=\"#shirt\" x=\"0\" y=\"0\"/>\n"
      "</svg>\n";

} // namespace

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
        s.sampleColours(photo, face);
        for (const char *key : {"face", "jaw", "ears"}) {
            const QColor got = s.components.value(QLatin1StringView(key)).fill;
            QVERIFY2(colourDistance(got, skin) <= 3,
                qPrintable(QStringLiteral("%1 %2").arg(QLatin1StringView(key), got.name())));
        }
        QVERIFY2(colourDistance(s.components.value(QStringLiteral("hair")).fill, hair) <= 3,
            qPrintable(s.components.value(QStringLiteral("hair")).fill.name()));
        QVERIFY2(colourDistance(s.components.value(QStringLiteral("lips")).fill, lips) <= 3,
            qPrintable(s.components.value(QStringLiteral("lips")).fill.name()));
        QVERIFY2(colourDistance(s.components.value(QStringLiteral("eyeballs")).fill, iris) <= 3,
            qPrintable(s.components.value(QStringLiteral("eyeballs")).fill.name()));
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
            s.sampleColours(
                syntheticPhoto(face, QColor(230, 185, 155), QColor(), QColor(200, 90, 90), QColor(60, 40, 30), false),
                face);
            QCOMPARE(
                s.components.value(QStringLiteral("hair")).fill, base.components.value(QStringLiteral("hair")).fill);
            QVERIFY(colourDistance(s.components.value(QStringLiteral("face")).fill, QColor(230, 185, 155)) <= 3);
        }
        // A green face is not skin; lips the colour of the skin are no lips; a white iris is
        // no iris: the preset's (or a lip colour derived from the skin) is used instead.
        {
            Style s = base;
            s.sampleColours(syntheticPhoto(face, QColor(0, 220, 0), QColor(40, 30, 20), QColor(0, 220, 0),
                                QColor(250, 250, 250), true),
                face);
            QCOMPARE(
                s.components.value(QStringLiteral("face")).fill, base.components.value(QStringLiteral("face")).fill);
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
            s.sampleColours(grey, face);
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
            s.sampleColours(QImage(), face);
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
        // An animation of a drawing keeps its values.
        QVERIFY(svg.contains("values=\"4;8;4\""));
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
            drawing.appearance = {GlassesShape::Round, true, true, true, false};
        if (style.endsWith(QLatin1StringView("+bald")))
            drawing.appearance = {GlassesShape::Rectangular, false, false, false, true};
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

QTEST_GUILESS_MAIN(TestSvgFace)
#include "tst_svgface.moc"
