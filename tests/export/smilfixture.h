#pragma once

#include "animationfixture.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/htmlplayer.h"
#include "export/smilexport.h"
#include "face/pose.h"
#include "media/mediareader.h"
#include "render/style.h"
#include "render/svgface.h"
#include "speech/audio.h"
#include "xmltree.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTransform>
#include <QXmlStreamReader>

#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

// What the tests of the SMIL export share: reading the exported SVG back (its elements, paths,
// transforms and SMIL animations, evaluated at any time) and a fixture exporting the test face's
// animation.
namespace toonface::smiltest {

using test::findId;
using test::Node;
using test::parseXml;

inline void collect(const Node &n, const QString &name, QList<const Node *> *out)
{
    if (n.name == name)
        out->append(&n);
    for (const Node &c : n.children)
        collect(c, name, out);
}

inline QList<const Node *> all(const Node &root, const char *name)
{
    QList<const Node *> out;
    collect(root, QString::fromLatin1(name), &out);
    return out;
}

// Drops every animation element and the player (metadata, script, play button).
inline Node withoutAnimation(Node n)
{
    static const QStringList dropped = {QStringLiteral("animate"), QStringLiteral("animateTransform"),
        QStringLiteral("set"), QStringLiteral("metadata"), QStringLiteral("script")};
    n.children.removeIf([](const Node &c) {
        return dropped.contains(c.name) || c.attribute(QStringLiteral("id")) == QLatin1StringView("tf-play");
    });
    for (Node &c : n.children)
        c = withoutAnimation(c);
    return n;
}

// ---- numbers, path data, transforms ----

// The length of the number at text[i] (sign, digits, point, exponent), 0 when none starts there.
inline qsizetype numberLength(QStringView text, qsizetype i)
{
    const qsizetype start = i;
    auto digits = [&] {
        const qsizetype from = i;
        while (i < text.size() && text[i].isDigit())
            ++i;
        return i - from;
    };
    if (i < text.size() && (text[i] == QLatin1Char('-') || text[i] == QLatin1Char('+')))
        ++i;
    qsizetype mantissa = digits();
    if (i < text.size() && text[i] == QLatin1Char('.')) {
        ++i;
        mantissa += digits();
    }
    if (mantissa == 0)
        return 0;
    if (i < text.size() && (text[i] == QLatin1Char('e') || text[i] == QLatin1Char('E'))) {
        qsizetype e = i + 1;
        if (e < text.size() && (text[e] == QLatin1Char('-') || text[e] == QLatin1Char('+')))
            ++e;
        const qsizetype afterSign = e;
        while (e < text.size() && text[e].isDigit())
            ++e;
        if (e > afterSign)
            i = e;
    }
    return i - start;
}

// The number numberLength() found, read with std::from_chars (locale-independent): QString's
// conversion was most of the interpolator's time.
inline double numberAt(QStringView text, qsizetype i, qsizetype n)
{
    char buffer[64];
    if (text[i] == QLatin1Char('+')) {
        ++i;
        --n;
    }
    n = std::min<qsizetype>(n, qsizetype(sizeof buffer));
    for (qsizetype k = 0; k < n; ++k)
        buffer[k] = char(text[i + k].unicode());
    double v = 0;
    std::from_chars(buffer, buffer + n, v);
    return v;
}

// Every number of `text`, in order; anything else separates them. A scanner rather than a
// regular expression: the interpolator reads hundreds of thousands of paths per test.
inline QVector<double> numbersOf(QStringView text)
{
    QVector<double> out;
    for (qsizetype i = 0; i < text.size();) {
        if (const qsizetype n = numberLength(text, i)) {
            out.append(numberAt(text, i, n));
            i += n;
        } else {
            ++i;
        }
    }
    return out;
}

inline int arity(QChar c)
{
    switch (c.toLower().toLatin1()) {
    case 'm':
    case 'l':
    case 't': return 2;
    case 'h':
    case 'v': return 1;
    case 'c': return 6;
    case 's':
    case 'q': return 4;
    default: return 0;
    }
}

// Path data as written: one letter per command (implicit repetitions spelled out) and the
// numbers as they stand.
struct RawPath
{
    QString commands;
    QVector<double> numbers;
};

inline std::optional<RawPath> rawPath(QStringView d)
{
    RawPath p;
    QChar current;
    int owed = 0;
    for (qsizetype i = 0; i < d.size();) {
        const QChar c = d[i];
        if ((c >= QLatin1Char('A') && c <= QLatin1Char('Z')) || (c >= QLatin1Char('a') && c <= QLatin1Char('z'))) {
            if (owed)
                return std::nullopt;
            current = c;
            p.commands += current;
            owed = arity(current);
            ++i;
            continue;
        }
        const qsizetype n = numberLength(d, i);
        if (n == 0) {
            ++i; // a separator
            continue;
        }
        if (!owed) {
            if (current.isNull() || arity(current) == 0)
                return std::nullopt;
            current = current == QLatin1Char('M') ? QLatin1Char('L')
                : current == QLatin1Char('m')     ? QLatin1Char('l')
                                                  : current;
            p.commands += current;
            owed = arity(current);
        }
        p.numbers.append(numberAt(d, i, n));
        i += n;
        --owed;
    }
    if (owed)
        return std::nullopt;
    return p;
}

// Absolute coordinates of a path (commands upper-cased).
inline RawPath absolute(const RawPath &p)
{
    RawPath out;
    double cx = 0, cy = 0, sx = 0, sy = 0;
    qsizetype i = 0;
    for (const QChar c : p.commands) {
        const bool rel = c.isLower();
        const QChar u = c.toUpper();
        out.commands += u;
        const double *v = p.numbers.constData() + i;
        switch (u.toLatin1()) {
        case 'H':
            cx = (rel ? cx : 0) + v[0];
            out.numbers << cx;
            break;
        case 'V':
            cy = (rel ? cy : 0) + v[0];
            out.numbers << cy;
            break;
        case 'Z':
            cx = sx;
            cy = sy;
            break;
        default: {
            const int n = arity(c);
            for (int k = 0; k < n; k += 2)
                out.numbers << (rel ? cx : 0) + v[k] << (rel ? cy : 0) + v[k + 1];
            cx = out.numbers[out.numbers.size() - 2];
            cy = out.numbers.last();
            if (u == QLatin1Char('M')) {
                sx = cx;
                sy = cy;
            }
        }
        }
        i += arity(c);
    }
    return out;
}

inline double maxDifference(const QVector<double> &a, const QVector<double> &b)
{
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (qsizetype i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

inline QTransform transformOf(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("(\\w+)\\(([^)]*)\\)"));
    QTransform t;
    for (auto it = re.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QVector<double> v = numbersOf(m.captured(2));
        if (m.captured(1) == QLatin1StringView("translate"))
            t.translate(v.value(0), v.value(1));
        else if (m.captured(1) == QLatin1StringView("rotate"))
            t.rotate(v.value(0));
        else if (m.captured(1) == QLatin1StringView("scale"))
            t.scale(v.value(0), v.size() > 1 ? v[1] : v.value(0));
    }
    return t;
}

// ---- SMIL, read independently of the exporter ----

struct Animation
{
    QString attribute;
    QString type; // animateTransform
    bool additive = false;
    double dur = 0;
    QVector<double> keyTimes;
    QVector<std::array<double, 4>> splines;
    QStringList values;
    QVector<std::optional<RawPath>> parsed; // the values, read as path data or numbers
};

// SMIL clock values in seconds: digits, an optional fraction, "s".
inline bool isClockValue(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("^[0-9]+(\\.[0-9]+)?s$"));
    return re.match(text).hasMatch();
}

inline double seconds(const QString &clock)
{
    QString s = clock.trimmed();
    if (s.endsWith(QLatin1Char('s')))
        s.chop(1);
    return s.toDouble();
}

inline Animation animation(const Node &n)
{
    Animation a;
    a.attribute = n.attribute(QStringLiteral("attributeName"));
    a.type = n.attribute(QStringLiteral("type"));
    a.additive = n.attribute(QStringLiteral("additive")) == QLatin1StringView("sum");
    a.dur = seconds(n.attribute(QStringLiteral("dur")));
    a.values = n.attribute(QStringLiteral("values")).split(QLatin1Char(';'));
    for (const QString &k : n.attribute(QStringLiteral("keyTimes")).split(QLatin1Char(';'), Qt::SkipEmptyParts))
        a.keyTimes.append(k.toDouble());
    for (const QString &s : n.attribute(QStringLiteral("keySplines")).split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QVector<double> v = numbersOf(s);
        a.splines.append({v.value(0), v.value(1), v.value(2), v.value(3)});
    }
    return a;
}

// Animations parsed once per test (a test's document outlives its use of the cache).
inline QHash<const Node *, Animation> &animationCache()
{
    static QHash<const Node *, Animation> cache;
    return cache;
}

inline Animation &cachedAnimation(const Node &n)
{
    auto it = animationCache().find(&n);
    if (it == animationCache().end())
        it = animationCache().insert(&n, animation(n));
    return *it;
}

// An attribute of an element: its value as written, its animation elements, and the scale
// the element's own transform draws it at (ownScale(); scaleProblem: why that is not a scale).
struct AnimatedAttribute
{
    std::optional<RawPath> value;
    QVector<const Node *> animations;
    double scale = 1;
    QString scaleProblem;
};

// The progress of a keySplines curve at time fraction x (solving its x(s) = x by bisection).
inline double splineAt(const std::array<double, 4> &c, double x)
{
    auto bezier = [](double p1, double p2, double s) {
        return 3 * s * (1 - s) * (1 - s) * p1 + 3 * s * s * (1 - s) * p2 + s * s * s;
    };
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; ++i) {
        const double mid = (lo + hi) / 2;
        (bezier(c[0], c[2], mid) < x ? lo : hi) = mid;
    }
    return bezier(c[1], c[3], (lo + hi) / 2);
}

