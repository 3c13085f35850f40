#pragma once

#include "timeline/timelineedits.h"
#include "timeline/timelinelayout.h"

#include <QColor>
#include <QRect>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

class QPainter;

namespace toonface {

class MouthIcons;
class WaveformPeaks;

// What one paint of the timeline shows: the document's animation (an implicitly shared copy), the
// view's layout and selection and the things derived from the document that the view caches.
struct TimelineScene
{
    Animation animation; // the document's (implicitly shared, not a deep copy)
    const QVector<Span> *mouthSpans = nullptr; // itemSpans(animation, Mouth), cached by the view
    const TimelineLayout *layout = nullptr;
    const Selection *selection = nullptr;
    // Each audio clip's peaks (of its whole file; null while not read), and what its box says
    // when there are none ("Reading the sound…", an error naming the file).
    QVector<const WaveformPeaks *> clipPeaks;
    QStringList clipStatus;
    // Each clip's sample values are multiplied by its gain before drawing (clipped at full height):
    // every recording is drawn at its own loudness, a quiet one beside a loud one included.
    QVector<double> clipGains;
    const MouthIcons *icons = nullptr;
    double playhead = 0;
    std::optional<RowKind> focusRow;
    QRect rubberBand; // viewport coordinates, null when none
    std::optional<double> snapLine; // a time the current drag snapped to
    int width = 0; // viewport size
    int height = 0;
};

// The parts of an item a pointer can take hold of. An audio clip's body is taken by its title
// strip (geometry::kAudioTitle high) only: the waveform under it scrubs the playhead.
enum class HitPart { None, Body, StartEdge, EndEdge, FadeIn, FadeOut, Intensity, Weight };

struct TimelineHit
{
    std::optional<RowKind> row;
    double time = 0;
    std::optional<ItemRef> item;
    HitPart part = HitPart::None;
};

// Paints the whole viewport: label column, ruler, the audio track's clips with their waveforms,
// script row, tracks, playhead.
// Only the visible time range is walked (binary searches into the time-sorted tracks), and at
// most one item is drawn per pixel column where they are denser than that.
void paintTimeline(QPainter &painter, const TimelineScene &scene);

// The item (and its part) at viewport point `pos`.
TimelineHit hitTest(const TimelineScene &scene, QPoint pos);

// The items whose drawing meets `rect` (viewport coordinates), for rubber-band selection.
Selection itemsIn(const TimelineScene &scene, const QRect &rect);

// The colours the tracks use, also for the palettes' buttons.
QColor mouthShapeColor(MouthShape shape);
QColor emotionColor(Emotion emotion);

} // namespace toonface
