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

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

using namespace toonface;

namespace {

using test::findId;
using test::Node;
using test::parseXml;

void collect(const Node &n, const QString &name, QList<const Node *> *out)
{
    if (n.name == name)
        out->append(&n);
    for (const Node &c : n.children)
        collect(c, name, out);
}

QList<const Node *> all(const Node &root, const char *name)
{
    QList<const Node *> out;
    collect(root, QString::fromLatin1(name), &out);
    return out;
}

// Drops every animation element and the player (metadata, script, play button).
Node withoutAnimation(Node n)
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

QVector<double> numbersOf(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("[-+]?(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?"));
    QVector<double> out;
    for (auto it = re.globalMatch(text); it.hasNext();)
        out.append(it.next().captured().toDouble());
    return out;
}

int arity(QChar c)
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

std::optional<RawPath> rawPath(const QString &d)
{
    static const QRegularExpression token(
        QStringLiteral("([A-Za-z])|([-+]?(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?)"));
    RawPath p;
    QChar current;
    int owed = 0;
    for (auto it = token.globalMatch(d); it.hasNext();) {
        const auto m = it.next();
        if (!m.captured(1).isEmpty()) {
            if (owed)
                return std::nullopt;
            current = m.captured(1)[0];
            p.commands += current;
            owed = arity(current);
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
        p.numbers.append(m.captured(2).toDouble());
        --owed;
    }
    if (owed)
        return std::nullopt;
    return p;
}

// Absolute coordinates of a path (commands upper-cased).
RawPath absolute(const RawPath &p)
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

double maxDifference(const QVector<double> &a, const QVector<double> &b)
{
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (qsizetype i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

QTransform transformOf(const QString &text)
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
bool isClockValue(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("^[0-9]+(\\.[0-9]+)?s$"));
    return re.match(text).hasMatch();
}

double seconds(const QString &clock)
{
    QString s = clock.trimmed();
    if (s.endsWith(QLatin1Char('s')))
        s.chop(1);
    return s.toDouble();
}

Animation animation(const Node &n)
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
QHash<const Node *, Animation> &animationCache()
{
    static QHash<const Node *, Animation> cache;
    return cache;
}

Animation &cachedAnimation(const Node &n)
{
    auto it = animationCache().find(&n);
    if (it == animationCache().end())
        it = animationCache().insert(&n, animation(n));
    return *it;
}

// The progress of a keySplines curve at time fraction x (solving its x(s) = x by bisection).
double splineAt(const std::array<double, 4> &c, double x)
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

Mix mixAt(const Animation &a, double t)
{
    if (a.values.size() == 1)
        return {0, 0, 0};
    const double f = std::clamp(t / a.dur, 0.0, 1.0);
    if (f >= 1.0)
        return {int(a.values.size()) - 1, int(a.values.size()) - 1, 0};
    int i = 0;
    while (i + 2 < a.keyTimes.size() && a.keyTimes[i + 1] <= f)
        ++i;
    const double x = (f - a.keyTimes[i]) / (a.keyTimes[i + 1] - a.keyTimes[i]);
    return {i, i + 1, a.splines.isEmpty() ? x : splineAt(a.splines[i], x)};
}

// The numbers of attribute `name` of element `e` at time t, with its animations applied;
// paths in absolute coordinates. Sets *why when the values do not fit together.
QVector<double> numbersAt(const Node &e, const QString &name, double t, QString *why)
{
    const bool path = name == QLatin1StringView("d");
    auto parse = [&](const QString &text) -> std::optional<RawPath> {
        if (path)
            return rawPath(text);
        return RawPath {QString(), numbersOf(text)};
    };
    std::optional<RawPath> value = parse(e.attribute(name));
    if (!value) {
        *why = QStringLiteral("bad %1 of %2").arg(name, e.attribute(QStringLiteral("id")));
        return {};
    }
    for (const Node &c : e.children) {
        if (c.name != QLatin1StringView("animate") || c.attribute(QStringLiteral("attributeName")) != name)
            continue;
        Animation &a = cachedAnimation(c);
        const Mix m = mixAt(a, t);
        if (a.parsed.isEmpty()) {
            for (const QString &v : a.values)
                a.parsed.append(parse(v));
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
    return path ? absolute(*value).numbers : value->numbers;
}

QTransform headAt(const Node &head, double t)
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
double transformDistance(const QTransform &a, const QTransform &b)
{
    double worst = 0;
    for (const QPointF p : {QPointF(0, 0), QPointF(512, 0), QPointF(0, 512), QPointF(512, 512), QPointF(256, 256)})
        worst = std::max(worst, QLineF(a.map(p), b.map(p)).length());
    return worst;
}

// The worst distance between the geometry of `parts` and that of the document at time t.
double worstDistance(const Node &doc, const QVector<FacePart> &parts, double t, QString *where)
{
    double worst = 0;
    for (const FacePart &p : parts) {
        const Node *e = findId(doc, p.id);
        if (!e) {
            *where = QStringLiteral("%1 is missing").arg(p.id);
            return std::numeric_limits<double>::infinity();
        }
        for (auto it = p.geometry.cbegin(); it != p.geometry.cend(); ++it) {
            const QVector<double> want = it.key() == QLatin1StringView("d")
                ? absolute(rawPath(it.value()).value_or(RawPath {})).numbers
                : numbersOf(it.value());
            QString why;
            const QVector<double> got = numbersAt(*e, it.key(), t, &why);
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

AnimationExportOptions silent()
{
    AnimationExportOptions o;
    o.audio = ExportAudio::None;
    return o;
}

} // namespace

class TestSmilExport : public QObject
{
    Q_OBJECT

private:
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

private Q_SLOTS:
    void init() { animationCache().clear(); }

    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_wav = m_dir.filePath(QStringLiteral("voice.wav"));
        QVERIFY(test::writeToneWav(m_wav, 10.0));
    }

    void wellFormed_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("audio");
        QTest::newRow("smil, silent") << int(AnimationExportOptions::Mode::Smil) << int(ExportAudio::None);
        QTest::newRow("smil, embedded sound") << int(AnimationExportOptions::Mode::Smil) << int(ExportAudio::Embed);
        QTest::newRow("frames, referenced sound")
            << int(AnimationExportOptions::Mode::Frames) << int(ExportAudio::Reference);
    }

    void wellFormed()
    {
        QFETCH(int, mode);
        QFETCH(int, audio);
        AnimationExportOptions o;
        o.mode = AnimationExportOptions::Mode(mode);
        o.audio = ExportAudio(audio);
        o.outputDir = m_dir.path();
        const QByteArray svg = exported(o);
        QVERIFY(!svg.isEmpty());
        QVERIFY(svg.startsWith("<?xml"));
        Node root;
        QString error;
        QVERIFY2(parseXml(svg, &root, &error), qPrintable(error));
        QCOMPARE(root.name, QStringLiteral("svg"));
        QXmlStreamReader reader(svg);
        reader.readNextStartElement();
        QCOMPARE(reader.namespaceUri(), QStringLiteral("http://www.w3.org/2000/svg"));
    }

    // The same input gives the same bytes (the work is spread over threads).
    void outputIsDeterministic()
    {
        for (auto mode : {AnimationExportOptions::Mode::Smil, AnimationExportOptions::Mode::Frames}) {
            AnimationExportOptions o = silent();
            o.mode = mode;
            QCOMPARE(exported(o), exported(o));
        }
    }

    // Every animation: values over keyTimes from 0 to 1, ascending, one spline per interval,
    // lasting the timeline's duration and frozen at its end.
    void keyTimesAreValid()
    {
        const Node doc = document(exported());
        const double duration = timeline().duration();
        QList<const Node *> animations = all(doc, "animate") + all(doc, "animateTransform");
        QVERIFY(animations.size() > 10);
        for (const Node *n : animations) {
            const Animation a = animation(*n);
            const QString what
                = QStringLiteral("%1 %2").arg(a.attribute, n->attribute(QStringLiteral("values")).left(40));
            QVERIFY2(isClockValue(n->attribute(QStringLiteral("dur"))), qPrintable(what));
            QVERIFY2(std::abs(a.dur - duration) < 1e-6, qPrintable(what));
            QCOMPARE(n->attribute(QStringLiteral("fill")), QStringLiteral("freeze"));
            if (a.values.size() == 1) {
                QVERIFY2(a.keyTimes.isEmpty(), qPrintable(what)); // a constant
                continue;
            }
            QCOMPARE(n->attribute(QStringLiteral("calcMode")), QStringLiteral("spline"));
            QCOMPARE(a.keyTimes.size(), a.values.size());
            QCOMPARE(a.keyTimes.first(), 0.0);
            QCOMPARE(a.keyTimes.last(), 1.0);
            for (qsizetype i = 1; i < a.keyTimes.size(); ++i)
                QVERIFY2(a.keyTimes[i] > a.keyTimes[i - 1], qPrintable(what));
            QCOMPARE(a.splines.size(), a.values.size() - 1);
            for (const auto &s : a.splines) {
                for (double v : s)
                    QVERIFY2(v >= 0 && v <= 1, qPrintable(what));
            }
        }
    }

    // The drawing without its animations is SvgFace's drawing of the pose at time 0.
    void drawingIsSvgFacesAtTimeZero_data()
    {
        QTest::addColumn<QString>("style");
        for (const QString &s : Style::presetNames())
            QTest::newRow(qPrintable(s)) << s;
    }

    void drawingIsSvgFacesAtTimeZero()
    {
        QFETCH(QString, style);
        const Style s = Style::preset(style);
        const Node got = withoutAnimation(document(exported(silent(), s)));
        const TimelineEvaluator evaluator(timeline(), m_face, m_shapes);
        const Node want = document(browserFace(s).svg(evaluator.evaluate(0)));
        const Node *staticGot = findId(got, QStringLiteral("static-layer"));
        const Node *staticWant = findId(want, QStringLiteral("static-layer"));
        QVERIFY(staticGot && staticWant);
        QCOMPARE(staticGot->children.size(), staticWant->children.size());
        for (qsizetype i = 0; i < staticWant->children.size(); ++i) {
            QCOMPARE(staticGot->children[i].name, staticWant->children[i].name);
            QCOMPARE(staticGot->children[i].attributes, staticWant->children[i].attributes);
        }
        // The whole document too, element for element.
        std::function<void(const Node &, const Node &)> same = [&](const Node &a, const Node &b) {
            QCOMPARE(a.name, b.name);
            QCOMPARE(a.attributes, b.attributes);
            QCOMPARE(a.children.size(), b.children.size());
            for (qsizetype i = 0; i < a.children.size(); ++i)
                same(a.children[i], b.children[i]);
        };
        same(got, want);
    }

    // The heart of it: the drawing rebuilt from the SMIL values at any time (frame times and
    // times between frames) is the renderer's drawing of evaluate(t), within 0.15 px.
    void poseRebuiltFromSmilMatchesEvaluator_data()
    {
        QTest::addColumn<QString>("style");
        QTest::addColumn<int>("busySeed"); // 0: the fixture's timeline
        for (const QString &s : Style::presetNames())
            QTest::newRow(qPrintable(s)) << s << 0;
        QTest::newRow("busy 1, normal") << QStringLiteral("normal") << 1;
        QTest::newRow("busy 2, cute") << QStringLiteral("cute") << 2;
    }

    void poseRebuiltFromSmilMatchesEvaluator()
    {
        QFETCH(QString, style);
        QFETCH(int, busySeed);
        const Style s = Style::preset(style);
        const Timeline t = busySeed ? test::busyTimeline(quint32(busySeed), 30.0) : timeline();
        const Node doc = document(exported(silent(), s, t));
        const Node *head = findId(doc, QStringLiteral("head"));
        QVERIFY(head);
        const SvgFace svgFace = browserFace(s);
        const TimelineEvaluator evaluator(t, m_face, m_shapes);
        // Frame times and times between frames; for the busy timelines, random steps of
        // 1-20 ms.
        QVector<double> times;
        std::mt19937 rng(busySeed);
        for (double time = 0; time <= t.duration();) {
            times.append(time);
            if (busySeed)
                time += std::uniform_real_distribution<double>(0.001, 0.02)(rng);
            else
                time += (times.size() % 3 == 0 ? 0.29 : 0.355) / t.frameRate();
        }
        double worst = 0, worstHead = 0;
        QString where;
        for (double time : times) {
            const Pose pose = evaluator.evaluate(time);
            QString here;
            const double d = worstDistance(doc, svgFace.parts(pose), time, &here);
            QVERIFY2(std::isfinite(d), qPrintable(here));
            if (d > worst) {
                worst = d;
                where = here;
            }
            worstHead = std::max(
                worstHead, transformDistance(headAt(*head, time), transformOf(svgFace.headTransform(pose.head))));
        }
        qInfo("%s: %lld times, worst distance %.3f px (%s), head %.3f px", qPrintable(style), qlonglong(times.size()),
            worst, qPrintable(where), worstHead);
        QVERIFY2(worst <= 0.15, qPrintable(QStringLiteral("%1 px at %2").arg(worst).arg(where)));
        QVERIFY2(worstHead <= 0.15, qPrintable(QString::number(worstHead)));
    }

    // Pose key frames (control points dragged on the preview) are animated too: a brow that
    // only they move, and a mouth corner.
    void poseKeysAreAnimated()
    {
        Timeline t;
        t.setFrameRate(25);
        t.addPoseKey({0.5, {{QStringLiteral("8.4"), QPointF(0.15, -0.05)}, {QStringLiteral("4.4"), QPointF(0, -0.1)}}});
        t.addPoseKey({1.5, {{QStringLiteral("8.4"), QPointF(-0.1, 0.05)}}});
        t.addPoseKey({2.5, {}});
        const Style style = Style::preset(QStringLiteral("normal"));
        const Node doc = document(exported(silent(), style, t));
        const SvgFace svgFace = browserFace(style);
        const TimelineEvaluator evaluator(t, m_face, m_shapes);
        double worst = 0;
        QString where;
        for (double time = 0; time <= t.duration(); time += 0.037) {
            QString here;
            const double d = worstDistance(doc, svgFace.parts(evaluator.evaluate(time)), time, &here);
            if (d > worst) {
                worst = d;
                where = here;
            }
        }
        QVERIFY2(worst <= 0.15, qPrintable(QStringLiteral("%1 px at %2").arg(worst).arg(where)));
        // The brow moved: it is animated, not drawn still.
        const Node *brow = findId(doc, QStringLiteral("eyebrow-right"));
        const Node *otherBrow = findId(doc, QStringLiteral("eyebrow-left"));
        QVERIFY(brow && otherBrow);
        const auto animated = [](const Node *e) {
            return std::any_of(e->children.cbegin(), e->children.cend(),
                [](const Node &c) { return c.name == QLatin1StringView("animate"); });
        };
        QVERIFY(animated(brow) != animated(otherBrow));
    }

    // Where an emotion starts without a fade the pose jumps; the animation follows within two
    // milliseconds (a twentieth of a frame).
    void jumpsAreFollowed()
    {
        const Node doc = document(exported());
        const SvgFace svgFace = browserFace(Style::preset(QStringLiteral("normal")));
        const TimelineEvaluator evaluator(timeline(), m_face, m_shapes);
        const double jump = 5.0; // the surprise clip starts at full intensity
        // The ramp is the exporter's shortest span (1 ms, rounded up to whole grid steps): with
        // the stronger emotions a jump is large enough that 1.1 ms before it is inside the ramp.
        for (double time : {jump - 0.002, jump, jump + 0.001}) {
            QString where;
            const double d = worstDistance(doc, svgFace.parts(evaluator.evaluate(time)), time, &where);
            QVERIFY2(d <= 0.15, qPrintable(QStringLiteral("%1 px at %2").arg(d).arg(where)));
        }
    }

    // Parts that move only with some tracks get only those tracks' key times: the eyeballs
    // (gaze: four keys) far fewer than the mouth.
    void keyTimesFollowTheTracksThatMove()
    {
        const Node doc = document(exported());
        auto keys = [&](const char *id, const char *attribute) {
            const Node *e = findId(doc, QString::fromLatin1(id));
            for (const Node &c : e ? e->children : QList<Node>()) {
                if (c.attribute(QStringLiteral("attributeName")) == QLatin1StringView(attribute))
                    return animation(c).keyTimes.size();
            }
            return qsizetype(0);
        };
        const qsizetype mouth = keys("mouth-upper-lip", "d");
        const qsizetype eyeball = keys("eyeball-left", "cx");
        QVERIFY(mouth > 50);
        QVERIFY(eyeball >= 4);
        QVERIFY(eyeball < 20);
        QCOMPARE(keys("hair", "points"), qsizetype(0)); // never moves: not animated
        // The brows move with emotions only.
        const qsizetype brows = keys("eyebrow-left", "points");
        QVERIFY(brows >= 6);
        QVERIFY(brows < mouth / 2);
    }

    void soundIsEmbedded()
    {
        AnimationExportOptions o;
        o.audio = ExportAudio::Embed;
        o.compressAudio = false;
        const QByteArray svg = exported(o);
        const Node doc = document(svg);
        const QList<const Node *> audio = all(doc, "tf:audio");
        QCOMPARE(audio.size(), 1);
        const QString href = audio.first()->attribute(QStringLiteral("href"));
        QVERIFY(href.startsWith(QStringLiteral("data:audio/wav;base64,")));
        QFile wav(m_wav);
        QVERIFY(wav.open(QIODevice::ReadOnly));
        QCOMPARE(QByteArray::fromBase64(href.mid(href.indexOf(QLatin1Char(',')) + 1).toLatin1()), wav.readAll());
        QCOMPARE(audio.first()->attribute(QStringLiteral("offset")).toDouble(), 0.0);
        QCOMPARE(audio.first()->attribute(QStringLiteral("duration")).toDouble(), 10.0);
        // The player: a play button and the script that starts the sound with the animation and
        // keeps the animation on the audio clock.
        QVERIFY(findId(doc, QStringLiteral("tf-play")));
        const QList<const Node *> scripts = all(doc, "script");
        QCOMPARE(scripts.size(), 1);
        for (const char *needle : {"pauseAnimations", "unpauseAnimations", "setCurrentTime", "currentTime", "play()"})
            QVERIFY2(svg.contains(needle), needle);
    }

    // Uncompressed sound is embedded as AAC: far smaller, as long, and in time (a burst that
    // starts at 1 s still starts there: the encoder's priming is accounted for); compressed
    // sound goes in as it is.
    void embeddedSoundIsCompressed_data()
    {
        QTest::addColumn<QString>("suffix");
        QTest::addColumn<QString>("mime");
        QTest::addColumn<bool>("recoded");
        QTest::newRow("wav 44.1 kHz") << QStringLiteral("wav") << QStringLiteral("audio/mp4") << true;
        QTest::newRow("flac") << QStringLiteral("flac") << QStringLiteral("audio/mp4") << true;
        QTest::newRow("mp3") << QStringLiteral("mp3") << QStringLiteral("audio/mpeg") << false;
    }
    void embeddedSoundIsCompressed()
    {
        QFETCH(QString, suffix);
        QFETCH(QString, mime);
        QFETCH(bool, recoded);
        // Silence, then a 440 Hz burst from 1 s to 2 s, then silence to 3 s.
        Audio sound;
        sound.sampleRate = 44100;
        sound.samples.resize(3 * sound.sampleRate);
        for (int i = sound.sampleRate; i < 2 * sound.sampleRate; ++i)
            sound.samples[i] = 0.5f * float(std::sin(2 * std::numbers::pi * 440.0 * i / sound.sampleRate));
        QTemporaryDir dir;
        const QString source = dir.filePath(QStringLiteral("burst.") + suffix);
        QString error;
        QVERIFY2(writeAudio(source, sound, &error), qPrintable(error));
        Timeline t = timeline();
        t.setAudio(AudioClip {source, 0.0, 3.0});
        AnimationExportOptions o;
        o.audio = ExportAudio::Embed;
        QByteArray svg = exportSmilSvg(m_face, Style(), t, m_shapes, o, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));
        const QString href = all(document(svg), "tf:audio").first()->attribute(QStringLiteral("href"));
        QVERIFY2(
            href.startsWith(QStringLiteral("data:") + mime + QStringLiteral(";base64,")), qPrintable(href.left(40)));
        const QByteArray bytes = QByteArray::fromBase64(href.mid(href.indexOf(QLatin1Char(',')) + 1).toLatin1());
        QFile in(source);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray original = in.readAll();
        if (!recoded) {
            QCOMPARE(bytes, original);
            return;
        }
        QVERIFY2(bytes.size() * 2 < original.size(),
            qPrintable(QStringLiteral("%1 of %2 bytes").arg(bytes.size()).arg(original.size())));
        const QString embedded = dir.filePath(QStringLiteral("embedded.m4a"));
        QFile out(embedded);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes);
        out.close();
        const std::optional<MediaInfo> info = probeMedia(embedded, &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->audioCodec, QStringLiteral("aac"));
        QCOMPARE(info->audioChannels, 1);
        QVERIFY2(std::abs(info->audioDurationS - 3.0) < 0.03, qPrintable(QString::number(info->audioDurationS)));
        // The burst's start: the first 1 ms window whose level passes half the burst's.
        const int rate = 16000;
        const std::optional<QVector<float>> decoded = readAudio(embedded, rate, &error);
        QVERIFY2(decoded, qPrintable(error));
        double onset = -1;
        for (qsizetype i = 0; i + rate / 1000 <= decoded->size(); i += rate / 1000) {
            double peak = 0;
            for (qsizetype k = i; k < i + rate / 1000; ++k)
                peak = std::max(peak, double(std::abs((*decoded)[k])));
            if (peak > 0.25) {
                onset = double(i) / rate;
                break;
            }
        }
        qInfo("%s: %lld bytes as %lld bytes of AAC, burst at %.4f s", qPrintable(suffix), qlonglong(original.size()),
            qlonglong(bytes.size()), onset);
        QVERIFY(std::abs(onset - 1.0) <= 0.005);
    }

    void soundIsReferenced()
    {
        QTemporaryDir out;
        QVERIFY(QDir().mkpath(out.filePath(QStringLiteral("clips"))));
        AnimationExportOptions o;
        o.audio = ExportAudio::Reference;
        o.outputDir = out.filePath(QStringLiteral("clips"));
        const QString wav = out.filePath(QStringLiteral("sound files/voice one.wav"));
        QVERIFY(QDir().mkpath(QFileInfo(wav).absolutePath()));
        QVERIFY(QFile::copy(m_wav, wav));
        o.audioPath = wav;
        const Node doc = document(exported(o));
        const QList<const Node *> audio = all(doc, "tf:audio");
        QCOMPARE(audio.size(), 1);
        QCOMPARE(audio.first()->attribute(QStringLiteral("href")), QStringLiteral("../sound%20files/voice%20one.wav"));
    }

    void silentExportHasNoPlayer()
    {
        const QByteArray svg = exported(silent());
        const Node doc = document(svg);
        QVERIFY(all(doc, "tf:audio").isEmpty());
        QVERIFY(all(doc, "script").isEmpty());
        QVERIFY(!findId(doc, QStringLiteral("tf-play")));
        const QList<const Node *> info = all(doc, "tf:animation");
        QCOMPARE(info.size(), 1);
        QCOMPARE(info.first()->attribute(QStringLiteral("duration")).toDouble(), 10.0);
        QCOMPARE(info.first()->attribute(QStringLiteral("fps")).toDouble(), 25.0);
    }

    void badInputIsReported()
    {
        QString error;
        AnimationExportOptions o;
        o.audioPath = m_dir.filePath(QStringLiteral("missing.wav"));
        QVERIFY(exportSmilSvg(m_face, Style(), timeline(), m_shapes, o, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("missing.wav")), qPrintable(error));
        o.audio = ExportAudio::Reference;
        error.clear();
        QVERIFY(exportHtmlPlayer(m_face, Style(), timeline(), m_shapes, o, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("missing.wav")), qPrintable(error));

        const QString layer = m_dir.filePath(QStringLiteral("broken.svg"));
        QFile f(layer);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<svg><g>");
        f.close();
        AnimationExportOptions l = silent();
        l.layerFiles = {layer};
        error.clear();
        QVERIFY(exportSmilSvg(m_face, Style(), timeline(), m_shapes, l, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("broken.svg")), qPrintable(error));
    }

    void layersAreDrawnAboveTheFace()
    {
        const QString layer = m_dir.filePath(QStringLiteral("shirt.svg"));
        QFile f(layer);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect id=\"shirt\" x=\"100\" y=\"450\" width=\"300\" "
                "height=\"62\" fill=\"#36c\"/></svg>");
        f.close();
        AnimationExportOptions o = silent();
        o.layerFiles = {layer};
        for (auto mode : {AnimationExportOptions::Mode::Smil, AnimationExportOptions::Mode::Frames}) {
            o.mode = mode;
            const Node doc = document(exported(o));
            QVERIFY(findId(doc, QStringLiteral("layer-1-shirt"))); // its ids prefixed with the layer's
            QCOMPARE(doc.children.last().attribute(QStringLiteral("id")), QStringLiteral("layer-1"));
        }
    }

    void emptyTimelineIsAStillDrawing()
    {
        Timeline empty;
        const QByteArray svg = exported(silent(), Style::preset(QStringLiteral("normal")), empty);
        const Node doc = document(svg);
        QVERIFY(all(doc, "animate").isEmpty());
        QVERIFY(findId(doc, QStringLiteral("mouth-upper-lip")));
    }

    // Frame mode: one hidden group per frame shown by <set> in its frame's time, the parts
    // that never move drawn once; each frame is the renderer's drawing at its time.
    void frameMode()
    {
        AnimationExportOptions o = silent();
        o.mode = AnimationExportOptions::Mode::Frames;
        const Timeline t = timeline();
        const Node doc = document(exported(o));
        QList<const Node *> frames;
        for (const Node *g : all(doc, "g")) {
            if (g->attribute(QStringLiteral("visibility")) == QLatin1StringView("hidden"))
                frames.append(g);
        }
        QCOMPARE(frames.size(), t.frameCount());
        QCOMPARE(int(std::lround(t.frameRate() * t.duration())), t.frameCount());
        QCOMPARE(all(doc, "polygon").size(), 1); // the hair, shared by every frame
        QVERIFY(all(doc, "animate").isEmpty());

        const SvgFace svgFace(m_face, Style::preset(QStringLiteral("normal")));
        const TimelineEvaluator evaluator(t, m_face, m_shapes);
        for (int i : {0, 1, 48, 125, t.frameCount() - 1}) {
            const Node &frame = *frames[i];
            const Node &set = frame.children.first();
            QCOMPARE(set.name, QStringLiteral("set"));
            QCOMPARE(set.attribute(QStringLiteral("attributeName")), QStringLiteral("visibility"));
            QCOMPARE(set.attribute(QStringLiteral("to")), QStringLiteral("visible"));
            QVERIFY(isClockValue(set.attribute(QStringLiteral("begin"))));
            QVERIFY(isClockValue(set.attribute(QStringLiteral("dur"))));
            QVERIFY(std::abs(seconds(set.attribute(QStringLiteral("begin"))) - i / t.frameRate()) < 1e-6);
            QVERIFY(std::abs(seconds(set.attribute(QStringLiteral("dur"))) - 1 / t.frameRate()) < 1e-6);
            QCOMPARE(set.has(QStringLiteral("fill")), i == t.frameCount() - 1);

            // Rebuild the frame: its own parts (ids suffixed -fN) and the shared ones it uses.
            Node rebuilt;
            const QString suffix = QStringLiteral("-f%1").arg(i);
            std::function<void(const Node &)> gather = [&](const Node &n) {
                for (const Node &c : n.children) {
                    if (c.name == QLatin1StringView("use")
                        && !c.attribute(QStringLiteral("xlink:href")).contains(suffix)) {
                        const Node *shared = findId(doc, c.attribute(QStringLiteral("xlink:href")).mid(1));
                        QVERIFY(shared);
                        gather(*shared);
                        continue;
                    }
                    Node copy = c;
                    for (auto &[k, v] : copy.attributes) {
                        if (k == QLatin1StringView("id") && v.endsWith(suffix))
                            v.chop(suffix.size());
                    }
                    rebuilt.children.append(copy);
                    gather(c);
                }
            };
            gather(frame);
            const QVector<FacePart> parts = svgFace.parts(evaluator.evaluate(i / t.frameRate()));
            QString where;
            const double d = worstDistance(rebuilt, parts, 0, &where);
            QVERIFY2(d <= 0.06, qPrintable(QStringLiteral("frame %1: %2 px at %3").arg(i).arg(d).arg(where)));
            const QList<const Node *> transforms = [&] {
                QList<const Node *> out;
                for (const Node &c : frame.children) {
                    if (c.name == QLatin1StringView("g"))
                        out.append(&c);
                }
                return out;
            }();
            QCOMPARE(transforms.size(), 1);
            QVERIFY(transformDistance(transformOf(transforms.first()->attribute(QStringLiteral("transform"))),
                        transformOf(svgFace.headTransform(evaluator.evaluate(i / t.frameRate()).head)))
                < 0.05);
        }
    }

    // The SMIL form is compact: a few kilobytes a second of talking, far less than frames. (The
    // expression cues, thirteen parts that follow the emotions, took it from under 8 to about
    // 10.7 kB a second on this timeline.)
    void sizesAreReasonable()
    {
        const QByteArray smil = exported();
        AnimationExportOptions o = silent();
        o.mode = AnimationExportOptions::Mode::Frames;
        const QByteArray frames = exported(o);
        const double duration = timeline().duration();
        const double still = SvgFace(m_face, Style::preset(QStringLiteral("normal"))).svg().size();
        qInfo("SMIL %lld bytes, frames %lld bytes, one drawing %.0f bytes, %.0f s", qlonglong(smil.size()),
            qlonglong(frames.size()), still, duration);
        QVERIFY(smil.size() < still + 12000 * duration);
        QVERIFY(frames.size() > 3 * smil.size());
    }

    void progressAndCancel()
    {
        AnimationExportOptions o = silent();
        QVector<double> reported;
        o.progress = [&](double f) { reported.append(f); };
        QVERIFY(!exported(o).isEmpty());
        QVERIFY(!reported.isEmpty());
        QVERIFY(std::is_sorted(reported.cbegin(), reported.cend()));
        QCOMPARE(reported.last(), 1.0);

        std::atomic_bool cancel = true;
        o.cancel = &cancel;
        for (auto mode : {AnimationExportOptions::Mode::Smil, AnimationExportOptions::Mode::Frames}) {
            o.mode = mode;
            QString error;
            QVERIFY(exportSmilSvg(m_face, Style(), timeline(), m_shapes, o, &error).isEmpty());
            QCOMPARE(error, QStringLiteral("cancelled"));
        }
    }

    void htmlPlayer_data()
    {
        QTest::addColumn<int>("audio");
        QTest::newRow("embedded") << int(ExportAudio::Embed);
        QTest::newRow("referenced") << int(ExportAudio::Reference);
        QTest::newRow("silent") << int(ExportAudio::None);
    }

    void htmlPlayer()
    {
        QFETCH(int, audio);
        AnimationExportOptions o;
        o.audio = ExportAudio(audio);
        o.outputDir = m_dir.path();
        QString error;
        const QByteArray html = exportHtmlPlayer(m_face, Style(), timeline(), m_shapes, o, &error);
        QVERIFY2(!html.isEmpty(), qPrintable(error));
        QVERIFY(html.startsWith("<!DOCTYPE html>"));
        // The SVG inline, animated, without its own player.
        const qsizetype from = html.indexOf("<svg");
        const qsizetype to = html.indexOf("</svg>");
        QVERIFY(from > 0 && to > from);
        const Node svg = document(html.mid(from, to + 6 - from));
        QVERIFY(all(svg, "animate").size() > 10);
        QVERIFY(all(svg, "script").isEmpty());
        QVERIFY(!findId(svg, QStringLiteral("tf-play")));
        // Its own controls in every case; the clock paused, set when seeking, corrected on
        // every animation frame (the browser test plays with them).
        for (const char *needle : {"pauseAnimations", "unpauseAnimations", "setCurrentTime", "requestAnimationFrame",
                 "id=\"tf-toggle\"", "id=\"tf-seek\"", "id=\"tf-time\""})
            QVERIFY2(html.contains(needle), needle);
        if (ExportAudio(audio) == ExportAudio::None) {
            QVERIFY(!html.contains("<audio"));
            return;
        }
        // The sound is hidden: the player's controls drive it.
        QVERIFY(html.contains("<audio id=\"tf-audio\" preload=\"auto\" src="));
        QVERIFY(!html.contains("controls src"));
        if (ExportAudio(audio) == ExportAudio::Embed)
            QVERIFY(html.contains("src=\"data:audio/mp4;base64,")); // the WAV compressed
        else
            QVERIFY(html.contains("src=\"voice.wav\""));
    }
};

QTEST_GUILESS_MAIN(TestSmilExport)
#include "tst_smilexport.moc"