// Which two values an animation mixes at time t, and how (fill="freeze" after the end).
struct Mix
{
    int from, to;
    double progress;
};

inline Mix mixAt(const Animation &a, double t)
{
    if (a.values.size() == 1)
        return {0, 0, 0};
    const double f = std::clamp(t / a.dur, 0.0, 1.0);
    if (f >= 1.0)
        return {int(a.values.size()) - 1, int(a.values.size()) - 1, 0};
    // The last key time at or before f (keyTimes ascend from 0), and never the last key.
    const auto after = std::upper_bound(a.keyTimes.cbegin(), a.keyTimes.cend(), f);
    const int i = int(std::max<qsizetype>(0, std::min(after - a.keyTimes.cbegin() - 1, a.keyTimes.size() - 2)));
    const double x = (f - a.keyTimes[i]) / (a.keyTimes[i + 1] - a.keyTimes[i]);
    return {i, i + 1, a.splines.isEmpty() ? x : splineAt(a.splines[i], x)};
}

// The uniform scale an element's own transform draws it at (an element written in fifths of a
// pixel carries scale(.2)); 1 without one. Sets *why for any other transform, which the export
// never writes on a part.
inline double ownScale(const Node &e, QString *why)
{
    const QString text = e.attribute(QStringLiteral("transform"));
    if (text.isEmpty())
        return 1;
    const QTransform m = transformOf(text);
    if (m.type() != QTransform::TxScale || m.m11() != m.m22()) {
        *why = QStringLiteral("%1 has transform %2").arg(e.attribute(QStringLiteral("id")), text);
        return 1;
    }
    return m.m11();
}

