#include "timeline/timelinelayout.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace toonface {

std::optional<ItemKind> itemKindOf(RowKind row)
{
    switch (row) {
    case RowKind::Waveform: return ItemKind::Audio;
    case RowKind::Script: return ItemKind::Syllable;
    case RowKind::Mouth: return ItemKind::Mouth;
    case RowKind::Emotion: return ItemKind::Emotion;
    case RowKind::Blink: return ItemKind::Blink;
    case RowKind::Head: return ItemKind::Head;
    case RowKind::Gaze: return ItemKind::Gaze;
    case RowKind::Pose: return ItemKind::Pose;
    default: return std::nullopt;
    }
}

RowKind rowOf(ItemKind kind)
{
    switch (kind) {
    case ItemKind::Syllable: return RowKind::Script;
    case ItemKind::Mouth: return RowKind::Mouth;
    case ItemKind::Emotion: return RowKind::Emotion;
    case ItemKind::Blink: return RowKind::Blink;
    case ItemKind::Head: return RowKind::Head;
    case ItemKind::Gaze: return RowKind::Gaze;
    case ItemKind::Pose: return RowKind::Pose;
    case ItemKind::Audio: return RowKind::Waveform;
    }
    return RowKind::Mouth;
}

QString rowTitle(RowKind row)
{
    switch (row) {
    case RowKind::Ruler: return QCoreApplication::translate("TimelineLayout", "Time");
    case RowKind::Waveform: return QCoreApplication::translate("TimelineLayout", "Audio");
    case RowKind::Script: return QCoreApplication::translate("TimelineLayout", "Script");
    case RowKind::Mouth: return QCoreApplication::translate("TimelineLayout", "Mouth");
    case RowKind::Emotion: return QCoreApplication::translate("TimelineLayout", "Emotion");
    case RowKind::Blink: return QCoreApplication::translate("TimelineLayout", "Blinks");
    case RowKind::Head: return QCoreApplication::translate("TimelineLayout", "Head");
    case RowKind::Gaze: return QCoreApplication::translate("TimelineLayout", "Gaze");
    case RowKind::Pose: return QCoreApplication::translate("TimelineLayout", "Pose");
    }
    return {};
}

QVector<int> stackInLanes(const QVector<Span> &spans)
{
    QVector<int> order(spans.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return spans[a].start < spans[b].start; });
    QVector<int> lanes(spans.size(), 0);
    QVector<double> laneEnds; // where each lane's last span ends
    constexpr double kTouch = 1e-9;
    for (int i : order) {
        const auto free = std::find_if(
            laneEnds.begin(), laneEnds.end(), [&](double end) { return end <= spans[i].start + kTouch; });
        if (free == laneEnds.end()) {
            lanes[i] = int(laneEnds.size());
            laneEnds.append(spans[i].end);
        } else {
            lanes[i] = int(free - laneEnds.begin());
            *free = spans[i].end;
        }
    }
    return lanes;
}

TimelineLayout::TimelineLayout()
{
    // Comfortable: what a tall screen gives each row. Compact: the least at which the items
    // still read (the script's hanzi over its pinyin, a mouth's drawing, an emotion's name over
    // its envelope, a key's diamond), so that every row shows on a 1280 x 720 screen.
    struct Heights
    {
        RowKind kind;
        int comfortable;
        int compact;
    };
    const Heights heights[]
        = {{RowKind::Waveform, 66, 44}, {RowKind::Script, 42, 32}, {RowKind::Mouth, 50, 34}, {RowKind::Emotion, 38, 28},
            {RowKind::Blink, 22, 16}, {RowKind::Head, 34, 20}, {RowKind::Gaze, 24, 15}, {RowKind::Pose, 24, 15}};
    m_rows.append({RowKind::Ruler, 0, kRulerHeight, kRulerHeight, 1, kRulerHeight, kRulerHeight});
    for (const Heights &h : heights)
        m_rows.append({h.kind, 0, h.comfortable, h.comfortable, 1, h.compact, h.comfortable});
    placeRows();
}

int TimelineLayout::comfortableHeight() const
{
    int sum = 0;
    for (const TimelineRow &r : m_rows)
        sum += r.kind == RowKind::Ruler ? 0 : r.comfortable * r.lanes;
    return sum;
}

int TimelineLayout::compactHeight() const
{
    int sum = 0;
    for (const TimelineRow &r : m_rows)
        sum += r.kind == RowKind::Ruler ? 0 : r.compact * r.lanes;
    return sum;
}

bool TimelineLayout::fitRows(int available)
{
    m_available = available;
    return placeRows();
}

bool TimelineLayout::placeRows()
{
    const int comfortable = comfortableHeight(), compact = compactHeight();
    const double share
        = comfortable > compact ? std::clamp(double(m_available - compact) / (comfortable - compact), 0.0, 1.0) : 1.0;
    bool changed = false;
    int top = 0;
    for (TimelineRow &r : m_rows) {
        if (r.kind == RowKind::Ruler)
            continue;
        const int lane = r.compact + int(std::floor(share * (r.comfortable - r.compact)));
        changed = changed || lane != r.laneHeight || r.height != lane * r.lanes;
        r.laneHeight = lane;
        r.height = lane * r.lanes;
        r.top = top;
        top += r.height;
    }
    return changed;
}

bool TimelineLayout::setItemLanes(RowKind kind, const QVector<int> &lanes)
{
    if (kind == RowKind::Waveform)
        m_audioLanes = lanes;
    else if (kind == RowKind::Emotion)
        m_emotionLanes = lanes;
    else
        return false;
    const int count = 1 + (lanes.isEmpty() ? 0 : *std::max_element(lanes.begin(), lanes.end()));
    for (TimelineRow &r : m_rows) {
        if (r.kind == kind && r.lanes != count) {
            r.lanes = count;
            placeRows();
            return true;
        }
    }
    return false;
}

int TimelineLayout::laneOf(RowKind kind, int index) const
{
    const QVector<int> *lanes = kind == RowKind::Waveform ? &m_audioLanes
        : kind == RowKind::Emotion                        ? &m_emotionLanes
                                                          : nullptr;
    return lanes ? lanes->value(index, 0) : 0;
}

int TimelineLayout::contentHeight() const
{
    return m_rows.last().top + m_rows.last().height;
}

const TimelineRow &TimelineLayout::row(RowKind kind) const
{
    for (const TimelineRow &r : m_rows)
        if (r.kind == kind)
            return r;
    return m_rows.first();
}

QRect TimelineLayout::rowRect(RowKind kind, int viewportWidth) const
{
    const TimelineRow &r = row(kind);
    const int top = kind == RowKind::Ruler ? 0 : kRulerHeight + r.top - m_verticalScroll;
    return QRect(kLabelWidth, top, std::max(0, viewportWidth - kLabelWidth), r.height);
}

QRect TimelineLayout::laneRect(RowKind kind, int lane, int viewportWidth) const
{
    const TimelineRow &r = row(kind);
    const QRect whole = rowRect(kind, viewportWidth);
    return QRect(
        whole.left(), whole.top() + std::clamp(lane, 0, r.lanes - 1) * r.laneHeight, whole.width(), r.laneHeight);
}

std::optional<RowKind> TimelineLayout::rowAt(int y) const
{
    if (y < kRulerHeight)
        return RowKind::Ruler;
    const int content = y - kRulerHeight + m_verticalScroll;
    for (const TimelineRow &r : m_rows)
        if (r.kind != RowKind::Ruler && content >= r.top && content < r.top + r.height)
            return r.kind;
    return std::nullopt;
}

} // namespace toonface
