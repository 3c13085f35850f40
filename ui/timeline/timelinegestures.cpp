// TimelineView's mouse gestures (declared in timelineview.h): what a press takes hold of
// (scrubbing, a rubber band, an item's body, edge or handle), the drag that follows as one
// undo step, and double-clicks.
#include "timeline/timelineview.h"

#include "playback/playhead.h"
#include "timeline/timelinegeometry.h"

#include <QLineEdit>
#include <QMouseEvent>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

constexpr int kDragThreshold = 3;

int nextMergeId()
{
    static int id = 0x54000000;
    return ++id;
}

} // namespace

void TimelineView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton) {
        QAbstractScrollArea::mousePressEvent(event);
        return;
    }
    if (m_pinyinEditor && m_pinyinEditor->isVisible())
        commitPinyin();
    const QPoint pos = event->position().toPoint();
    const TimelineHit hit = hitAt(pos);
    m_drag = Drag();
    m_drag.pressPos = pos;
    m_drag.start = m_document->animation();
    m_drag.mergeId = nextMergeId();
    if (!hit.row)
        return;
    if (pos.x() < TimelineLayout::kLabelWidth) {
        setFocusRow(hit.row);
        return;
    }
    if (*hit.row == RowKind::Ruler || (*hit.row == RowKind::Waveform && !hit.item)) {
        // A click elsewhere on the time lets go of the selection, so that what acts on a range
        // (Head Nod, Shake, an emotion) acts at the playhead, not over items chosen before.
        if (!(event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier)))
            setSelection({});
        m_drag.mode = DragMode::Scrub;
        m_drag.started = true;
        m_playhead->setScrubbing(true);
        m_playhead->setTime(snapped(hit.time));
        return;
    }
    setFocusRow(hit.row);
    if (!hit.item) {
        if (!(event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier)))
            setSelection({});
        m_drag.mode = DragMode::RubberBand;
        m_drag.baseSelection = m_selection;
        return;
    }
    const ItemRef item = *hit.item;
    m_drag.item = item;
    if (event->modifiers() & Qt::ControlModifier) {
        Selection s = m_selection;
        s.toggle(item);
        setSelection(s);
        m_anchor = item;
        if (!s.contains(item))
            return;
    } else if (event->modifiers() & Qt::ShiftModifier) {
        // Extends from the last item clicked on the same row to this one, as in a list.
        Selection s = m_selection;
        const bool range = m_anchor && m_anchor->kind == item.kind;
        const int from = range ? std::min(m_anchor->index, item.index) : item.index;
        const int count = int(itemSpans(m_document->animation(), item.kind).size());
        const int to = range ? std::min(std::max(m_anchor->index, item.index), count - 1) : item.index;
        for (int i = from; i <= to; ++i)
            s.insert({item.kind, i});
        setSelection(s);
        if (!range)
            m_anchor = item;
    } else if (!m_selection.contains(item) || hit.part != HitPart::Body) {
        setSelection({item});
        m_anchor = item;
    } else {
        m_anchor = item;
    }
    const double pointer = m_layout.timeAt(pos.x());
    switch (hit.part) {
    case HitPart::Body:
        m_drag.mode = DragMode::Move;
        m_drag.grabOffset = itemTime(m_drag.start, item) - pointer;
        break;
    case HitPart::StartEdge:
    case HitPart::EndEdge: {
        m_drag.mode = DragMode::Edge;
        m_drag.edge = hit.part == HitPart::StartEdge ? SpanEdge::Start : SpanEdge::End;
        const Span span = itemSpans(m_drag.start, item.kind)[item.index];
        m_drag.grabOffset = (m_drag.edge == SpanEdge::Start ? span.start : span.end) - pointer;
        break;
    }
    case HitPart::FadeIn: m_drag.mode = DragMode::FadeIn; break;
    case HitPart::FadeOut: m_drag.mode = DragMode::FadeOut; break;
    case HitPart::Intensity: m_drag.mode = DragMode::Intensity; break;
    case HitPart::Weight: m_drag.mode = DragMode::Weight; break;
    case HitPart::None: break;
    }
}

void TimelineView::mouseMoveEvent(QMouseEvent *event)
{
    const QPoint pos = event->position().toPoint();
    if (m_drag.mode == DragMode::None || !(event->buttons() & Qt::LeftButton)) {
        const TimelineHit hit = hitAt(pos);
        Qt::CursorShape cursor = Qt::ArrowCursor;
        if (hit.part == HitPart::StartEdge || hit.part == HitPart::EndEdge || hit.part == HitPart::FadeIn
            || hit.part == HitPart::FadeOut)
            cursor = Qt::SizeHorCursor;
        else if (hit.part == HitPart::Intensity || hit.part == HitPart::Weight)
            cursor = Qt::SizeVerCursor;
        viewport()->setCursor(cursor);
        return;
    }
    if (!m_drag.started && (pos - m_drag.pressPos).manhattanLength() < kDragThreshold)
        return;
    m_drag.started = true;
    dragTo(pos, false);
}

