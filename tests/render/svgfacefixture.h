#pragma once

#include "face/averageface.h"
#include "face/emotion.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "render/style.h"
#include "render/svgface.h"
#include "xmltree.h"

#include <QColor>
#include <QImage>
#include <QMap>
#include <QPainterPath>
#include <QPolygonF>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QXmlStreamReader>

#include <cmath>

// What the tests of the SVG face share: a test face and its named poses, the drawing's parts,
// paths and colours, and golden files.
namespace toonface::svgfacetest {

using test::findId;
using test::Node;
using test::parseXml;

inline Node parsed(const QByteArray &data)
{
    Node root;
    QString error;
    if (!parseXml(data, &root, &error))
        qWarning("XML does not parse: %s", qPrintable(error));
    return root;
}

inline QStringList idsUnder(const Node &n)
{
    QStringList ids;
    for (const Node &c : n.children) {
        if (c.has(QStringLiteral("id")))
            ids << c.attribute(QStringLiteral("id"));
        ids << idsUnder(c);
    }
    return ids;
}

inline const QRegularExpression &numberPattern()
{
    static const QRegularExpression re(QStringLiteral("-?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?"));
    return re;
}

inline QList<double> numbers(const QString &s)
{
    QList<double> out;
    auto it = numberPattern().globalMatch(s);
    while (it.hasNext())
        out << it.next().captured().toDouble();
    return out;
}

inline QString skeleton(const QString &s)
{
    QString copy = s;
    return copy.replace(numberPattern(), QStringLiteral("#"));
}

inline QString commandLetters(const QString &d)
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
inline bool sameDocument(const Node &a, const Node &b, double tolerance, const QString &path, QString *why)
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

inline const QSize kImage(512, 512);

inline FaceModel testFace()
{
    return averageFace(QRectF(106, 130, 300, 330), kImage);
}

inline Style preset(const char *name)
{
    bool ok = false;
    Style s = Style::preset(QString::fromLatin1(name), &ok);
    Q_ASSERT(ok);
    return s;
}

inline Pose scaled(Pose p, double k)
{
    for (QPointF &o : p.offset)
        o *= k;
    return p;
}

inline QMap<QString, Pose> namedPoses(const FaceModel &face)
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

inline QPolygonF pathPoints(const QString &d)
{
    const QList<double> n = numbers(d);
    QPolygonF p;
    for (qsizetype i = 0; i + 1 < n.size(); i += 2)
        p << QPointF(n[i], n[i + 1]);
    return p;
}

// The paths this renderer writes: absolute M, L, H, V, C, Z.
inline QPainterPath painterPath(const QString &d)
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

inline double area(const QPainterPath &path)
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

inline const FacePart *partById(const QVector<FacePart> &parts, const QString &id)
{
    for (const FacePart &p : parts) {
        if (p.id == id)
            return &p;
    }
    return nullptr;
}
// A pointer into a temporary list would dangle (AddressSanitizer found one).
const FacePart *partById(QVector<FacePart> &&parts, const QString &id) = delete;

inline QByteArray staticLayer(const QByteArray &svg)
{
    const qsizetype start = svg.indexOf("<g id=\"static-layer\">");
    const qsizetype end = svg.indexOf("</g>", start);
    return start >= 0 && end > start ? svg.mid(start, end - start) : QByteArray();
}

inline int colourDistance(QColor a, QColor b)
{
    return std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()), std::abs(a.blue() - b.blue())});
}

inline QColor pixel(const QImage &image, QPointF p)
{
    return image.pixelColor(int(std::floor(p.x())), int(std::floor(p.y())));
}

inline QString goldenPath(const QString &name)
{
    return QStringLiteral(TOONFACE_TEST_DATA "/render/%1.svg").arg(name);
}

inline constexpr char kShirtLayer[]
    = "<?xml version=\"1.0\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"512\" height=\"512\">\n"
      "  <defs><linearGradient id=\"cloth\"><stop offset=\"0\" stop-color=\"#3366cc\"/></linearGradient></defs>\n"
      "  <rect id=\"shirt\" x=\"100\" y=\"470\" width=\"312\" height=\"42\" fill=\"#3366cc\"/>\n"
      "  <use xlink:href=\"#shirt\" x=\"0\" y=\"0\"/>\n"
      "</svg>\n";

} // namespace toonface::svgfacetest
