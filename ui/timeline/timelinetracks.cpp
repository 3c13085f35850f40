#include "timeline/timelinetracks.h"

#include "anim/keycurve.h"
#include "speech/alignconfidence.h"
#include "speech/pinyin.h"
#include "timeline/mouthicons.h"
#include "timeline/posetrack.h"
#include "timeline/timelinegeometry.h"
#include "views/displaynames.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace toonface::tracks {

using namespace colors;
using namespace geometry;

namespace {

// Items narrower than kDenseWidth pixels (zoomed far out) are not drawn one by one: each
// pixel column takes the colour of the first such item in it, and the columns are drawn as one
// image stretched over the row. A 10-minute track then costs one blit, not thousands of shapes.
constexpr double kDenseWidth = 3.0;

class DenseStrip
{
public:
    explicit DenseStrip(const TimelineScene &s)
        : m_line(std::max(1, s.width), 1, QImage::Format_ARGB32_Premultiplied)
    {
        m_line.fill(Qt::transparent);
    }
    // Whether [x0, x1] is narrow enough for the strip; if so it is taken.
    bool take(double x0, double x1, const QColor &color)
    {
        if (x1 - x0 >= kDenseWidth)
            return false;
        const int from = std::max(0, int(std::floor(x0))), to = std::min(m_line.width() - 1, int(std::ceil(x1)) - 1);
        auto *pixels = reinterpret_cast<QRgb *>(m_line.scanLine(0));
        for (int x = from; x <= std::max(from, to) && x < m_line.width(); ++x)
            if (pixels[x] == 0) {
                pixels[x] = color.rgba();
                m_used = true;
            }
        return true;
    }
    void draw(QPainter &p, const QRectF &band)
    {
        if (m_used)
            p.drawImage(QRectF(0, band.top(), m_line.width(), band.height()), m_line);
    }

private:
    QImage m_line;
    bool m_used = false;
};

void outlineSelected(QPainter &p, const QRectF &r, double radius)
{
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(kSelection, 2));
    p.drawRoundedRect(r.adjusted(1, 1, -1, -1), radius, radius);
}

void drawDiamond(QPainter &p, const QRectF &r, const QColor &fill, bool selected)
{
    QPainterPath d;
    d.moveTo(r.center().x(), r.top());
    d.lineTo(r.right(), r.center().y());
    d.lineTo(r.center().x(), r.bottom());
    d.lineTo(r.left(), r.center().y());
    d.closeSubpath();
    p.setPen(QPen(selected ? kSelection : fill.darker(170), selected ? 2 : 1));
    p.setBrush(selected ? fill.lighter(130) : fill);
    p.drawPath(d);
}

QVector<Span> pointSpans(const QVector<double> &times)
{
    QVector<Span> spans;
    spans.reserve(times.size());
    for (double t : times)
        spans.append({t, t});
    return spans;
}

QVector<double> headTimes(const QVector<HeadKey> &keys)
{
    QVector<double> times;
    times.reserve(keys.size());
    for (const HeadKey &k : keys)
        times.append(k.time);
    return times;
}

// Diamonds at `times` on `row`, one per pixel column at most.
void paintKeys(QPainter &p, const TimelineScene &s, RowKind row, ItemKind kind, const QVector<double> &times,
    const QColor &color, double t0, double t1)
{
    const double pad = kKeySize / s.layout->pixelsPerSecond();
    const auto [first, last] = visibleRange(pointSpans(times), t0 - pad, t1 + pad);
    double lastColumn = -1e9;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = keyRect(s, row, times[i]);
        const bool selected = s.selection->contains({kind, int(i)});
        // Keys closer than a few pixels overlap: the first of each such cluster stands for them.
        if (!selected && r.center().x() - lastColumn < 3)
            continue;
        lastColumn = r.center().x();
        drawDiamond(p, r, color, selected);
    }
}

} // namespace

