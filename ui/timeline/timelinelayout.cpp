#include "timeline/timelinelayout.h"

#include <QCoreApplication>

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

TimelineLayout::TimelineLayout()
{
    const std::pair<RowKind, int> heights[] = {{RowKind::Waveform, 66}, {RowKind::Script, 42}, {RowKind::Mouth, 50},
        {RowKind::Emotion, 38}, {RowKind::Blink, 22}, {RowKind::Head, 34}, {RowKind::Gaze, 24}, {RowKind::Pose, 24}};
    m_rows.append({RowKind::Ruler, 0, kRulerHeight});
    int top = 0;
    for (const auto &[kind, height] : heights) {
        m_rows.append({kind, top, height});
        top += height;
    }
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