inline std::optional<RawPath> attributeNumbers(const QString &name, const QString &text)
{
    if (name == QLatin1StringView("d"))
        return rawPath(text);
    return RawPath {QString(), numbersOf(text)};
}

inline AnimatedAttribute readAttribute(const Node &e, const QString &name)
{
    AnimatedAttribute read {attributeNumbers(name, e.attribute(name)), {}, 1, {}};
    read.scale = ownScale(e, &read.scaleProblem);
    for (const Node &c : e.children) {
        if (c.name == QLatin1StringView("animate") && c.attribute(QStringLiteral("attributeName")) == name)
            read.animations.append(&c);
    }
    return read;
}

// The numbers of attribute `name` of element `e` (read as `read`) at time t, with its
// animations applied; paths in absolute coordinates. Sets *why when the values do not fit
// together.
inline QVector<double> numbersAt(
    const Node &e, const QString &name, const AnimatedAttribute &read, double t, QString *why)
{
    std::optional<RawPath> value = read.value;
    if (!value) {
        *why = QStringLiteral("bad %1 of %2").arg(name, e.attribute(QStringLiteral("id")));
        return {};
    }
    for (const Node *c : read.animations) {
        Animation &a = cachedAnimation(*c);
        const Mix m = mixAt(a, t);
        if (a.parsed.isEmpty()) {
            for (const QString &v : a.values)
                a.parsed.append(attributeNumbers(name, v));
        }
        const auto &from = a.parsed[m.from];
        const auto &to = a.parsed[m.to];
        // Browsers interpolate and add path data number by number, so the commands must match.
        if (!from || !to || from->commands != value->commands || to->commands != value->commands
            || from->numbers.size() != value->numbers.size() || to->numbers.size() != value->numbers.size()) {
            *why = QStringLiteral("%1 of %2: values do not match the attribute's structure")
                       .arg(name, e.attribute(QStringLiteral("id")));
            return {};
        }
        for (qsizetype j = 0; j < value->numbers.size(); ++j) {
            const double v = from->numbers[j] + (to->numbers[j] - from->numbers[j]) * m.progress;
            value->numbers[j] = a.additive ? value->numbers[j] + v : v;
        }
    }
    QVector<double> out = name == QLatin1StringView("d") ? absolute(*value).numbers : value->numbers;
    if (!read.scaleProblem.isEmpty())
        *why = read.scaleProblem;
    for (double &x : out)
        x *= read.scale;
    return out;
}

