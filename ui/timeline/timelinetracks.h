#pragma once

#include "timeline/timelinepainter.h"

// The rows that hold items, each painted over its visible time range (timelinepainter.cpp
// paints the frame around them: labels, ruler, waveform, playhead).
namespace toonface::tracks {

// The colours of the dock.
namespace colors {
inline const QColor kBackground(0x1f, 0x21, 0x25);
inline const QColor kRowEven(0x27, 0x29, 0x2e);
inline const QColor kRowOdd(0x2b, 0x2d, 0x33);
inline const QColor kText(0xdc, 0xde, 0xe2);
inline const QColor kDimText(0x9a, 0x9e, 0xa6);
inline const QColor kSelection(0xff, 0xd2, 0x4a);
inline const QColor kGrid(0x36, 0x39, 0x40);
} // namespace colors

// [first, last) of `spans` (sorted, not overlapping much) that meet the time range [t0, t1].
std::pair<qsizetype, qsizetype> visibleRange(const QVector<Span> &spans, double t0, double t1);

void paintScriptRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintMouthRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintEmotionRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintBlinkRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintHeadRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintGazeRow(QPainter &p, const TimelineScene &s, double t0, double t1);
void paintPoseRow(QPainter &p, const TimelineScene &s, double t0, double t1);

} // namespace toonface::tracks
