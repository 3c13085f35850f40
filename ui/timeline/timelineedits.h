#pragma once

#include "document/animation.h"
#include "timeline/timelineselection.h"

#include <QJsonObject>
#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// The timeline's edits as plain functions: each takes the animation as it is and returns it
// edited, so the widgets only turn gestures into calls and every edit is testable without them.
// Times are seconds; `minSpan` is the shortest a cue, clip, blink or syllable may become (the
// view passes one frame).

enum class SpanEdge { Start, End };

// A time span on a track: a mouth cue, an emotion clip, a blink or a syllable.
struct Span
{
    double start = 0;
    double end = 0;
    bool operator==(const Span &) const = default;
};

// Moves one edge of spans[index] to `to`. A neighbour that touched that edge follows it (the
// boundary between two cues moves); a neighbour the span grows into gives way, shrinking to
// `minSpan` and then pushed along, and so on down the track. The span keeps at least minSpan;
// no span starts before 0. Spans are sorted and do not overlap before and after.
QVector<Span> dragSpanEdge(QVector<Span> spans, int index, SpanEdge edge, double to, double minSpan);

// Moves the spans at `indices` by `dt`, clamped so that no neighbour shrinks below minSpan and
// nothing starts before 0. A neighbour that touched a moved span, or that it moves onto, gives
// way (its end or start follows the moved span). Returns the dt applied.
double moveSpans(QVector<Span> &spans, const QVector<int> &indices, double dt, double minSpan);

// The spans of each track kind that has them (Mouth: Timeline::mouthCues; Syllable, Emotion,
// Blink; Audio: where each clip is heard), and writing them back (a mouth key gets an explicit
// duration when its end changed; audio clips are moved and trimmed by audioclipedits.h only).
QVector<Span> itemSpans(const Animation &animation, ItemKind kind);
void setItemSpans(Animation &animation, ItemKind kind, const QVector<Span> &spans);
// The time of a key or the start of a span.
double itemTime(const Animation &animation, const ItemRef &item);
int itemCount(const Animation &animation, ItemKind kind);
inline bool hasSpans(ItemKind kind)
{
    return kind == ItemKind::Syllable || kind == ItemKind::Mouth || kind == ItemKind::Emotion || kind == ItemKind::Blink
        || kind == ItemKind::Audio;
}

// Syllables: new start and end times (same count, same order; `retimed` gives each changed
// syllable's shapes their starts by face-model.md's fractions — by proportion for English
// words — and moves the mouth keys with them: each key at a syllable's start, one of its shape
// starts or its end goes to the new time of that point, keys between such points keep their
// place in proportion. Keys outside the changed syllables' reach stay.
Animation retimeSyllables(const Animation &animation, const QVector<Span> &syllableTimes);

// Drags an edge of an item that has a span (mouth cue, emotion clip, blink, syllable; an audio
// clip is trimmed, see trimAudioClip).
Animation dragItemEdge(const Animation &animation, ItemRef item, SpanEdge edge, double to, double minSpan);
// Moves the selected items by dt (every kind at once; spans by moveSpans, keys keep their order
// with their unselected neighbours). *applied receives the dt applied to span kinds. A
// selection that holds audio clips moves those clips only, with what they own (moveAudioClips).
Animation moveItems(
    const Animation &animation, const Selection &selection, double dt, double minSpan, double *applied = nullptr);
// Removes the selected items. A removed mouth cue leaves the cue before it holding over its time;
// a removed syllable leaves silence (its mouth keys become one `m`); a removed audio clip goes
// with its syllables and mouth keys (removeAudioClips).
Animation deleteItems(const Animation &animation, const Selection &selection);

// Mouth keys.
Animation setMouthShape(const Animation &animation, const QVector<int> &keys, MouthShape shape);
Animation setMouthWeight(const Animation &animation, const QVector<int> &keys, double weight);
// A key of `shape` from `time`: the cue under `time` ends there and the new key holds until
// that cue's end (or for the silence hold past the last key). Returns the new key's index.
Animation insertMouthKey(
    const Animation &animation, double time, MouthShape shape, double minSpan, int *index = nullptr);

// Emotion clips.
Animation setEmotionIntensity(const Animation &animation, int clip, double intensity);
// Fades are clamped to [0, the clip's length] and their sum to its length.
Animation setEmotionFades(const Animation &animation, int clip, double fadeIn, double fadeOut);
// An emotion clip over [start, end]; clips overlapping it are cut back (or split) around it.
Animation insertEmotion(const Animation &animation, Emotion emotion, double start, double end, double intensity = 1.0,
    int *index = nullptr);

// Syllables: a new pinyin (with or without a tone: "hao3", "hǎo", "hao") re-derives the
// syllable's shapes (syllableShapes) and replaces its mouth keys. nullopt with *error when the
// text is not one Mandarin syllable or the syllable is an English word.
std::optional<Animation> setSyllablePinyin(
    const Animation &animation, int syllable, const QString &text, QString *error);

// Blinks, head.
Animation regenerateBlinks(const Animation &animation, quint32 seed);
Animation addShake(const Animation &animation, double start, double end);
Animation addNod(const Animation &animation, double start, double end);

// The time span the selection covers (from its first start to its last end).
std::optional<Span> selectionRange(const Animation &animation, const Selection &selection);

// Copy and paste: the selected mouth keys, emotion clips, blinks, head, gaze and pose keys with
// times relative to the earliest of them, as JSON (mime type kTimelineItemsMime).
inline constexpr char kTimelineItemsMime[] = "application/x-toonface-timeline-items";
QJsonObject copyItems(const Animation &animation, const Selection &selection);
// Pastes at `time`: mouth keys replace the keys in the range they cover; clips, blinks and keys
// are added (a pose key replaces one at the same time). nullopt with *error when `items` is not what copyItems writes.
// *pasted receives the pasted items.
std::optional<Animation> pasteItems(
    const Animation &animation, const QJsonObject &items, double time, QString *error, Selection *pasted = nullptr);

// Snapping: `t` moved to the nearest frame (when fps > 0) or, when closer than `tolerance`, to
// the nearest of `boundaries` (boundaries win over frames).
double snapTime(double t, double fps, const QVector<double> &boundaries, double tolerance);
// Every syllable start and end, sorted.
QVector<double> syllableBoundaries(const Animation &animation);

} // namespace toonface
