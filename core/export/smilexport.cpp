#include "export/smilexport.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/videoencoder.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "render/svgface.h"
#include "speech/audio.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QMap>
#include <QMimeDatabase>
#include <QTemporaryDir>
#include <QUrl>
#include <QXmlStreamReader>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <numeric>
#include <span>
#include <vector>

namespace toonface {

namespace {

constexpr const char *kNamespace = "urn:toonface:animation:1";

bool cancelled(const AnimationExportOptions &options)
{
    return options.cancel && options.cancel->load();
}

void report(const AnimationExportOptions &options, double fraction)
{
    if (options.progress)
        options.progress(std::clamp(fraction, 0.0, 1.0));
}

// Runs f(i) for i in [0, n) on the global thread pool (inline for small n).
template<class F>
void forEachParallel(qsizetype n, const F &f)
{
    if (n < 16) {
        for (qsizetype i = 0; i < n; ++i)
            f(i);
        return;
    }
    std::vector<qsizetype> indices(static_cast<size_t>(n));
    std::iota(indices.begin(), indices.end(), qsizetype(0));
    QtConcurrent::blockingMap(indices, [&f](qsizetype &i) { f(i); });
}

// ---- numbers in attribute text ----

// Every number of `text`, in order (locale-independent). Letters other than exponents go to
// *letters when given.
void parseNumbers(QByteArrayView text, QVector<double> *numbers, QByteArray *letters = nullptr)
{
    const char *p = text.data();
    const char *end = p + text.size();
    while (p < end) {
        const char c = *p;
        if ((c >= '0' && c <= '9') || c == '-' || c == '.' || c == '+') {
            double v = 0;
            const char *from = c == '+' ? p + 1 : p;
            const auto [next, ec] = std::from_chars(from, end, v);
            if (ec == std::errc() && next > from) {
                numbers->append(v);
                p = next;
                continue;
            }
        } else if (letters && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) {
            letters->append(c);
        }
        ++p;
    }
}

// How many numbers follow an SVG path command letter.
int pathArity(char command)
{
    switch (command | 0x20) { // lower case
    case 'm':
    case 'l':
    case 't': return 2;
    case 'h':
    case 'v': return 1;
    case 'c': return 6;
    case 's':
    case 'q': return 4;
    case 'a': return 7;
    default: return 0;
    }
}

// Path data as one command letter per command (implicit repetitions written out: the
// numbers after M beyond its first pair are L's) and its numbers. False when malformed.
bool parsePath(QByteArrayView d, QVector<double> *numbers, QByteArray *commands)
{
    const char *p = d.data();
    const char *end = p + d.size();
    char current = 0;
    int pending = 0; // numbers still owed to the current command
    while (p < end) {
        const char c = *p;
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) {
            if (pending != 0 || (pathArity(c) == 0 && (c | 0x20) != 'z'))
                return false;
            current = c;
            commands->append(c);
            pending = pathArity(c);
            ++p;
            continue;
        }
        if ((c >= '0' && c <= '9') || c == '-' || c == '.' || c == '+') {
            double v = 0;
            const char *from = c == '+' ? p + 1 : p;
            const auto [next, ec] = std::from_chars(from, end, v);
            if (ec != std::errc() || next == from)
                return false;
            if (pending == 0) {
                // An implicit repetition of the current command.
                if (current == 0 || pathArity(current) == 0)
                    return false;
                current = current == 'M' ? 'L' : current == 'm' ? 'l' : current;
                commands->append(current);
                pending = pathArity(current);
            }
            numbers->append(v);
            --pending;
            p = next;
            continue;
        }
        ++p; // separators
    }
    return pending == 0;
}

constexpr qint64 kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};

// n units of 10^-decimals as the shortest decimal text: no trailing zeros, no zero before the
// point (".5"), never "-0".
void appendFixed(QByteArray &out, qint64 n, int decimals)
{
    char buf[32];
    int len = 0;
    if (n < 0) {
        out += '-';
        n = -n;
    }
    const qint64 scale = kPow10[decimals];
    qint64 whole = n / scale;
    qint64 frac = n % scale;
    if (whole != 0 || frac == 0) {
        do {
            buf[len++] = char('0' + whole % 10);
            whole /= 10;
        } while (whole > 0);
        while (len > 0)
            out += buf[--len];
    }
    if (frac != 0) {
        int digits = decimals;
        while (frac % 10 == 0) {
            frac /= 10;
            --digits;
        }
        out += '.';
        for (int i = digits - 1; i >= 0; --i) {
            buf[i] = char('0' + frac % 10);
            frac /= 10;
        }
        out.append(buf, digits);
    }
}

qint64 quantize(double v, int decimals)
{
    if (!std::isfinite(v))
        return 0;
    return std::llround(std::clamp(v, -1e9, 1e9) * double(kPow10[decimals]));
}

// A SMIL clock value: unlike a number, it needs a digit before the point ("0.04s").
QByteArray seconds(double s)
{
    QByteArray out;
    appendFixed(out, quantize(s, 6), 6);
    if (out.startsWith('.'))
        out.prepend('0');
    out += 's';
    return out;
}

// Numbers joined as tightly as SVG path grammar allows: no separator before a minus sign, nor
// before a leading point after a number that already has one.
class PathWriter
{
public:
    explicit PathWriter(QByteArray &out)
        : m_out(out)
    { }
    void command(char c)
    {
        m_out += c;
        m_needSeparator = false;
    }
    void number(qint64 n, int decimals)
    {
        const qsizetype at = m_out.size();
        appendFixed(m_out, n, decimals);
        const char first = m_out.at(at);
        const bool joined = first == '-' || (first == '.' && m_lastHasPoint);
        if (m_needSeparator && !joined)
            m_out.insert(at, ' ');
        m_lastHasPoint = m_out.indexOf('.', at) >= 0;
        m_needSeparator = true;
    }

private:
    QByteArray &m_out;
    bool m_needSeparator = false;
    bool m_lastHasPoint = false;
};

// Path data from absolute numbers (already quantized): relative commands after the first
// moveto, which keeps the numbers short; quantizing the absolute coordinates first keeps the
// relative ones from accumulating rounding errors.
void appendRelativePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals)
{
    PathWriter w(out);
    qint64 cx = 0, cy = 0, sx = 0, sy = 0;
    qsizetype i = 0;
    for (qsizetype k = 0; k < commands.size(); ++k) {
        const char c = commands[k];
        switch (c) {
        case 'M':
            if (k == 0) {
                w.command('M');
                w.number(v[i], decimals);
                w.number(v[i + 1], decimals);
            } else {
                w.command('m');
                w.number(v[i] - cx, decimals);
                w.number(v[i + 1] - cy, decimals);
            }
            cx = sx = v[i];
            cy = sy = v[i + 1];
            i += 2;
            break;
        case 'L':
            w.command('l');
            w.number(v[i] - cx, decimals);
            w.number(v[i + 1] - cy, decimals);
            cx = v[i];
            cy = v[i + 1];
            i += 2;
            break;
        case 'C':
            w.command('c');
            for (int j = 0; j < 3; ++j) {
                w.number(v[i + 2 * j] - cx, decimals);
                w.number(v[i + 2 * j + 1] - cy, decimals);
            }
            cx = v[i + 4];
            cy = v[i + 5];
            i += 6;
            break;
        case 'H':
            w.command('h');
            w.number(v[i] - cx, decimals);
            cx = v[i];
            i += 1;
            break;
        case 'V':
            w.command('v');
            w.number(v[i] - cy, decimals);
            cy = v[i];
            i += 1;
            break;
        default: // Z
            w.command('z');
            cx = sx;
            cy = sy;
            break;
        }
    }
}

void appendAbsolutePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals)
{
    PathWriter w(out);
    qsizetype i = 0;
    for (const char c : commands) {
        w.command(c);
        for (int j = pathArity(c); j > 0; --j)
            w.number(v[i++], decimals);
    }
}

// Commands appendRelativePath() can rewrite.
bool relativeWritable(const QByteArray &commands)
{
    return !commands.isEmpty() && commands[0] == 'M'
        && std::all_of(commands.begin(), commands.end(), [](char c) { return QByteArrayView("MLCHVZ").contains(c); });
}

// ---- what moves ----

enum class ChannelKind { Path, Points, Number, Translate, Rotate, Scale };

// One animated attribute: the geometry attribute of a part, or one transform of the head.
struct Channel
{
    ChannelKind kind = ChannelKind::Number;
    int part = -1; // index into SvgFace::parts(); -1 for the head
    QString attribute; // the geometry attribute ("d", "cx", "points") for parts
    QByteArray commands; // Path: one letter per command
    // Parts: the numbers of the attribute as written in the document (at time 0). Their
    // animations are additive: values are offsets from these, so numbers that never move are
    // written as 0.
    QVector<double> base;
    int size = 0; // numbers
    int decimals = 1; // written to 10^-decimals
    double weight = 1; // pixels per unit of its numbers
    Tracks tracks;
};

// Reads the numbers of channel `c` from one drawing into out[0 .. c.size).
bool readChannel(const Channel &c, const QVector<FacePart> &parts, const QVector<double> &head, double *out)
{
    switch (c.kind) {
    case ChannelKind::Translate:
        out[0] = head[0];
        out[1] = head[1];
        return true;
    case ChannelKind::Rotate: out[0] = head[2]; return true;
    case ChannelKind::Scale: out[0] = head[3]; return true;
    default: break;
    }
    const QByteArray text = parts[c.part].geometry.value(c.attribute).toLatin1();
    QVector<double> numbers;
    numbers.reserve(c.size);
    if (c.kind == ChannelKind::Path) {
        QByteArray commands;
        if (!parsePath(text, &numbers, &commands) || commands != c.commands)
            return false;
    } else {
        parseNumbers(text, &numbers);
    }
    if (numbers.size() != c.size)
        return false;
    std::copy(numbers.cbegin(), numbers.cend(), out);
    return true;
}

// The transform of <g id="head">: translate(x,y) rotate(a) scale(s) translate(-cx,-cy).
bool headNumbers(const SvgFace &svg, const HeadPose &head, QVector<double> *out)
{
    out->clear();
    parseNumbers(svg.headTransform(head).toLatin1(), out);
    return out->size() == 6;
}

// Samples the timeline's drawing: the numbers of chosen channels at a time.
class Sampler
{
public:
    Sampler(
        const SvgFace &svg, const TimelineEvaluator &evaluator, const QVector<Channel> &channels, qsizetype partCount)
        : m_svg(svg)
        , m_evaluator(evaluator)
        , m_channels(channels)
        , m_partCount(partCount)
    { }

    // The numbers of channels `which` at time t, one after another. False when the drawing's
    // structure differs from the one at time 0.
    bool sample(double t, const QVector<int> &which, double *out) const
    {
        const Pose pose = m_evaluator.evaluate(t);
        bool needParts = false, needHead = false;
        for (int c : which)
            (m_channels[c].part < 0 ? needHead : needParts) = true;
        QVector<FacePart> parts;
        if (needParts) {
            parts = m_svg.parts(pose);
            if (parts.size() != m_partCount)
                return false;
        }
        QVector<double> head;
        if (needHead && !headNumbers(m_svg, pose.head, &head))
            return false;
        for (int c : which) {
            if (!readChannel(m_channels[c], parts, head, out))
                return false;
            out += m_channels[c].size;
        }
        return true;
    }

private:
    const SvgFace &m_svg;
    const TimelineEvaluator &m_evaluator;
    const QVector<Channel> &m_channels;
    qsizetype m_partCount;
};

// The channels of a drawing: every numeric geometry attribute of every part, and the head.
QVector<Channel> makeChannels(const QVector<FacePart> &parts, const QVector<double> &neutralHead, QRectF canvas)
{
    QVector<Channel> channels;
    for (qsizetype i = 0; i < parts.size(); ++i) {
        const FacePart &part = parts[i];
        for (auto it = part.geometry.cbegin(); it != part.geometry.cend(); ++it) {
            const QByteArray text = it.value().toLatin1();
            Channel c;
            c.part = int(i);
            c.attribute = it.key();
            QVector<double> numbers;
            if (it.key() == QLatin1StringView("d")) {
                if (!parsePath(text, &numbers, &c.commands))
                    continue;
                c.kind = ChannelKind::Path;
            } else {
                QByteArray letters;
                parseNumbers(text, &numbers, &letters);
                if (!letters.isEmpty() || numbers.isEmpty())
                    continue; // not geometry that can move (fill-rule, ...)
                c.kind = numbers.size() == 1 ? ChannelKind::Number : ChannelKind::Points;
            }
            c.size = int(numbers.size());
            c.base = numbers;
            channels.append(c);
        }
    }
    // The head turns and scales about its centre: an angle or scale error moves points by
    // up to the farthest corner's distance from it.
    const QPointF centre(neutralHead[0], neutralHead[1]);
    double reach = 1;
    for (const QPointF corner : {canvas.topLeft(), canvas.topRight(), canvas.bottomLeft(), canvas.bottomRight()})
        reach = std::max(reach, std::hypot(corner.x() - centre.x(), corner.y() - centre.y()));
    auto decimalsFor = [](double weight) { return std::clamp(int(std::ceil(std::log10(weight / 0.1))), 1, 8); };
    Channel translate;
    translate.kind = ChannelKind::Translate;
    translate.size = 2;
    Channel rotate;
    rotate.kind = ChannelKind::Rotate;
    rotate.size = 1;
    rotate.weight = reach * std::numbers::pi / 180.0;
    rotate.decimals = decimalsFor(rotate.weight);
    Channel scale;
    scale.kind = ChannelKind::Scale;
    scale.size = 1;
    scale.weight = reach;
    scale.decimals = decimalsFor(scale.weight);
    for (Channel *c : {&translate, &rotate, &scale}) {
        c->tracks = Track::Head;
        channels.append(*c);
    }
    return channels;
}

