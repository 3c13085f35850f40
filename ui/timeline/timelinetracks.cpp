#include "timeline/timelinetracks.h"

#include "speech/pinyin.h"
#include "timeline/mouthicons.h"
#include "timeline/posetrack.h"
#include "timeline/timelinegeometry.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace toonface::tracks {

using namespace colors;
using namespace geometry;

namespace {

// Skips items that would land on a pixel column already drawn (zoomed far out).
class ColumnFilter
{
public:
    bool skip(double x0, double x1)
    {
        if (x1 - x0 < 1.5 && std::floor(x0) <= m_last)
            return true;
        m_last = std::floor(x1);
        return false;
    }

private:
    double m_last = -1e9;
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

// Diamonds at `times` on `row`, one per pixel column at most.
void paintKeys(QPainter &p, const TimelineScene &s, RowKind row, ItemKind kind, const QVector<double> &times,
    const QColor &color, double t0, double t1)
{
    const double pad = kKeySize / s.layout->pixelsPerSecond();
    const auto [first, last] = visibleRange(pointSpans(times), t0 - pad, t1 + pad);
    ColumnFilter columns;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = keyRect(s, row, times[i]);
        const bool selected = s.selection->contains({kind, int(i)});
        if (!selected && columns.skip(r.center().x(), r.center().x()))
            continue;
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
    ColumnFilter columns;
    for (qsizetype i = first; i < last; ++i) {
        const LipsyncSyllable &syl = syllables[i];
        const QRectF r = spanRect(s, RowKind::Script, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Syllable, int(i)});
        if (!selected && columns.skip(r.left(), r.right()))
            continue;
        const QColor fill = syl.confidence < 0.5 ? QColor(0x5a, 0x47, 0x3a) : QColor(0x3b, 0x41, 0x4d);
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
    ColumnFilter columns;
    for (qsizetype i = first; i < last && i < keys.size(); ++i) {
        const MouthKey &k = keys[i];
        const QRectF r = spanRect(s, RowKind::Mouth, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Mouth, int(i)});
        if (!selected && columns.skip(r.left(), r.right()))
            continue;
        const QColor color = mouthShapeColor(k.shape);
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
        const QRectF r = spanRect(s, RowKind::Emotion, {c.start, c.end});
        const bool selected = s.selection->contains({ItemKind::Emotion, int(i)});
        const QColor color = emotionColor(c.emotion);
        p.setPen(QPen(color.darker(160), 1));
        p.setBrush(QColor(color.red(), color.green(), color.blue(), 45));
        p.drawRoundedRect(r.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
        const ClipHandles h = clipHandles(s, c);
        QPainterPath envelope;
        envelope.moveTo(r.left(), r.bottom());
        envelope.lineTo(h.fadeIn);
        envelope.lineTo(h.fadeOut);
        envelope.lineTo(r.right(), r.bottom());
        envelope.closeSubpath();
        p.setPen(QPen(color.lighter(120), 1.5));
        p.setBrush(QColor(color.red(), color.green(), color.blue(), selected ? 170 : 130));
        p.drawPath(envelope);
        if (selected)
            outlineSelected(p, r, 3);
        if (r.width() > 40) {
            p.setPen(kText);
            p.drawText(r.adjusted(5, 0, -4, 0), Qt::AlignTop | Qt::AlignLeft,
                QStringLiteral("%1  %2%").arg(emotionName(c.emotion)).arg(qRound(c.intensity * 100)));
        }
        if (r.width() > 3 * kHandleRadius) {
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
    ColumnFilter columns;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = spanRect(s, RowKind::Blink, spans[i]);
        const bool selected = s.selection->contains({ItemKind::Blink, int(i)});
        if (!selected && columns.skip(r.left(), r.right()))
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
}

void paintHeadRow(QPainter &p, const TimelineScene &s, double t0, double t1)
{
    const Timeline &tl = s.animation.timeline;
    const QVector<HeadKey> &keys = tl.headKeys();
    if (keys.isEmpty())
        return;
    const QRectF band = rowBand(s, RowKind::Head);
    const double mid = band.center().y(), half = band.height() / 2;
    // The rotation (side to side) and the vertical motion (nods) as curves over the keys.
    const int x0 = std::max(TimelineLayout::kLabelWidth, int(s.layout->xOf(std::max(t0, keys.first().time))));
    const int x1 = std::min(s.width, int(s.layout->xOf(std::min(t1, keys.last().time))) + 1);
    if (x1 > x0) {
        QPolygonF rotation, nod;
        for (int x = x0; x <= x1; x += 2) {
            const HeadKey h = tl.headAt(s.layout->timeAt(x));
            rotation.append(QPointF(x, mid - std::clamp(h.rotationDeg / 12.0, -1.0, 1.0) * half));
            nod.append(QPointF(x, mid + std::clamp(h.translationEs0.y() / 0.08, -1.0, 1.0) * half));
        }
        p.setPen(QPen(QColor(0xf0, 0x9a, 0x5a), 1.3));
        p.drawPolyline(rotation);
        p.setPen(QPen(QColor(0x8f, 0xd0, 0x6a), 1.3));
        p.drawPolyline(nod);
    }
    QVector<double> times;
    times.reserve(keys.size());
    for (const HeadKey &k : keys)
        times.append(k.time);
    paintKeys(p, s, RowKind::Head, ItemKind::Head, times, QColor(0xd8, 0xc4, 0x8a), t0, t1);
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