std::pair<qsizetype, qsizetype> visibleRange(const QVector<Span> &spans, double t0, double t1)
{
    auto first = std::lower_bound(spans.begin(), spans.end(), t0, [](const Span &s, double t) { return s.start < t; });
    while (first != spans.begin() && (first - 1)->end >= t0)
        --first;
    const auto last = std::upper_bound(first, spans.end(), t1, [](double t, const Span &s) { return t < s.start; });
    return {first - spans.begin(), last - spans.begin()};
}

void paintScriptRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<LipsyncSyllable> &syllables = s.animation.syllables;
    QVector<Span> spans;
    spans.reserve(syllables.size());
    for (const LipsyncSyllable &syl : syllables)
        spans.append({syl.start, syl.end});
    const auto [first, last] = visibleRange(spans, t0, t1);
    const QFont base = p.font();
    QFont big = base;
    big.setPointSizeF(base.pointSizeF() * 1.15);
    QFont small = base;
    small.setPointSizeF(base.pointSizeF() * 0.8);
    DenseStrip strip(s);
    for (qsizetype i = first; i < last; ++i) {
        const LipsyncSyllable &syl = syllables[i];
        const QRectF r = spanRect(s, RowKind::Script, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Syllable, int(i)});
        const QColor fill = syl.confidence < kDoubtfulConfidence ? QColor(0x5a, 0x47, 0x3a) : QColor(0x3b, 0x41, 0x4d);
        if (strip.take(r.left(), r.right(), selected ? kSelection : fill.lighter(130)))
            continue;
        p.setPen(QPen(fill.lighter(150), 1));
        p.setBrush(selected ? fill.lighter(140) : fill);
        p.drawRoundedRect(r.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
        if (selected)
            outlineSelected(p, r, 3);
        if (r.width() < 10)
            continue;
        const QRectF inner = r.adjusted(3, 1, -3, -1);
        p.setPen(kText);
        if (syl.pinyin.isEmpty()) {
            p.setFont(base);
            p.drawText(inner, Qt::AlignCenter, syl.text);
            continue;
        }
        p.setFont(big);
        p.drawText(QRectF(inner.left(), inner.top(), inner.width(), inner.height() * 0.58),
            Qt::AlignHCenter | Qt::AlignBottom, syl.text);
        if (r.width() >= 22) {
            p.setFont(small);
            p.setPen(kDimText.lighter(120));
            p.drawText(QRectF(inner.left(), inner.top() + inner.height() * 0.56, inner.width(), inner.height() * 0.44),
                Qt::AlignHCenter | Qt::AlignTop, toneMarkSpelling({syl.pinyin, syl.tone}));
        }
    }
    strip.draw(p, rowBand(s, RowKind::Script));
    p.setFont(base);
}

void paintMouthRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<Span> &spans = *s.mouthSpans;
    const QVector<MouthKey> &keys = s.animation.timeline.mouthKeys();
    const auto [first, last] = visibleRange(spans, t0, t1);
    const QFont base = p.font();
    QFont letter = base;
    letter.setBold(true);
    p.setFont(letter);
    const QFontMetricsF metrics(letter);
    DenseStrip strip(s);
    for (qsizetype i = first; i < last && i < keys.size(); ++i) {
        const MouthKey &k = keys[i];
        const QRectF r = spanRect(s, RowKind::Mouth, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Mouth, int(i)});
        const QColor color = mouthShapeColor(k.shape);
        if (strip.take(r.left(), r.right(), selected ? kSelection : color.darker(125)))
            continue;
        const bool wide = r.width() >= 6;
        p.setPen(wide ? QPen(color.darker(190), 1) : Qt::NoPen);
        p.setBrush(selected ? color.lighter(125) : color.darker(125));
        p.drawRoundedRect(r.adjusted(0.5, 0.5, -0.5, -0.5), wide ? 3 : 0, wide ? 3 : 0);
        if (k.weight < 1.0 && wide) {
            const double y = weightY(r, k.weight);
            p.fillRect(QRectF(r.left() + 1, r.top() + 1, r.width() - 2, y - r.top()), QColor(0, 0, 0, 90));
            p.setPen(QPen(kText, 1, Qt::DotLine));
            p.drawLine(QPointF(r.left() + 2, y), QPointF(r.right() - 2, y));
        }
        if (selected)
            outlineSelected(p, r, 3);
        const QString name = mouthShapeName(k.shape);
        const QImage &icon = s.icons ? s.icons->icon(k.shape) : QImage();
        const QSizeF iconSize = s.icons ? QSizeF(s.icons->size()) : QSizeF();
        if (!icon.isNull() && r.width() >= iconSize.width() + 6) {
            const QRectF iconRect(
                r.left() + (r.width() - iconSize.width()) / 2, r.top() + 4, iconSize.width(), iconSize.height());
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(255, 255, 255, 40));
            p.drawRoundedRect(iconRect.adjusted(-1, -1, 1, 1), 3, 3);
            p.drawImage(iconRect, icon);
            p.setPen(kText);
            p.drawText(
                QRectF(r.left(), iconRect.bottom(), r.width(), r.bottom() - iconRect.bottom()), Qt::AlignCenter, name);
        } else if (r.width() >= metrics.horizontalAdvance(name) + 4) {
            p.setPen(kText);
            p.drawText(r, Qt::AlignCenter, name);
        }
    }
    strip.draw(p, rowBand(s, RowKind::Mouth));
    p.setFont(base);
}

void paintEmotionRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<EmotionClip> &clips = s.animation.timeline.emotionClips();
    QFont small = p.font();
    const QFont base = small;
    small.setPointSizeF(base.pointSizeF() * 0.85);
    p.setFont(small);
    for (qsizetype i = 0; i < clips.size(); ++i) {
        const EmotionClip &c = clips[i];
        if (c.end < t0 || c.start > t1)
            continue;
        const QRectF r = itemSpanRect(s, RowKind::Emotion, int(i), {c.start, c.end});
        const bool selected = s.selection->contains({ItemKind::Emotion, int(i)});
        const QColor color = emotionColor(c.emotion);
        const bool wide = r.width() > kClipHandlesMinWidth;
        if (wide) {
            p.setPen(QPen(color.darker(160), 1));
            p.setBrush(QColor(color.red(), color.green(), color.blue(), 45));
            p.drawRoundedRect(r.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
        } else {
            // Whole pixels: a translucent fill of a fractional rectangle under antialiasing
            // takes Qt's slow path (20 times slower; 60 clips zoomed out cost 4 ms).
            p.fillRect(r.toAlignedRect(), QColor(color.red(), color.green(), color.blue(), 45));
        }
        const ClipHandles h = clipHandles(s, int(i), c);
        const QPointF envelope[] = {r.bottomLeft(), h.fadeIn, h.fadeOut, r.bottomRight()};
        p.setPen(wide ? QPen(color.lighter(120), 1.5) : Qt::NoPen);
        p.setBrush(QColor(color.red(), color.green(), color.blue(), selected ? 170 : 130));
        p.drawPolygon(envelope, 4);
        if (selected)
            outlineSelected(p, r, 3);
        if (r.width() > 40) {
            p.setPen(kText);
            p.drawText(r.adjusted(5, 0, -4, 0), Qt::AlignTop | Qt::AlignLeft,
                QStringLiteral("%1  %2%").arg(emotionTitle(c.emotion)).arg(qRound(c.intensity * 100)));
        }
        if (wide) {
            p.setPen(QPen(color.darker(200), 1));
            p.setBrush(selected ? kSelection : kText);
            p.drawEllipse(h.fadeIn, kHandleRadius, kHandleRadius);
            p.drawEllipse(h.fadeOut, kHandleRadius, kHandleRadius);
        }
    }
    p.setFont(base);
}

void paintBlinkRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<BlinkEvent> &blinks = s.animation.timeline.blinks();
    QVector<Span> spans;
    spans.reserve(blinks.size());
    for (const BlinkEvent &b : blinks)
        spans.append({b.time, b.time + b.duration});
    const auto [first, last] = visibleRange(spans, t0, t1);
    const QColor color(0x7c, 0xb7, 0xe6);
    DenseStrip strip(s);
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = spanRect(s, RowKind::Blink, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Blink, int(i)});
        if (strip.take(r.left() - 1, r.right() + 1, selected ? kSelection : color))
            continue;
        p.setPen(QPen(selected ? kSelection : color.darker(150), selected ? 2 : 1));
        p.setBrush(selected ? color.lighter(120) : color.darker(115));
        p.drawRoundedRect(r, r.height() / 2, r.height() / 2);
        if (r.width() >= 12) {
            // A shut eye: a lid's curve with lashes.
            const QPointF c = r.center();
            const double w = std::min(r.width() - 6, 12.0) / 2;
            QPainterPath lid;
            lid.moveTo(c.x() - w, c.y() - 1);
            lid.quadTo(c.x(), c.y() + 4, c.x() + w, c.y() - 1);
            p.setPen(QPen(kBackground, 1.4));
            p.setBrush(Qt::NoBrush);
            p.drawPath(lid);
        }
    }
    strip.draw(p, rowBand(s, RowKind::Blink).adjusted(0, 3, 0, -3));
}

void paintHeadRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<HeadKey> &keys = s.animation.timeline.headKeys();
    if (keys.isEmpty())
        return;
    const QRectF band = rowBand(s, RowKind::Head);
    const double mid = band.center().y(), half = band.height() / 2;
    // The rotation (side to side) and the vertical motion (nods) as curves over the keys.
    const int x0 = std::max(TimelineLayout::kLabelWidth, int(s.layout->xOf(std::max(t0, keys.first().time))));
    const int x1 = std::min(s.width, int(s.layout->xOf(std::min(t1, keys.last().time))) + 1);
    if (x1 > x0) {
        QPolygonF rotation, nod;
        auto add = [&](double x, const HeadKey &h) {
            rotation.append(QPointF(x, mid - std::clamp(h.rotationDeg / 12.0, -1.0, 1.0) * half));
            nod.append(QPointF(x, mid + std::clamp(h.translationEs0.y() / 0.08, -1.0, 1.0) * half));
        };
        const QVector<double> times = headTimes(keys);
        const auto [first, last] = visibleRange(pointSpans(times), t0, t1);
        if ((last - first) * 2 > x1 - x0) {
            // Keys denser than every other pixel: the line through them is the curve.
            for (qsizetype i = std::max<qsizetype>(0, first - 1); i < std::min(keys.size(), last + 1); ++i)
                add(s.layout->xOf(keys[i].time), keys[i]);
        } else {
            // The head's curve as the evaluator eases it (Timeline::headAt), times gathered once.
            const auto lerp = [](const HeadKey &a, const HeadKey &b, double u) {
                return HeadKey {0, a.rotationDeg + (b.rotationDeg - a.rotationDeg) * u,
                    a.translationEs0 + (b.translationEs0 - a.translationEs0) * u, 1.0};
            };
            for (int x = x0; x <= x1; x += 2)
                add(x, easedAt(times, keys, s.layout->timeAt(x), lerp));
        }
        p.setPen(QPen(QColor(0xf0, 0x9a, 0x5a), 1.3));
        p.drawPolyline(rotation);
        p.setPen(QPen(QColor(0x8f, 0xd0, 0x6a), 1.3));
        p.drawPolyline(nod);
    }
    paintKeys(p, s, RowKind::Head, ItemKind::Head, headTimes(keys), QColor(0xd8, 0xc4, 0x8a), t0, t1);
}

void paintGazeRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const QVector<GazeKey> &keys = s.animation.timeline.gazeKeys();
    QVector<double> times;
    times.reserve(keys.size());
    for (const GazeKey &k : keys)
        times.append(k.time);
    paintKeys(p, s, RowKind::Gaze, ItemKind::Gaze, times, QColor(0x9f, 0xd3, 0xe8), t0, t1);
}

void paintPoseRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    paintKeys(
        p, s, RowKind::Pose, ItemKind::Pose, poseKeyTimes(s.animation.timeline), QColor(0xe8, 0x8f, 0xc8), t0, t1);
}

} // namespace toonface::tracks
