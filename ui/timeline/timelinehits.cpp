// Hit testing and rubber-band selection (declared in timelinepainter.h), by the geometry the
// painter draws with.
#include "timeline/posetrack.h"
#include "timeline/timelinegeometry.h"
#include "timeline/timelinetracks.h"

#include <QLineF>

#include <cmath>

namespace toonface {

using namespace geometry;

namespace {

QVector<Span> spansOf(const TimelineScene &s, ItemKind kind)
{
    if (kind == ItemKind::Mouth)
        return *s.mouthSpans;
    return itemSpans(s.animation, kind);
}

// The span item at x on `row`: an edge when within its grip (the nearer edge wins), else the body.
void hitSpans(const TimelineScene &s, RowKind row, ItemKind kind, QPointF pos, TimelineHit *hit)
{
    const QVector<Span> spans = spansOf(s, kind);
    const double pad = kEdgeGrip / s.layout->pixelsPerSecond();
    const auto [first, last] = tracks::visibleRange(spans, hit->time - pad, hit->time + pad);
    double best = kEdgeGrip + 1;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = itemSpanRect(s, row, int(i), spans[i]);
        if (pos.y() < r.top() - kRowInset || pos.y() > r.bottom() + kRowInset)
            continue; // another lane's
        const double grip = edgeGrip(r.width());
        const double toStart = std::abs(pos.x() - r.left()), toEnd = std::abs(pos.x() - r.right());
        if (toStart <= grip && toStart < best) {
            best = toStart;
            hit->item = ItemRef {kind, int(i)};
            hit->part = HitPart::StartEdge;
        }
        if (toEnd <= grip && toEnd < best) {
            best = toEnd;
            hit->item = ItemRef {kind, int(i)};
            hit->part = HitPart::EndEdge;
        }
    }
    if (hit->item)
        return;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = itemSpanRect(s, row, int(i), spans[i]);
        if (pos.x() >= r.left() && pos.x() <= r.right() && pos.y() >= r.top() && pos.y() <= r.bottom()) {
            hit->item = ItemRef {kind, int(i)};
            hit->part = HitPart::Body;
        }
    }
}

void hitMouthWeight(const TimelineScene &s, QPointF pos, TimelineHit *hit)
{
    if (!hit->item || hit->part != HitPart::Body)
        return;
    const QRectF r = spanRect(s, RowKind::Mouth, (*s.mouthSpans)[hit->item->index]);
    const double weight = s.animation.timeline.mouthKeys()[hit->item->index].weight;
    if (r.width() >= 8 && std::abs(pos.y() - weightY(r, weight)) <= 3)
        hit->part = HitPart::Weight;
}

bool hitEmotionHandles(const TimelineScene &s, QPointF pos, TimelineHit *hit)
{
    const QVector<EmotionClip> &clips = s.animation.timeline.emotionClips();
    for (qsizetype i = clips.size() - 1; i >= 0; --i) {
        const QRectF r = itemSpanRect(s, RowKind::Emotion, int(i), {clips[i].start, clips[i].end});
        if (r.width() <= kClipHandlesMinWidth || pos.x() < r.left() - kHandleRadius
            || pos.x() > r.right() + kHandleRadius || pos.y() < r.top() - kRowInset || pos.y() > r.bottom() + kRowInset)
            continue;
        const ClipHandles h = clipHandles(s, int(i), clips[i]);
        const double reach = kHandleRadius + 2;
        const ItemRef ref {ItemKind::Emotion, int(i)};
        if (QLineF(pos, h.fadeIn).length() <= reach) {
            hit->item = ref;
            hit->part = HitPart::FadeIn;
            return true;
        }
        if (QLineF(pos, h.fadeOut).length() <= reach) {
            hit->item = ref;
            hit->part = HitPart::FadeOut;
            return true;
        }
        if (std::abs(pos.y() - h.intensityY) <= 3 && pos.x() > h.fadeIn.x() && pos.x() < h.fadeOut.x()) {
            hit->item = ref;
            hit->part = HitPart::Intensity;
            return true;
        }
    }
    return false;
}

void hitKeys(const TimelineScene &s, RowKind row, ItemKind kind, QPointF pos, TimelineHit *hit)
{
    const QVector<Span> spans = spansOf(s, kind);
    const double pad = kKeySize / s.layout->pixelsPerSecond();
    const auto [first, last] = tracks::visibleRange(spans, hit->time - pad, hit->time + pad);
    double best = kKeySize / 2 + 2;
    for (qsizetype i = first; i < last; ++i) {
        const QRectF r = keyRect(s, row, spans[i].start);
        const double d = std::abs(pos.x() - r.center().x());
        if (d <= best && std::abs(pos.y() - r.center().y()) <= kKeySize) {
            best = d;
            hit->item = ItemRef {kind, int(i)};
            hit->part = HitPart::Body;
        }
    }
}

} // namespace

TimelineHit hitTest(const TimelineScene &s, QPoint point)
{
    TimelineHit hit;
    hit.row = s.layout->rowAt(point.y());
    hit.time = s.layout->timeAt(point.x());
    if (!hit.row || point.x() < TimelineLayout::kLabelWidth)
        return hit;
    const std::optional<ItemKind> kind = itemKindOf(*hit.row);
    if (!kind)
        return hit;
    const QPointF pos(point);
    if (*kind == ItemKind::Emotion && hitEmotionHandles(s, pos, &hit))
        return hit;
    if (hasSpans(*kind))
        hitSpans(s, *hit.row, *kind, pos, &hit);
    else
        hitKeys(s, *hit.row, *kind, pos, &hit);
    if (*kind == ItemKind::Mouth)
        hitMouthWeight(s, pos, &hit);
    // An audio clip moves by its title strip; the waveform below scrubs.
    if (*kind == ItemKind::Audio && hit.part == HitPart::Body
        && pos.y() > itemSpanRect(s, RowKind::Waveform, hit.item->index, {}).top() + kAudioTitle) {
        hit.item.reset();
        hit.part = HitPart::None;
    }
    return hit;
}

Selection itemsIn(const TimelineScene &s, const QRect &rect)
{
    Selection selection;
    const double t0 = s.layout->timeAt(rect.left()), t1 = s.layout->timeAt(rect.right());
    for (const TimelineRow &row : s.layout->rows()) {
        const std::optional<ItemKind> kind = itemKindOf(row.kind);
        if (!kind || !s.layout->rowRect(row.kind, s.width).intersects(rect))
            continue;
        const QVector<Span> spans = spansOf(s, *kind);
        const double pad = hasSpans(*kind) ? 0.0 : kKeySize / 2 / s.layout->pixelsPerSecond();
        const auto [first, last] = tracks::visibleRange(spans, t0 - pad, t1 + pad);
        for (qsizetype i = first; i < last; ++i) {
            const QRectF r
                = hasSpans(*kind) ? itemSpanRect(s, row.kind, int(i), spans[i]) : keyRect(s, row.kind, spans[i].start);
            if (r.intersects(QRectF(rect)))
                selection.insert({*kind, int(i)});
        }
    }
    return selection;
}

} // namespace toonface
