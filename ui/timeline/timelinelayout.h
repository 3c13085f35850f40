#pragma once

#include "timeline/timelineedits.h"
#include "timeline/timelineselection.h"

#include <QRect>
#include <QString>
#include <QVector>

#include <limits>
#include <optional>

namespace toonface {

// The rows of the timeline dock, top to bottom.
enum class RowKind { Ruler, Waveform, Script, Mouth, Emotion, Blink, Head, Gaze, Pose };

struct TimelineRow
{
    RowKind kind;
    int top = 0; // in content coordinates: the rows below the ruler scroll vertically
    int height = 0; // laneHeight * lanes
    int laneHeight = 0; // between compact and comfortable, as the viewport's height allows
    int lanes = 1; // overlapping clips stack in sub-lanes, one above the other
    int compact = 0; // the least a lane's items can be read and taken at
    int comfortable = 0;
};

// The items a row holds (none for the ruler and the waveform).
std::optional<ItemKind> itemKindOf(RowKind row);
RowKind rowOf(ItemKind kind);
QString rowTitle(RowKind row);

// The sub-lane of each span (in the order given) so that no two overlapping spans share one:
// each takes the lowest lane free at its start, so a row of clips that never overlap keeps one
// lane. Spans that only touch (one ends where the next starts) share a lane.
QVector<int> stackInLanes(const QVector<Span> &spans);

// Where things are in the timeline's viewport: a label column on the left, the ruler on top,
// the rows below it; time runs left to right at pixelsPerSecond() from scrollTime() at the
// label column's edge. A plain value.
class TimelineLayout
{
public:
    static constexpr int kLabelWidth = 92;
    static constexpr int kRulerHeight = 30;

    TimelineLayout();

    const QVector<TimelineRow> &rows() const { return m_rows; }
    // The rows' total height below the ruler, as they are now; at their comfortable heights;
    // at their compact heights.
    int contentHeight() const;
    int comfortableHeight() const;
    int compactHeight() const;
    // The rows' room below the ruler: they shrink from comfortable towards compact (all in the
    // same proportion) to fit in it, never below compact (the rows then scroll). Returns whether
    // the rows' heights changed.
    bool fitRows(int available);
    const TimelineRow &row(RowKind kind) const;
    // Gives each item of `kind`'s row its lane (see stackInLanes()); the row grows to hold them
    // all and the rows below move down. Returns whether the rows' heights changed.
    bool setItemLanes(RowKind kind, const QVector<int> &lanes);
    // The lane item `index` of `kind`'s row is drawn in (0 for rows without lanes).
    int laneOf(RowKind kind, int index) const;

    double pixelsPerSecond() const { return m_pixelsPerSecond; }
    void setPixelsPerSecond(double pps) { m_pixelsPerSecond = pps; }
    double scrollTime() const { return m_scrollTime; }
    void setScrollTime(double t) { m_scrollTime = t; }
    int verticalScroll() const { return m_verticalScroll; }
    void setVerticalScroll(int y) { m_verticalScroll = y; }

    double xOf(double t) const { return kLabelWidth + (t - m_scrollTime) * m_pixelsPerSecond; }
    double timeAt(double x) const { return m_scrollTime + (x - kLabelWidth) / m_pixelsPerSecond; }

    // A row's rectangle in the viewport (ruler fixed on top, the others scrolled), the time area only.
    QRect rowRect(RowKind kind, int viewportWidth) const;
    // One lane of a row, likewise.
    QRect laneRect(RowKind kind, int lane, int viewportWidth) const;
    // The row at viewport y, nullopt below the last.
    std::optional<RowKind> rowAt(int y) const;

private:
    // Sets each row's lane height and top from the room and the lanes; true when any changed.
    bool placeRows();

    QVector<TimelineRow> m_rows;
    int m_available = std::numeric_limits<int>::max();
    QVector<int> m_audioLanes;
    QVector<int> m_emotionLanes;
    double m_pixelsPerSecond = 100;
    double m_scrollTime = 0;
    int m_verticalScroll = 0;
};

} // namespace toonface