// Which tracks move each part channel, found by drawing probe poses of every track the
// timeline uses, on the neutral face and on one pose of every other track (so a dependency
// that shows only in combination, say an eyeball reaching past a shut lid, is found too).
void findTracks(QVector<Channel> &channels, const SvgFace &svg, const Timeline &timeline, const MouthShapeSet &shapes)
{
    const FaceModel &face = svg.face();
    struct Probe
    {
        Track track;
        Pose pose;
    };
    QVector<Probe> probes;
    if (!timeline.mouthKeys().isEmpty()) {
        for (MouthShape s : kAllMouthShapes)
            probes.append({Track::Mouth, mouthPose(face, shapes, s)});
    }
    QVector<Emotion> emotions;
    for (const EmotionClip &clip : timeline.emotionClips()) {
        if (!emotions.contains(clip.emotion))
            emotions.append(clip.emotion);
    }
    for (Emotion e : emotions)
        probes.append({Track::Emotion, emotionPose(face, e, 1.0)});
    if (!timeline.blinks().isEmpty()) {
        for (double open : {0.0, 0.5}) {
            Pose p;
            p.leftEyeOpen = p.rightEyeOpen = open;
            probes.append({Track::Blink, p});
        }
    }
    if (!timeline.gazeKeys().isEmpty()) {
        const double es0 = face.fapu().es0;
        const auto &keys = timeline.gazeKeys();
        auto extreme = [&](auto less) { return std::min_element(keys.cbegin(), keys.cend(), less)->offsetEs0; };
        const QPointF offsets[] = {extreme([](auto &a, auto &b) { return a.offsetEs0.x() < b.offsetEs0.x(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.x() > b.offsetEs0.x(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.y() < b.offsetEs0.y(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.y() > b.offsetEs0.y(); })};
        for (const QPointF &g : offsets) {
            Pose p;
            p.offset[pt::idx("3.6")] = g * es0;
            p.offset[pt::idx("3.5")] = g * es0;
            probes.append({Track::Gaze, p});
        }
    }

    QVector<std::pair<Track, Pose>> bases {{Track(0), Pose {}}};
    for (const Probe &p : probes) {
        if (std::none_of(bases.cbegin(), bases.cend(), [&](const auto &b) { return b.first == p.track; }))
            bases.append({p.track, p.pose});
    }
    for (const auto &[baseTrack, base] : bases) {
        const QVector<FacePart> before = svg.parts(base);
        for (const Probe &probe : probes) {
            if (probe.track == baseTrack)
                continue;
            const QVector<FacePart> after = svg.parts(base + probe.pose);
            if (after.size() != before.size())
                continue;
            for (Channel &c : channels) {
                if (c.part >= 0
                    && after[c.part].geometry.value(c.attribute) != before[c.part].geometry.value(c.attribute))
                    c.tracks |= probe.track;
            }
        }
    }
}

// ---- key times and values ----

// Animation time on a grid of duration / 10^digits, at most 0.1 ms: keyTimes are then exact
// decimal fractions of `digits` digits. Key times move to the grid; an ease cut or extended
// by so little keeps a timing that writes as the whole ease's to keySplines' three decimals.
struct Grid
{
    explicit Grid(double duration)
        : duration(duration)
        , digits(std::clamp(int(std::ceil(std::log10(std::max(duration, 1e-3) * 1e4))), 3, 9))
        , steps(kPow10[digits])
    { }
    double time(qint64 n) const { return duration * double(n) / double(steps); }
    qint64 snap(double t) const
    {
        return std::clamp(qint64(std::llround(t / duration * double(steps))), qint64(0), steps);
    }

    double duration;
    int digits;
    qint64 steps;
};

// The timing curve of one interval: the cubic Bezier (0,0) (1/3,y1) (2/3,y2) (1,1). Its x is
// the time fraction itself, so the progress is the cubic 3x(1-x)^2 y1 + 3x^2(1-x) y2 + x^3.
struct Timing
{
    double y1 = 1.0 / 3.0;
    double y2 = 2.0 / 3.0;
    double at(double x) const { return 3 * x * (1 - x) * ((1 - x) * y1 + x * y2) + x * x * x; }
};

// The part [u0, u1] of the ease 3u^2 - 2u^3, as a timing curve (exact: a piece of a cubic is
// a cubic).
Timing easeTiming(double u0, double u1)
{
    auto y = [](double u) { return u * u * (3 - 2 * u); };
    auto slope = [](double u) { return 6 * u * (1 - u); };
    const double du = u1 - u0;
    const double dy = y(u1) - y(u0);
    if (!(dy > 1e-12))
        return {};
    return {std::clamp(slope(u0) * du / (3 * dy), 0.0, 1.0), std::clamp(1 - slope(u1) * du / (3 * dy), 0.0, 1.0)};
}

// A stretch of time on which a channel follows its end values along one timing.
struct Piece
{
    qint64 a, b;
    Timing timing;
};

// The samples of one group of channels, one row of numbers per grid time.
class SampleTable
{
public:
    explicit SampleTable(int width)
        : m_width(width)
    { }
    // The row of time n, valid until the next add().
    const double *row(qint64 n) const { return m_data.constData() + qsizetype(m_rows.value(n)) * m_width; }

    // Samples the times not yet sampled, in parallel.
    bool add(QVector<qint64> times, const Sampler &sampler, const QVector<int> &which, const Grid &grid)
    {
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        times.removeIf([&](qint64 n) { return m_rows.contains(n); });
        const qsizetype first = m_data.size() / m_width;
        m_data.resize((first + times.size()) * m_width);
        std::atomic_bool ok = true;
        double *data = m_data.data();
        forEachParallel(times.size(), [&](qsizetype i) {
            if (!sampler.sample(grid.time(times[i]), which, data + (first + i) * m_width))
                ok = false;
        });
        for (qsizetype i = 0; i < times.size(); ++i)
            m_rows.insert(times[i], int(first + i));
        return ok;
    }

private:
    int m_width;
    QHash<qint64, int> m_rows;
    QVector<double> m_data;
};

// Samples inside a span and the time fractions at which they are.
struct Checks
{
    int count = 0;
    std::array<const double *, 15> rows;
    std::array<double, 15> x;
};

// The numbers [from, to) of a group's rows, with their weights (pixels per unit).
struct Slice
{
    int from, to;
    const QVector<double> &weights;
};

// The largest weighted distance between the check samples and what the timing gives them
// from the span's end values.
double timingError(const Timing &timing, const double *a, const double *b, const Checks &checks, const Slice &s)
{
    double worst = 0;
    for (int k = 0; k < checks.count; ++k) {
        const double p = timing.at(checks.x[k]);
        const double *c = checks.rows[k];
        for (int j = s.from; j < s.to; ++j)
            worst = std::max(worst, s.weights[j] * std::abs(a[j] + (b[j] - a[j]) * p - c[j]));
    }
    return worst;
}

// The timing that fits the check samples best (weighted least squares on y1, y2), clamped to
// the [0, 1] that keySplines allows.
Timing fittedTiming(const double *a, const double *b, const Checks &checks, const Slice &s)
{
    double m11 = 0, m12 = 0, m22 = 0, r1 = 0, r2 = 0;
    for (int k = 0; k < checks.count; ++k) {
        const double x = checks.x[k];
        const double b1 = 3 * x * (1 - x) * (1 - x);
        const double b2 = 3 * x * x * (1 - x);
        double dd = 0, dr = 0;
        for (int j = s.from; j < s.to; ++j) {
            const double w2 = s.weights[j] * s.weights[j];
            const double d = b[j] - a[j];
            dd += w2 * d * d;
            dr += w2 * d * (checks.rows[k][j] - a[j] - d * x * x * x);
        }
        m11 += dd * b1 * b1;
        m12 += dd * b1 * b2;
        m22 += dd * b2 * b2;
        r1 += dr * b1;
        r2 += dr * b2;
    }
    const double det = m11 * m22 - m12 * m12;
    if (!(det > 1e-12 * std::max(1e-12, m11 * m22)))
        return {};
    return {std::clamp((r1 * m22 - m12 * r2) / det, 0.0, 1.0), std::clamp((m11 * r2 - m12 * r1) / det, 0.0, 1.0)};
}

// The time fraction at which `timing` reaches progress p (it rises monotonically).
double timingInverse(const Timing &timing, double p)
{
    double lo = 0, hi = 1;
    for (int i = 0; i < 40; ++i) {
        const double mid = (lo + hi) / 2;
        (timing.at(mid) < p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Where to split a span that no timing fits, as a time fraction; `checks` at its quarter,
// half and three quarters. Where the renderer clamps (lips that touch, an eyeball reaching
// past the lids) its geometry bends: against the progress of the span's timing, the worst
// number's samples lie on two lines. Splitting where they meet leaves two halves that each
// follow the timing exactly. When the samples show the bend in the first or last quarter but
// not where, split at that quarter; when they show no bend, in the middle.
double splitPoint(const Timing &timing, const double *a, const double *b, const Checks &checks, int j, double weight)
{
    const double x[5] = {0, checks.x[0], checks.x[1], checks.x[2], 1};
    double e[5];
    const double v[5] = {a[j] * weight, checks.rows[0][j] * weight, checks.rows[1][j] * weight,
        checks.rows[2][j] * weight, b[j] * weight};
    for (int k = 0; k < 5; ++k)
        e[k] = timing.at(x[k]);
    for (int k = 0; k < 4; ++k) {
        if (!(e[k + 1] > e[k] + 1e-9))
            return 0.5;
    }
    auto line = [&](int p, int q, double at) { return v[p] + (v[q] - v[p]) * (at - e[p]) / (e[q] - e[p]); };
    // Samples are read from the renderer's text, to 0.01 px.
    constexpr double kNoise = 0.04;
    const bool middleOnLeft = std::abs(line(0, 1, e[2]) - v[2]) <= kNoise;
    const bool middleOnRight = std::abs(line(3, 4, e[2]) - v[2]) <= kNoise;
    const double left = (v[1] - v[0]) / (e[1] - e[0]);
    const double right = (v[4] - v[3]) / (e[4] - e[3]);
    if (std::abs(left - right) > 1e-9) {
        const double bend = (v[3] - v[0] - right * e[3] + left * e[0]) / (left - right);
        if (bend > e[1] && bend < e[3] && (bend > e[2] ? middleOnLeft : middleOnRight))
            return timingInverse(timing, bend);
    }
    if (middleOnRight && !middleOnLeft)
        return x[1];
    if (middleOnLeft && !middleOnRight)
        return x[3];
    return 0.5;
}

// One animated channel, ready to write: its key times, values and timings.
struct ChannelKeys
{
    int channel = -1;
    QVector<qint64> times;
    QVector<qint64> values; // quantized, channel size per key
    QVector<std::optional<Timing>> timings; // per interval; nullopt: the value holds
};

// Refines the key times of the channels `which` (moved by the same tracks) until every number
// follows its channel's timing within the tolerance, and returns their keys.
bool buildGroup(const QVector<int> &which, const QVector<Channel> &channels, const Sampler &sampler,
    const TimelineEvaluator &evaluator, const Grid &grid, const AnimationExportOptions &options,
    QVector<ChannelKeys> *result, QString *error)
{
    QVector<double> weights;
    QVector<int> starts; // of each channel's numbers in a row, and the row's end
    for (int c : which) {
        starts.append(int(weights.size()));
        for (int k = 0; k < channels[c].size; ++k)
            weights.append(channels[c].weight);
    }
    starts.append(int(weights.size()));
    const int width = int(weights.size());
    const int channelCount = int(which.size());
    SampleTable table(width);

    const TimelineEvaluator::ExportKeys keys = evaluator.exportKeys(channels[which.first()].tracks);
    QVector<qint64> nodes;
    QVector<double> keyTimes; // the key time each node stands for
    QVector<TimelineEvaluator::Segment> segments;
    for (qsizetype i = 0; i < keys.times.size(); ++i) {
        const qint64 n = grid.snap(keys.times[i]);
        if (!nodes.isEmpty() && n <= nodes.last())
            continue; // closer than the grid to the previous key: one key
        if (!nodes.isEmpty())
            segments.append(i - 1 < keys.segments.size() ? keys.segments[i - 1] : TimelineEvaluator::Segment::Mixed);
        nodes.append(n);
        keyTimes.append(keys.times[i]);
    }
    if (nodes.isEmpty() || nodes.first() != 0) {
        nodes.prepend(0);
        keyTimes.prepend(0);
        segments.prepend(TimelineEvaluator::Segment::Mixed);
    }
    if (nodes.last() != grid.steps) {
        nodes.append(grid.steps);
        keyTimes.append(grid.duration);
        segments.append(TimelineEvaluator::Segment::Mixed);
    }
    const QString structureError = QStringLiteral("the drawing changes its structure with the pose");
    if (!table.add(nodes, sampler, which, grid)) {
        *error = structureError;
        return false;
    }

    // Each channel is refined on its own (all share the samples), so a channel that bends
    // (the teeth as the mouth closes) does not add key times to the others.
    struct Span
    {
        qint64 a, b;
        int channel;
        bool ease; // the pose eases over [u0, u1] of one ease
        double u0, u1;
        int checks = 0; // at its quarters (0), eighths (1) or sixteenths (2)
    };
    QVector<QVector<Piece>> pieces(channelCount);
    QVector<Span> pending;
    for (qsizetype s = 0; s < segments.size(); ++s) {
        const qint64 a = nodes[s], b = nodes[s + 1];
        const bool ease = segments[s] == TimelineEvaluator::Segment::Ease;
        // The span of the ease that the grid times cover (a little more or less than all).
        const double length = keyTimes[s + 1] - keyTimes[s];
        const double u0 = ease ? (grid.time(a) - keyTimes[s]) / length : 0.0;
        const double u1 = ease ? (grid.time(b) - keyTimes[s]) / length : 1.0;
        for (int c = 0; c < channelCount; ++c) {
            if (segments[s] == TimelineEvaluator::Segment::Hold
                && std::equal(table.row(a) + starts[c], table.row(a) + starts[c + 1], table.row(b) + starts[c]))
                pieces[c].append({a, b, {}});
            else
                pending.append({a, b, c, ease, u0, u1, ease ? 0 : 1});
        }
    }

    // Spans shorter than this are not split further (a jump becomes a 1 ms ramp).
    const qint64 minSpan = std::max<qint64>(4, qint64(std::ceil(1e-3 / grid.time(1))));
    while (!pending.isEmpty()) {
        if (cancelled(options)) {
            *error = QStringLiteral("cancelled");
            return false;
        }
        // A span over one ease is checked at its quarters: the geometry being linear in the
        // pose between bends, its ease fits everywhere when it fits there, and a bend anywhere
        // shows at them. Where eases overlap the motion is only smooth: such spans are checked
        // at every eighth, and a timing fitted to them (whose two free parameters could meet
        // the checks while missing a bend between them) at every sixteenth.
        auto sixteenths = [](const Span &s) {
            static constexpr int quarters[] = {4, 8, 12};
            static constexpr int eighths[] = {2, 4, 6, 8, 10, 12, 14};
            static constexpr int all[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
            return s.checks == 0 ? std::span<const int>(quarters)
                : s.checks == 1  ? std::span<const int>(eighths)
                                 : std::span<const int>(all);
        };
        QVector<qint64> needed;
        for (const Span &s : pending) {
            if (s.b - s.a >= 16) {
                for (int k : sixteenths(s))
                    needed.append(s.a + (s.b - s.a) * k / 16);
            }
        }
        if (!table.add(needed, sampler, which, grid)) {
            *error = structureError;
            return false;
        }
        QVector<Span> next;
        QVector<qint64> splits;
        for (const Span &s : pending) {
            Timing base = s.ease ? easeTiming(s.u0, s.u1) : Timing {};
            if (s.b - s.a < 16) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            const double *a = table.row(s.a);
            const double *b = table.row(s.b);
            Checks checks, quarters;
            for (int k : sixteenths(s)) {
                const qint64 n = s.a + (s.b - s.a) * k / 16;
                const double x = double(n - s.a) / double(s.b - s.a);
                checks.rows[checks.count] = table.row(n);
                checks.x[checks.count++] = x;
                if (k % 4 == 0) {
                    quarters.rows[quarters.count] = table.row(n);
                    quarters.x[quarters.count++] = x;
                }
            }
            // The pose's own ease (or a linear timing where eases overlap) when it fits.
            const Slice slice {starts[s.channel], starts[s.channel + 1], weights};
            double baseError = timingError(base, a, b, checks, slice);
            // The grid trims or stretches an ease by a fraction of a step; the whole ease's
            // spline (written shorter) is taken when it fits as well.
            if (s.ease && (s.u0 != 0.0 || s.u1 != 1.0)) {
                const Timing whole = easeTiming(0.0, 1.0);
                const double wholeError = timingError(whole, a, b, checks, slice);
                if (wholeError <= std::max(baseError, 0.5 * options.tolerance)) {
                    base = whole;
                    baseError = wholeError;
                }
            }
            if (baseError <= options.tolerance) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            // Where eases overlap, a fitted timing (checked at every sixteenth first).
            if (!s.ease) {
                const Timing fitted = fittedTiming(a, b, checks, slice);
                if (timingError(fitted, a, b, checks, slice) <= options.tolerance) {
                    if (s.checks == 2) {
                        pieces[s.channel].append({s.a, s.b, fitted});
                    } else {
                        Span closer = s;
                        closer.checks = 2;
                        next.append(closer);
                    }
                    continue;
                }
            }
            if (s.b - s.a <= minSpan) {
                pieces[s.channel].append({s.a, s.b, base});
                continue;
            }
            // Split, where the number that strays most from the span's own timing bends.
            int worst = slice.from;
            double most = -1;
            for (int j = slice.from; j < slice.to; ++j) {
                for (int k = 0; k < quarters.count; ++k) {
                    const double d
                        = weights[j] * std::abs(a[j] + (b[j] - a[j]) * base.at(quarters.x[k]) - quarters.rows[k][j]);
                    if (d > most) {
                        most = d;
                        worst = j;
                    }
                }
            }
            const double x = splitPoint(base, a, b, quarters, worst, weights[worst]);
            const qint64 m = std::clamp(s.a + qint64(std::llround(x * double(s.b - s.a))), s.a + 1, s.b - 1);
            const double um = s.u0 + (s.u1 - s.u0) * double(m - s.a) / double(s.b - s.a);
            next.append({s.a, m, s.channel, s.ease, s.u0, um, s.ease ? 0 : 1});
            next.append({m, s.b, s.channel, s.ease, um, s.u1, s.ease ? 0 : 1});
            splits.append(m);
        }
        if (!table.add(splits, sampler, which, grid)) {
            *error = structureError;
            return false;
        }
        pending = std::move(next);
    }

    // Per channel: quantized values at the piece ends; consecutive pieces on which a channel
    // holds its value merge into one.
    for (int c = 0; c < channelCount; ++c) {
        std::sort(pieces[c].begin(), pieces[c].end(), [](const Piece &p, const Piece &q) { return p.a < q.a; });
        const Channel &channel = channels[which[c]];
        ChannelKeys k;
        k.channel = which[c];
        auto quantized = [&](qint64 n, QVector<qint64> *out) {
            const double *row = table.row(n) + starts[c];
            for (int j = 0; j < channel.size; ++j)
                out->append(quantize(row[j] - (channel.base.isEmpty() ? 0.0 : channel.base[j]), channel.decimals));
        };
        QVector<qint64> end;
        k.times.append(0);
        quantized(0, &k.values);
        bool lastHolds = false;
        for (const Piece &p : pieces[c]) {
            end.clear();
            quantized(p.b, &end);
            const bool holds = std::equal(end.cbegin(), end.cend(), k.values.cend() - channel.size);
            if (holds && lastHolds) {
                k.times.last() = p.b;
                continue;
            }
            k.times.append(p.b);
            k.values.append(end);
            k.timings.append(holds ? std::nullopt : std::optional<Timing>(p.timing));
            lastHolds = holds;
        }
        result->append(std::move(k));
    }
    return true;
}

// ---- writing values ----

void appendValue(QByteArray &out, const Channel &c, const qint64 *v)
{
    switch (c.kind) {
    case ChannelKind::Path: appendAbsolutePath(out, c.commands, v, c.decimals); break;
    case ChannelKind::Points:
    case ChannelKind::Translate:
        for (int j = 0; j < c.size; ++j) {
            if (j)
                out += j % 2 ? ',' : ' ';
            appendFixed(out, v[j], c.decimals);
        }
        break;
    default: appendFixed(out, v[0], c.decimals); break;
    }
}

void appendTiming(QByteArray &out, const std::optional<Timing> &timing)
{
    if (!timing) {
        out += "0 0 1 1";
        return;
    }
    const qint64 y1 = quantize(timing->y1, 3);
    const qint64 y2 = quantize(timing->y2, 3);
    if (y1 == 333 && y2 == 667) {
        out += "0 0 1 1";
        return;
    }
    out += ".333 ";
    appendFixed(out, y1, 3);
    out += " .667 ";
    appendFixed(out, y2, 3);
}

// The animation element of one channel's keys, or an empty array when it never moves.
QByteArray animationElement(const Channel &c, const ChannelKeys &k, const Grid &grid, const QByteArray &dur)
{
    QByteArray out;
    const bool moves = k.times.size() > 2 || (k.timings.size() == 1 && k.timings.first());
    const bool head = c.part < 0;
    if (!moves && !head)
        return out;
    if (head) {
        out += "<animateTransform attributeName=\"transform\" type=\"";
        out += c.kind == ChannelKind::Translate ? "translate\" additive=\"replace\""
            : c.kind == ChannelKind::Rotate     ? "rotate\" additive=\"sum\""
                                                : "scale\" additive=\"sum\"";
    } else {
        out += "<animate attributeName=\"" + c.attribute.toLatin1() + "\" additive=\"sum\"";
    }
    out += " dur=\"" + dur + "\" fill=\"freeze\"";
    if (!moves) {
        out += " values=\"";
        appendValue(out, c, k.values.constData());
        out += "\"/>";
        return out;
    }
    out += " calcMode=\"spline\" keyTimes=\"";
    for (qsizetype i = 0; i < k.times.size(); ++i) {
        if (i)
            out += ';';
        appendFixed(out, k.times[i], grid.digits);
    }
    out += "\" keySplines=\"";
    for (qsizetype i = 0; i < k.timings.size(); ++i) {
        if (i)
            out += ';';
        appendTiming(out, k.timings[i]);
    }
    out += "\" values=\"";
    for (qsizetype i = 0; i < k.times.size(); ++i) {
        if (i)
            out += ';';
        appendValue(out, c, k.values.constData() + i * c.size);
    }
    out += "\"/>";
    return out;
}

// ---- the document ----

// A parsed XML element (or text, when name is empty).
struct XmlNode
{
    QByteArray name;
    std::vector<std::pair<QByteArray, QByteArray>> attributes; // qualified names; namespace declarations included
    std::vector<XmlNode> children;
    QByteArray text;

    QByteArray attribute(const char *key) const
    {
        for (const auto &[k, v] : attributes) {
            if (k == key)
                return v;
        }
        return {};
    }
};

bool parseXml(const QByteArray &data, XmlNode *root, QString *error)
{
    QXmlStreamReader reader(data);
    std::vector<XmlNode *> stack;
    while (!reader.atEnd()) {
        const auto token = reader.readNext();
        if (token == QXmlStreamReader::StartElement) {
            XmlNode n;
            n.name = reader.qualifiedName().toUtf8();
            for (const auto &ns : reader.namespaceDeclarations()) {
                n.attributes.emplace_back(ns.prefix().isEmpty() ? QByteArray("xmlns") : "xmlns:" + ns.prefix().toUtf8(),
                    ns.namespaceUri().toUtf8());
            }
            for (const auto &a : reader.attributes())
                n.attributes.emplace_back(a.qualifiedName().toUtf8(), a.value().toUtf8());
            if (stack.empty()) {
                *root = std::move(n);
                stack.push_back(root);
            } else {
                stack.back()->children.push_back(std::move(n));
                stack.push_back(&stack.back()->children.back());
            }
        } else if (token == QXmlStreamReader::EndElement) {
            stack.pop_back();
        } else if (token == QXmlStreamReader::Characters && !stack.empty()) {
            XmlNode t;
            t.text = reader.text().toUtf8();
            stack.back()->children.push_back(std::move(t));
        }
    }
    if (reader.hasError()) {
        *error = QStringLiteral("the drawing is not valid XML: %1").arg(reader.errorString());
        return false;
    }
    return true;
}

void appendEscaped(QByteArray &out, const QByteArray &s, bool attribute)
{
    for (const char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += attribute ? "&quot;" : "\""; break;
        default: out += c;
        }
    }
}

void appendStartTag(QByteArray &out, const XmlNode &n, bool close)
{
    out += '<';
    out += n.name;
    for (const auto &[k, v] : n.attributes) {
        out += ' ';
        out += k;
        out += "=\"";
        appendEscaped(out, v, true);
        out += '"';
    }
    out += close ? "/>" : ">";
}

// Writes `n`; `inject` may add content at the start and at the end of any element.
using XmlInjector = std::function<void(const XmlNode &, QByteArray *first, QByteArray *last)>;

void writeXml(QByteArray &out, const XmlNode &n, const XmlInjector &inject)
{
    if (n.name.isEmpty()) {
        appendEscaped(out, n.text, false);
        return;
    }
    QByteArray first, last;
    if (inject)
        inject(n, &first, &last);
    if (n.children.empty() && first.isEmpty() && last.isEmpty()) {
        appendStartTag(out, n, true);
        return;
    }
    appendStartTag(out, n, false);
    out += first;
    for (const XmlNode &child : n.children)
        writeXml(out, child, inject);
    out += last;
    out += "</" + n.name + '>';
}

const XmlNode *findById(const XmlNode &n, const QByteArray &id)
{
    if (!n.name.isEmpty() && n.attribute("id") == id)
        return &n;
    for (const XmlNode &c : n.children) {
        if (const XmlNode *found = findById(c, id))
            return found;
    }
    return nullptr;
}

QRectF viewBoxOf(const XmlNode &root)
{
    QVector<double> v;
    parseNumbers(root.attribute("viewBox"), &v);
    return v.size() == 4 ? QRectF(v[0], v[1], v[2], v[3]) : QRectF(0, 0, 512, 512);
}

// ---- sound ----

struct AudioSource
{
    QByteArray uri; // empty: no sound
    double offset = 0;
    double duration = 0;
};

QByteArray audioMimeType(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    static const QHash<QString, const char *> known = {{QStringLiteral("wav"), "audio/wav"},
        {QStringLiteral("mp3"), "audio/mpeg"}, {QStringLiteral("ogg"), "audio/ogg"},
        {QStringLiteral("oga"), "audio/ogg"}, {QStringLiteral("opus"), "audio/ogg"},
        {QStringLiteral("m4a"), "audio/mp4"}, {QStringLiteral("aac"), "audio/aac"},
        {QStringLiteral("flac"), "audio/flac"}, {QStringLiteral("webm"), "audio/webm"}};
    if (const auto it = known.constFind(suffix); it != known.constEnd())
        return *it;
    return QMimeDatabase().mimeTypeForFile(path).name().toLatin1();
}

// The sound of `path` as AAC in MP4 when it is stored uncompressed or losslessly; false (and
// the file is embedded as it is) for compressed sound or a file FFmpeg cannot read (the
// browser may still play it).
bool compressedAudio(const QString &path, QByteArray *bytes)
{
    QString why;
    const std::optional<MediaInfo> info = probeMedia(path, &why);
    if (!info || !info->hasAudio)
        return false;
    static const QStringList lossless = {QStringLiteral("flac"), QStringLiteral("alac"), QStringLiteral("wavpack"),
        QStringLiteral("ape"), QStringLiteral("tta")};
    if (!info->audioCodec.startsWith(QLatin1StringView("pcm_")) && !lossless.contains(info->audioCodec))
        return false;
    // Speech keeps its sound below 16 kHz: 32 kHz sampling is enough, lower rates stay as they are.
    const int rate = std::min(info->audioSampleRate > 0 ? info->audioSampleRate : 32000, 32000);
    const std::optional<QVector<float>> samples = readAudio(path, rate, &why);
    QTemporaryDir dir;
    if (!samples || !dir.isValid())
        return false;
    const QString m4a = dir.filePath(QStringLiteral("sound.m4a"));
    QFile file(m4a);
    if (!writeAudio(m4a, Audio {*samples, rate}, &why) || !file.open(QIODevice::ReadOnly))
        return false;
    *bytes = file.readAll();
    return !bytes->isEmpty();
}

bool resolveAudio(
    const Timeline &timeline, double duration, const AnimationExportOptions &options, AudioSource *out, QString *error)
{
    if (options.audio == ExportAudio::None)
        return true;
    QString path = options.audioPath;
    out->duration = duration;
    if (timeline.audio()) {
        if (path.isEmpty())
            path = timeline.audio()->path;
        out->offset = timeline.audio()->offset;
        out->duration = timeline.audio()->duration > 0 ? timeline.audio()->duration : duration;
    }
    if (path.isEmpty())
        return true;
    const QFileInfo info(path);
    if (options.audio == ExportAudio::Embed) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("cannot read the audio file %1: %2").arg(path, file.errorString());
            return false;
        }
        QByteArray aac;
        if (options.compressAudio && compressedAudio(path, &aac))
            out->uri = "data:audio/mp4;base64," + aac.toBase64();
        else
            out->uri = "data:" + audioMimeType(path) + ";base64," + file.readAll().toBase64();
        return true;
    }
    if (!info.isFile()) {
        *error = QStringLiteral("the audio file %1 does not exist").arg(path);
        return false;
    }
    const QDir base(options.outputDir.isEmpty() ? QDir::currentPath() : options.outputDir);
    out->uri = QUrl::toPercentEncoding(base.relativeFilePath(info.absoluteFilePath()), "/");
    return true;
}

QByteArray metadata(const AudioSource &audio, double duration, double fps)
{
    QByteArray m = "\n<metadata><tf:animation xmlns:tf=\"" + QByteArray(kNamespace) + "\" duration=\"";
    appendFixed(m, quantize(duration, 6), 6);
    m += "\" fps=\"";
    appendFixed(m, quantize(fps, 6), 6);
    m += "\"/>";
    if (!audio.uri.isEmpty()) {
        m += "<tf:audio xmlns:tf=\"" + QByteArray(kNamespace) + "\" href=\"";
        appendEscaped(m, audio.uri, true);
        m += "\" offset=\"";
        appendFixed(m, quantize(audio.offset, 6), 6);
        m += "\" duration=\"";
        appendFixed(m, quantize(audio.duration, 6), 6);
        m += "\"/>";
    }
    m += "</metadata>\n";
    return m;
}

// The standalone document's player: a play button over the drawing and the script that
// starts the sound with the animation and keeps the animation on the audio clock.
QByteArray playerScript(QRectF canvas)
{
    const double r = 0.08 * std::min(canvas.width(), canvas.height());
    const double cx = canvas.center().x(), cy = canvas.center().y();
    auto n = [](double v) {
        QByteArray s;
        appendFixed(s, quantize(v, 1), 1);
        return s;
    };
    QByteArray out = "<g id=\"tf-play\" visibility=\"hidden\" cursor=\"pointer\"><circle cx=\"" + n(cx) + "\" cy=\""
        + n(cy) + "\" r=\"" + n(r) + "\" fill=\"#000\" fill-opacity=\".55\"/><path d=\"M" + n(cx - 0.35 * r) + ','
        + n(cy - 0.5 * r) + 'L' + n(cx + 0.55 * r) + ',' + n(cy) + 'L' + n(cx - 0.35 * r) + ',' + n(cy + 0.5 * r)
        + "Z\" fill=\"#fff\"/></g>\n";
    out += R"(<script type="text/ecmascript"><![CDATA[
(function () {
  var svg = document.documentElement;
  var ns = 'urn:toonface:animation:1';
  var meta = document.getElementsByTagNameNS(ns, 'audio')[0];
  var info = document.getElementsByTagNameNS(ns, 'animation')[0];
  var button = document.getElementById('tf-play');
  if (!meta || !info || !svg.pauseAnimations) return;
  var audio = new Audio(meta.getAttribute('href'));
  var offset = parseFloat(meta.getAttribute('offset')) || 0;
  var clip = parseFloat(meta.getAttribute('duration')) || 0;
  var length = parseFloat(info.getAttribute('duration')) || 0;
  var playing = false;
  function show(visible) { button.setAttribute('visibility', visible ? 'visible' : 'hidden'); }
  function audible(t) { return t - offset >= 0 && t - offset < Math.min(clip, audio.duration || clip); }
  function startAudio(t) {
    audio.currentTime = Math.max(0, t - offset);
    var p = audio.play();
    return p && p.then ? p : { then: function (ok) { ok(); } };
  }
  function tick() {
    if (!playing) return;
    var t = svg.getCurrentTime();
    if (t >= length) { stop(); return; }
    if (audible(t)) {
      if (audio.paused) startAudio(t);
      // Put the animation back on the audio clock when it drifts more than a frame.
      else if (Math.abs(audio.currentTime + offset - t) > 0.04) svg.setCurrentTime(audio.currentTime + offset);
    }
    requestAnimationFrame(tick);
  }
  function play() {
    if (svg.getCurrentTime() >= length) svg.setCurrentTime(0);
    var t = svg.getCurrentTime();
    var started = audible(t) ? startAudio(t) : { then: function (ok) { ok(); } };
    started.then(function () {
      playing = true; show(false); svg.unpauseAnimations(); requestAnimationFrame(tick);
    }, function () { show(true); });
  }
  function stop() { playing = false; audio.pause(); svg.pauseAnimations(); show(true); }
  svg.pauseAnimations();
  svg.setCurrentTime(0);
  svg.addEventListener('click', function () { if (playing) stop(); else play(); });
  play();
})();
]]></script>
)";
    return out;
}

// ---- putting it together ----

struct Drawing
{
    SvgFace svg;
    XmlNode document; // SvgFace::svg() at time 0
    QVector<FacePart> parts; // at time 0
    QVector<Channel> channels;
};

bool prepareDrawing(const Timeline &timeline, const MouthShapeSet &shapes, const TimelineEvaluator &evaluator,
    const AnimationExportOptions &options, Drawing *d, QString *error)
{
    for (const QString &file : options.layerFiles) {
        if (!d->svg.addLayerFile(file, error))
            return false;
    }
    const Pose start = evaluator.evaluate(0);
    if (!parseXml(d->svg.svg(start), &d->document, error))
        return false;
    d->parts = d->svg.parts(start);
    QVector<double> neutralHead;
    if (!headNumbers(d->svg, HeadPose {}, &neutralHead)) {
        *error = QStringLiteral("unexpected head transform '%1'").arg(d->svg.headTransform(HeadPose {}));
        return false;
    }
    d->channels = makeChannels(d->parts, neutralHead, viewBoxOf(d->document));
    findTracks(d->channels, d->svg, timeline, shapes);
    if (timeline.headKeys().isEmpty()) {
        for (Channel &c : d->channels) {
            if (c.part < 0)
                c.tracks = {};
        }
    }
    return true;
}

// The Smil-mode document. `standalone`: with XML declaration, metadata and player script.
bool smilDocument(const Drawing &d, const TimelineEvaluator &evaluator, const Timeline &timeline,
    const AudioSource &audio, bool standalone, const AnimationExportOptions &options, QByteArray *out, QString *error)
{
    const double duration = evaluator.duration();
    const Grid grid(duration);
    const QByteArray dur = seconds(duration);
    const Sampler sampler(d.svg, evaluator, d.channels, d.parts.size());

    // Channels moved by the same tracks start from the same key times and share their samples.
    QVector<Tracks> groups;
    for (const Channel &c : d.channels) {
        if (c.tracks && !groups.contains(c.tracks))
            groups.append(c.tracks);
    }
    QVector<ChannelKeys> keys;
    if (duration > 0) {
        for (qsizetype g = 0; g < groups.size(); ++g) {
            QVector<int> which;
            for (qsizetype c = 0; c < d.channels.size(); ++c) {
                if (d.channels[c].tracks == groups[g])
                    which.append(int(c));
            }
            if (!buildGroup(which, d.channels, sampler, evaluator, grid, options, &keys, error))
                return false;
            report(options, 0.9 * double(g + 1) / double(groups.size()));
        }
    }

    QHash<QByteArray, QByteArray> animations; // element id -> its animation elements
    QByteArray head;
    bool headMoves = false;
    for (const ChannelKeys &k : keys) {
        const Channel &c = d.channels[k.channel];
        const QByteArray element = animationElement(c, k, grid, dur);
        if (c.part < 0) {
            head += element;
            headMoves = headMoves || k.times.size() > 2 || (k.timings.size() == 1 && k.timings.first());
        } else if (!element.isEmpty()) {
            animations[d.parts[c.part].id.toLatin1()] += element;
        }
    }
    if (headMoves) {
        QVector<double> neutral;
        headNumbers(d.svg, HeadPose {}, &neutral);
        head += "<animateTransform attributeName=\"transform\" type=\"translate\" additive=\"sum\" dur=\"" + dur
            + "\" fill=\"freeze\" values=\"";
        appendFixed(head, quantize(neutral[4], 2), 2);
        head += ',';
        appendFixed(head, quantize(neutral[5], 2), 2);
        head += "\"/>";
    } else {
        head.clear();
    }

    const QRectF canvas = viewBoxOf(d.document);
    const bool withPlayer = standalone && !audio.uri.isEmpty() && duration > 0;
    if (standalone)
        *out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    const XmlNode *root = &d.document;
    writeXml(*out, *root, [&](const XmlNode &n, QByteArray *first, QByteArray *last) {
        if (&n == root) {
            if (standalone)
                *first += metadata(audio, duration, timeline.frameRate());
            if (withPlayer)
                *last += playerScript(canvas);
            return;
        }
        const QByteArray id = n.attribute("id");
        if (id.isEmpty())
            return;
        if (id == "head") {
            *first += head;
            return;
        }
        if (const auto it = animations.constFind(id); it != animations.constEnd())
            *first += *it;
    });
    *out += '\n';
    return true;
}

// The Frames-mode document.
bool framesDocument(const Drawing &d, const TimelineEvaluator &evaluator, const Timeline &timeline,
    const AudioSource &audio, const AnimationExportOptions &options, QByteArray *out, QString *error)
{
    const double fps = timeline.frameRate();
    const int frames = std::max(1, timeline.frameCount());
    const XmlNode *head = findById(d.document, "head");
    if (!head) {
        *error = QStringLiteral("the drawing has no head group");
        return false;
    }
    QHash<QByteArray, int> partOf;
    for (qsizetype i = 0; i < d.parts.size(); ++i)
        partOf.insert(d.parts[i].id.toLatin1(), int(i));
    QVector<bool> moving(d.parts.size(), false);
    bool headMoves = false;
    for (const Channel &c : d.channels) {
        if (c.tracks && c.part >= 0)
            moving[c.part] = true;
        headMoves = headMoves || (c.part < 0 && c.tracks);
    }
    auto isMoving = [&](const QByteArray &id) {
        const auto it = partOf.constFind(id);
        return it != partOf.constEnd() && moving[*it];
    };

    // Clip paths of moving parts are repeated in each frame (their ids suffixed); the others
    // stay in <defs>.
    QMap<QByteArray, QByteArray> clipTarget; // clip id -> the moving element it uses
    QByteArray defs;
    if (const XmlNode *original = [&]() -> const XmlNode * {
            for (const XmlNode &c : d.document.children) {
                if (c.name == "defs")
                    return &c;
            }
            return nullptr;
        }()) {
        for (const XmlNode &clip : original->children) {
            QByteArray target;
            for (const XmlNode &use : clip.children) {
                if (use.name == "use")
                    target = use.attribute("xlink:href").mid(1);
            }
            if (clip.name == "clipPath" && isMoving(target))
                clipTarget.insert(clip.attribute("id"), target);
            else
                writeXml(defs, clip, {});
        }
    }

    // The elements of the head group in drawing order; runs of parts that never move are
    // drawn once in <defs> and used by every frame.
    struct Item
    {
        const XmlNode *node; // a moving part, or null for a shared run
        int run = -1;
    };
    QVector<Item> items;
    int runs = 0;
    bool inRun = false;
    std::function<void(const XmlNode &)> collect = [&](const XmlNode &n) {
        for (const XmlNode &c : n.children) {
            if (c.name.isEmpty())
                continue;
            if (c.name == "g" && !partOf.contains(c.attribute("id"))) {
                collect(c);
                continue;
            }
            if (isMoving(c.attribute("id"))) {
                items.append({&c});
                inRun = false;
                continue;
            }
            if (!inRun) {
                defs += "<g id=\"tf-shared-" + QByteArray::number(runs) + "\">";
                items.append({nullptr, runs++});
                inRun = true;
            } else {
                defs.chop(4); // reopen the run's group
            }
            writeXml(defs, c, {});
            defs += "</g>";
        }
    };
    collect(*head);

    *out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    appendStartTag(*out, d.document, false);
    *out += metadata(audio, evaluator.duration(), fps);
    *out += "<defs>" + defs + "</defs>\n";
    XmlNode outer = *head;
    outer.children.clear();
    std::erase_if(
        outer.attributes, [&](const auto &a) { return a.first == "id" || (headMoves && a.first == "transform"); });
    appendStartTag(*out, outer, false);
    *out += '\n';

    const QByteArray frameDur = seconds(1.0 / fps);
    auto frameText = [&](int i) {
        const Pose pose = evaluator.evaluate(i / fps);
        const QVector<FacePart> parts = d.svg.parts(pose);
        const QByteArray suffix = "-f" + QByteArray::number(i);
        QByteArray f = "<g visibility=\"hidden\"><set attributeName=\"visibility\" to=\"visible\" begin=\"";
        f += seconds(i / fps) + "\" dur=\"" + frameDur + '"';
        if (i + 1 == frames)
            f += " fill=\"freeze\"";
        f += "/>";
        if (headMoves)
            f += "<g transform=\"" + d.svg.headTransform(pose.head).toLatin1() + "\">";
        for (auto it = clipTarget.cbegin(); it != clipTarget.cend(); ++it)
            f += "<clipPath id=\"" + it.key() + suffix + "\"><use xlink:href=\"#" + it.value() + suffix
                + "\"/></clipPath>";
        for (const Item &item : items) {
            if (!item.node) {
                f += "<use xlink:href=\"#tf-shared-" + QByteArray::number(item.run) + "\"/>";
                continue;
            }
            const int p = partOf.value(item.node->attribute("id"));
            XmlNode e = *item.node;
            for (auto &[k, v] : e.attributes) {
                if (k == "id") {
                    v += suffix;
                } else if (k == "clip-path") {
                    const QByteArray clip = v.mid(5, v.size() - 6); // url(#...)
                    if (clipTarget.contains(clip))
                        v = "url(#" + clip + suffix + ')';
                } else if (p < parts.size() && parts[p].geometry.contains(QString::fromLatin1(k))) {
                    const QByteArray text = parts[p].geometry.value(QString::fromLatin1(k)).toLatin1();
                    QVector<double> numbers;
                    QByteArray commands;
                    QVector<qint64> q;
                    if (k == "d" && parsePath(text, &numbers, &commands)) {
                        for (double x : numbers)
                            q.append(quantize(x, 1));
                        v.clear();
                        if (relativeWritable(commands))
                            appendRelativePath(v, commands, q.constData(), 1);
                        else
                            appendAbsolutePath(v, commands, q.constData(), 1);
                    } else if (k != "d") {
                        QByteArray letters;
                        parseNumbers(text, &numbers, &letters);
                        if (!letters.isEmpty() || numbers.isEmpty()) {
                            v = text;
                            continue;
                        }
                        Channel c;
                        c.kind = numbers.size() == 1 ? ChannelKind::Number : ChannelKind::Points;
                        c.size = int(numbers.size());
                        for (double x : numbers)
                            q.append(quantize(x, 1));
                        v.clear();
                        appendValue(v, c, q.constData());
                    } else {
                        v = text;
                    }
                }
            }
            writeXml(f, e, {});
        }
        if (headMoves)
            f += "</g>";
        f += "</g>\n";
        return f;
    };

    constexpr int kChunk = 256;
    for (int first = 0; first < frames; first += kChunk) {
        if (cancelled(options)) {
            *error = QStringLiteral("cancelled");
            return false;
        }
        const int count = std::min(kChunk, frames - first);
        QVector<QByteArray> texts(count);
        forEachParallel(count, [&](qsizetype i) { texts[i] = frameText(first + int(i)); });
        for (const QByteArray &t : texts)
            *out += t;
        report(options, double(first + count) / frames);
    }
    *out += "</g>\n";
    // The user's layers, and anything else after the head group, as they were.
    bool afterHead = false;
    for (const XmlNode &c : d.document.children) {
        if (&c == head) {
            afterHead = true;
            continue;
        }
        if (afterHead)
            writeXml(*out, c, {});
    }
    if (!audio.uri.isEmpty())
        *out += playerScript(viewBoxOf(d.document));
    *out += "</svg>\n";
    return true;
}

struct Prepared
{
    TimelineEvaluator evaluator;
    Drawing drawing;
    AudioSource audio;
};

std::optional<Prepared> prepare(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    Prepared p {TimelineEvaluator(timeline, face, shapes), {SvgFace(face, style), {}, {}, {}}, {}};
    // Browsers clip the eyeballs by the eye outline: the skin covers for renderers that cannot
    // (SvgFace) would only add two animated paths. The frame mode is for old players: it keeps them.
    p.drawing.svg.setEyeCovers(options.mode == AnimationExportOptions::Mode::Frames);
    p.drawing.svg.setFrame(options.frame);
    if (!prepareDrawing(timeline, shapes, p.evaluator, options, &p.drawing, error)
        || !resolveAudio(timeline, p.evaluator.duration(), options, &p.audio, error))
        return std::nullopt;
    report(options, 0.0);
    return p;
}

} // namespace

QByteArray exportSmilSvg(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    QString why;
    QByteArray out;
    const std::optional<Prepared> p = prepare(face, style, timeline, shapes, options, &why);
    const bool ok = p
        && (options.mode == AnimationExportOptions::Mode::Frames
                ? framesDocument(p->drawing, p->evaluator, timeline, p->audio, options, &out, &why)
                : smilDocument(p->drawing, p->evaluator, timeline, p->audio, true, options, &out, &why));
    if (!ok) {
        if (error)
            *error = why;
        return {};
    }
    report(options, 1.0);
    return out;
}

std::optional<SmilElement> exportSmilElement(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    QString why;
    SmilElement e;
    const std::optional<Prepared> p = prepare(face, style, timeline, shapes, options, &why);
    if (!p || !smilDocument(p->drawing, p->evaluator, timeline, p->audio, false, options, &e.svg, &why)) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    e.audioUri = p->audio.uri;
    e.audioOffset = p->audio.offset;
    e.audioDuration = p->audio.duration;
    e.duration = p->evaluator.duration();
    report(options, 1.0);
    return e;
}

} // namespace toonface