inline QVector<double> numbersAt(const Node &e, const QString &name, double t, QString *why)
{
    return numbersAt(e, name, readAttribute(e, name), t, why);
}

// A document read for the interpolator: its elements by id and their attributes, each read
// once, since worstDistance() reads every part at thousands of times. It points into `doc`,
// which must outlive it and stay unchanged.
class SmilDocument
{
public:
    explicit SmilDocument(const Node &doc) { index(doc); }
    const Node *find(const QString &id) const { return m_ids.value(id); }
    const AnimatedAttribute &attribute(const Node &e, const QString &name) const
    {
        auto it = m_attributes.find({&e, name});
        if (it == m_attributes.end())
            it = m_attributes.insert({&e, name}, readAttribute(e, name));
        return *it;
    }

private:
    void index(const Node &n)
    {
        const QString id = n.attribute(QStringLiteral("id"));
        if (!id.isEmpty() && !m_ids.contains(id))
            m_ids.insert(id, &n); // the first in document order, as findId()
        for (const Node &c : n.children)
            index(c);
    }

    QHash<QString, const Node *> m_ids;
    mutable QHash<QPair<const Node *, QString>, AnimatedAttribute> m_attributes;
};

inline QTransform headAt(const Node &head, double t)
{
    QTransform m = transformOf(head.attribute(QStringLiteral("transform")));
    for (const Node &c : head.children) {
        if (c.name != QLatin1StringView("animateTransform"))
            continue;
        const Animation &a = cachedAnimation(c);
        const Mix mix = mixAt(a, t);
        const QVector<double> from = numbersOf(a.values[mix.from]);
        const QVector<double> to = numbersOf(a.values[mix.to]);
        QVector<double> v(from.size());
        for (qsizetype j = 0; j < v.size(); ++j)
            v[j] = from[j] + (to.value(j) - from[j]) * mix.progress;
        if (!a.additive)
            m.reset();
        if (a.type == QLatin1StringView("translate"))
            m.translate(v.value(0), v.value(1));
        else if (a.type == QLatin1StringView("rotate"))
            m.rotate(v.value(0));
        else if (a.type == QLatin1StringView("scale"))
            m.scale(v.value(0), v.size() > 1 ? v[1] : v.value(0));
    }
    return m;
}

