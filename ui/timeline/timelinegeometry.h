#pragma once

#include "timeline/timelinepainter.h"

#include <QPointF>
#include <QRectF>

#include <algorithm>

// Where the painter draws each item and its handles, shared with hit testing so that what is
// grabbed is what is seen. Viewport coordinates.
namespace toonface::geometry {

inline constexpr double kRowInset = 3; // items keep this far from their row's top and bottom
inline constexpr double kEdgeGrip = 5; // pixels either side of an edge that take hold of it
inline constexpr double kKeySize = 11; // a key's diamond
inline constexpr double kHandleRadius = 4.5;
inline constexpr double kClipHandlesMinWidth = 30; // narrower clips show no handles (nor name)
inline constexpr double kAudioTitle = 14; // an audio clip's title strip, which moves it

// A row's band, where its items are drawn (a row with one lane; see laneBand()).
inline QRectF rowBand(const TimelineScene &s, RowKind row)
{
    const QRect r = s.layout->rowRect(row, s.width);
    return QRectF(r).adjusted(0, kRowInset, 0, -kRowInset);
}

// One lane of a row whose overlapping clips stack (audio, emotion).
inline QRectF laneBand(const TimelineScene &s, RowKind row, int lane)
{
    const QRect r = s.layout->laneRect(row, lane, s.width);
    return QRectF(r).adjusted(0, kRowInset, 0, -kRowInset);
}

inline QRectF spanRect(const TimelineScene &s, RowKind row, const Span &span, int lane = 0)
{
    const QRectF band = laneBand(s, row, lane);
    const double x0 = s.layout->xOf(span.start), x1 = s.layout->xOf(span.end);
    return QRectF(x0, band.top(), std::max(1.0, x1 - x0), band.height());
}

// Span item `index` of its row, in its lane.
inline QRectF itemSpanRect(const TimelineScene &s, RowKind row, int index, const Span &span)
{
    return spanRect(s, row, span, s.layout->laneOf(row, index));
}

inline QRectF keyRect(const TimelineScene &s, RowKind row, double t)
{
    const QRectF band = rowBand(s, row);
    return QRectF(s.layout->xOf(t) - kKeySize / 2, band.center().y() - kKeySize / 2, kKeySize, kKeySize);
}

// An emotion clip's envelope: the intensity's height and the fade handles.
struct ClipHandles
{
    double intensityY;
    QPointF fadeIn;
    QPointF fadeOut;
};

// Emotion clip `index` (`c`), in its lane.
inline ClipHandles clipHandles(const TimelineScene &s, int index, const EmotionClip &c)
{
    const QRectF r = itemSpanRect(s, RowKind::Emotion, index, {c.start, c.end});
    const double top = r.top() + 12; // room for the name above full intensity
    const double y = r.bottom() - (r.bottom() - top) * std::clamp(c.intensity, 0.0, 1.0);
    const double length = std::max(1e-9, c.end - c.start);
    const double sum = c.fadeIn + c.fadeOut;
    const double scale = sum > length ? length / sum : 1.0; // fades shrink in proportion
    return {
        y, QPointF(s.layout->xOf(c.start + c.fadeIn * scale), y), QPointF(s.layout->xOf(c.end - c.fadeOut * scale), y)};
}

// The height of a mouth key's weight line (the block's top at weight 1).
inline double weightY(const QRectF &block, double weight)
{
    return block.top() + (1.0 - std::clamp(weight, 0.0, 1.0)) * (block.height() - 4);
}

// How far an edge grip reaches into a block that is `width` wide.
inline double edgeGrip(double width)
{
    return std::min(kEdgeGrip, width / 3);
}

} // namespace toonface::geometry