void TimelineView::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_drag.mode == DragMode::None)
        return;
    if (m_drag.started)
        dragTo(event->position().toPoint(), true);
    if (m_drag.mode == DragMode::Scrub)
        m_playhead->setScrubbing(false);
    m_drag = Drag();
    m_rubberBand = QRect();
    m_snapLine.reset();
    viewport()->update();
}

QString TimelineView::dragText() const
{
    switch (m_drag.mode) {
    case DragMode::Move: return tr("Move on Timeline");
    case DragMode::Edge:
        return m_drag.item.kind == ItemKind::Syllable ? tr("Retime Syllable") : tr("Resize on Timeline");
    case DragMode::FadeIn:
    case DragMode::FadeOut: return tr("Change Emotion Fade");
    case DragMode::Intensity: return tr("Change Emotion Intensity");
    case DragMode::Weight: return tr("Change Mouth Weight");
    default: return {};
    }
}

void TimelineView::dragTo(QPoint pos, bool commit)
{
    const double pointer = m_layout.timeAt(pos.x());
    std::optional<Animation> after;
    bool toBoundary = false;
    m_snapLine.reset();
    switch (m_drag.mode) {
    case DragMode::None: return;
    case DragMode::Scrub: m_playhead->setTime(snapped(pointer)); return;
    case DragMode::RubberBand: {
        m_rubberBand = QRect(m_drag.pressPos, pos).normalized();
        Selection s = m_drag.baseSelection;
        const Selection inside = itemsIn(scene(), m_rubberBand);
        for (const ItemRef &r : inside.items())
            s.insert(r);
        setSelection(s);
        viewport()->update();
        return;
    }
    case DragMode::Move: {
        const double from = itemTime(m_drag.start, m_drag.item);
        // Not moved sideways: not moved (snapping alone would shift an item that is off the frames).
        const double to = pos.x() == m_drag.pressPos.x() ? from : snapped(pointer + m_drag.grabOffset, &toBoundary);
        after = moveItems(m_drag.start, m_selection, to - from, minSpan());
        break;
    }
    case DragMode::Edge: {
        if (pos.x() == m_drag.pressPos.x()) {
            after = m_drag.start;
            break;
        }
        const double to = snapped(pointer + m_drag.grabOffset, &toBoundary);
        after = dragItemEdge(m_drag.start, m_drag.item, m_drag.edge, to, minSpan());
        if (toBoundary)
            m_snapLine = to;
        break;
    }
    case DragMode::FadeIn:
    case DragMode::FadeOut: {
        const EmotionClip &c = m_drag.start.timeline.emotionClips()[m_drag.item.index];
        const double t = snapped(pointer);
        after = m_drag.mode == DragMode::FadeIn
            ? setEmotionFades(m_drag.start, m_drag.item.index, t - c.start, c.fadeOut)
            : setEmotionFades(m_drag.start, m_drag.item.index, c.fadeIn, c.end - t);
        break;
    }
    case DragMode::Intensity: {
        const QRectF r = itemRect(m_drag.item);
        const double top = r.top() + 12;
        after = toonface::setEmotionIntensity(
            m_drag.start, m_drag.item.index, (r.bottom() - pos.y()) / std::max(1.0, r.bottom() - top));
        break;
    }
    case DragMode::Weight: {
        const QRectF r = itemRect(m_drag.item);
        const QVector<int> keys = m_selection.indices(ItemKind::Mouth);
        after = toonface::setMouthWeight(m_drag.start, keys, 1.0 - (pos.y() - r.top()) / std::max(1.0, r.height() - 4));
        break;
    }
    }
    if (m_drag.mode == DragMode::Move && toBoundary)
        m_snapLine = snapped(pointer + m_drag.grabOffset);
    // Nothing is pushed until the drag changes something, so a drag that changes nothing leaves
    // no empty step in the history.
    if (after && (m_drag.pushed || !(*after == m_drag.start))) {
        m_drag.pushed = true;
        m_document->changeAnimation(*after, dragText(), m_drag.mergeId, commit);
    }
}

void TimelineView::mouseDoubleClickEvent(QMouseEvent *event)
{
    const TimelineHit hit = hitAt(event->position().toPoint());
    if (hit.item && hit.item->kind == ItemKind::Syllable)
        editSyllable(hit.item->index);
    else if (hit.item && hit.item->kind == ItemKind::Emotion)
        Q_EMIT emotionIntensityRequested(hit.item->index);
}

} // namespace toonface