// How far apart two transforms carry the canvas corners and centre.
inline double transformDistance(const QTransform &a, const QTransform &b)
{
    double worst = 0;
    for (const QPointF p : {QPointF(0, 0), QPointF(512, 0), QPointF(0, 512), QPointF(512, 512), QPointF(256, 256)})
        worst = std::max(worst, QLineF(a.map(p), b.map(p)).length());
    return worst;
}

// The worst distance between the geometry of `parts` and that of the document at time t.
inline double worstDistance(const SmilDocument &doc, const QVector<FacePart> &parts, double t, QString *where)
{
    double worst = 0;
    for (const FacePart &p : parts) {
        const Node *e = doc.find(p.id);
        if (!e) {
            *where = QStringLiteral("%1 is missing").arg(p.id);
            return std::numeric_limits<double>::infinity();
        }
        // A circle of radius 0 draws nothing: where it is then does not matter (smilhidden.h),
        // only that its radius is 0.
        static const QStringList radii {QStringLiteral("r"), QStringLiteral("rx"), QStringLiteral("ry")};
        const bool hidden = std::any_of(radii.cbegin(), radii.cend(),
            [&](const QString &r) { return p.geometry.contains(r) && numbersOf(p.geometry.value(r)).value(0) <= 0; });
        for (auto it = p.geometry.cbegin(); it != p.geometry.cend(); ++it) {
            if (hidden && !radii.contains(it.key()))
                continue;
            const QVector<double> want = it.key() == QLatin1StringView("d")
                ? absolute(rawPath(it.value()).value_or(RawPath {})).numbers
                : numbersOf(it.value());
            QString why;
            const QVector<double> got = numbersAt(*e, it.key(), doc.attribute(*e, it.key()), t, &why);
            if (!why.isEmpty()) {
                *where = why;
                return std::numeric_limits<double>::infinity();
            }
            const double d = maxDifference(got, want);
            if (d > worst) {
                worst = d;
                *where = QStringLiteral("%1 %2 at %3 s").arg(p.id, it.key()).arg(t);
            }
        }
    }
    return worst;
}

inline double worstDistance(const Node &doc, const QVector<FacePart> &parts, double t, QString *where)
{
    return worstDistance(SmilDocument(doc), parts, t, where);
}

inline AnimationExportOptions silent()
{
    AnimationExportOptions o;
    o.audio = ExportAudio::None;
    return o;
}

// The test face, its animation with a tone as its sound, and the export of it.
class SmilExportFixture : public QObject
{
protected:
    QTemporaryDir m_dir;
    QString m_wav;
    FaceModel m_face = test::animationFace();
    MouthShapeSet m_shapes;

    // The drawing a Smil-mode export animates: SvgFace's, without the eye covers.
    SvgFace browserFace(const Style &style) const
    {
        SvgFace f(m_face, style);
        f.setEyeCovers(false);
        return f;
    }

    Timeline timeline() const { return test::animationTimeline(m_wav); }

    QByteArray exported(const AnimationExportOptions &options = silent(),
        const Style &style = Style::preset(QStringLiteral("normal")), std::optional<Timeline> t = std::nullopt) const
    {
        QString error;
        const QByteArray svg = exportSmilSvg(m_face, style, t ? *t : timeline(), m_shapes, options, &error);
        if (svg.isEmpty())
            qWarning("export failed: %s", qPrintable(error));
        return svg;
    }

    static Node document(const QByteArray &svg)
    {
        Node root;
        QString error;
        if (!parseXml(svg, &root, &error))
            qWarning("not XML: %s", qPrintable(error));
        return root;
    }

    bool prepare()
    {
        if (!m_dir.isValid())
            return false;
        m_wav = m_dir.filePath(QStringLiteral("voice.wav"));
        return test::writeToneWav(m_wav, 10.0);
    }
};

} // namespace toonface::smiltest
