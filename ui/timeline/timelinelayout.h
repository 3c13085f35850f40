#pragma once

#include "timeline/timelineselection.h"

#include <QRect>
#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// The rows of the timeline dock, top to bottom.
enum class RowKind { Ruler, Waveform, Script, Mouth, Emotion, Blink, Head, Gaze, Pose };

struct TimelineRow
{
    RowKind kind;
    int top = 0; // in content coordinates: the rows below the ruler scroll vertically
    int height = 0;
};

// The items a row holds (none for the ruler and the waveform).
std::optional<ItemKind> itemKindOf(RowKind row);
RowKind rowOf(ItemKind kind);
QString rowTitle(RowKind row);

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
    // The rows' total height below the ruler.
    int contentHeight() const;
    const TimelineRow &row(RowKind kind) const;

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
    // The row at viewport y, nullopt below the last.
    std::optional<RowKind> rowAt(int y) const;

private:
    QVector<TimelineRow> m_rows;
    double m_pixelsPerSecond = 100;
    double m_scrollTime = 0;
    int m_verticalScroll = 0;
};

} // namespace toonface
