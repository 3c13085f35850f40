#include "timeline/timelineedits.h"

#include "speech/pinyin.h"
#include "speech/syllableshapes.h"
#include "timeline/audioclipedits.h"
#include "timeline/posetrack.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <limits>

namespace toonface {

namespace {

// Two times this close are the same point (project files keep milliseconds).
constexpr double kSameTime = 1e-6;
// Keys moved together keep at least this much time from their unselected neighbours.
constexpr double kKeyGap = 1e-3;
// A mouth key inserted past the last cue holds this long.
constexpr double kInsertedHold = 0.2;

bool sameTime(double a, double b)
{
    return std::abs(a - b) < kSameTime;
}

QVector<Span> dragSpanEdgeOnce(QVector<Span> spans, int index, SpanEdge edge, double to, double minSpan)
{
    Span &s = spans[index];
    if (edge == SpanEdge::End) {
        to = std::max(to, s.start + minSpan);
        double boundary = to;
        double previousOldEnd = s.end;
        s.end = to;
        for (int j = index + 1; j < spans.size(); ++j) {
            Span &n = spans[j];
            const bool touched = sameTime(n.start, previousOldEnd);
            if (!touched && n.start >= boundary - kSameTime)
                break;
            const double oldEnd = n.end;
            n.start = boundary;
            n.end = std::max(n.end, n.start + minSpan);
            if (n.end == oldEnd)
                break;
            boundary = n.end;
            previousOldEnd = oldEnd;
        }
        return spans;
    }
    to = std::min(to, s.end - minSpan);
    double boundary = to;
    double nextOldStart = s.start;
    s.start = to;
    for (int j = index - 1; j >= 0; --j) {
        Span &p = spans[j];
        const bool touched = sameTime(p.end, nextOldStart);
        if (!touched && p.end <= boundary + kSameTime)
            break;
        const double oldStart = p.start;
        p.end = boundary;
        p.start = std::min(p.start, p.end - minSpan);
        if (p.start == oldStart)
            break;
        boundary = p.start;
        nextOldStart = oldStart;
    }
    return spans;
}

// The key order kept with unselected neighbours: dt clamped for keys at `times`.
double clampKeyMove(const QVector<double> &times, const QVector<int> &selected, double dt)
{
    if (selected.isEmpty())
        return dt;
    QVector<bool> isSelected(times.size(), false);
    for (int i : selected)
        if (i >= 0 && i < times.size())
            isSelected[i] = true;
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (int i : selected) {
        if (i < 0 || i >= times.size())
            continue;
        lo = std::max(lo, -times[i]);
        for (int j = i - 1; j >= 0; --j)
            if (!isSelected[j]) {
                lo = std::max(lo, times[j] + kKeyGap - times[i]);
                break;
            }
        for (int j = i + 1; j < times.size(); ++j)
            if (!isSelected[j]) {
                hi = std::min(hi, times[j] - kKeyGap - times[i]);
                break;
            }
    }
    return lo > hi ? 0.0 : std::clamp(dt, lo, hi);
}

QVector<double> keyTimes(const Animation &a, ItemKind kind)
{
    QVector<double> t;
    const Timeline &tl = a.timeline;
    switch (kind) {
    case ItemKind::Head:
        for (const HeadKey &k : tl.headKeys())
            t.append(k.time);
        break;
    case ItemKind::Gaze:
        for (const GazeKey &k : tl.gazeKeys())
            t.append(k.time);
        break;
    case ItemKind::Pose: t = poseKeyTimes(tl); break;
    default: break;
    }
    return t;
}

void setKeyTimes(Animation &a, ItemKind kind, const QVector<double> &t)
{
    Timeline &tl = a.timeline;
    if (kind == ItemKind::Head) {
        QVector<HeadKey> keys = tl.headKeys();
        for (qsizetype i = 0; i < keys.size(); ++i)
            keys[i].time = t[i];
        tl.setHeadKeys(keys);
    } else if (kind == ItemKind::Gaze) {
        QVector<GazeKey> keys = tl.gazeKeys();
        for (qsizetype i = 0; i < keys.size(); ++i)
            keys[i].time = t[i];
        tl.setGazeKeys(keys);
    } else if (kind == ItemKind::Pose) {
        setPoseKeyTimes(tl, t);
    }
}

template<class T>
void removeIndices(QVector<T> &items, QVector<int> indices)
{
    std::sort(indices.begin(), indices.end(), std::greater<int>());
    for (int i : indices)
        if (i >= 0 && i < items.size())
            items.removeAt(i);
}

// A piecewise linear map of times through (old, new) anchor pairs; the identity outside them.
class TimeMap
{
public:
    void add(double from, double to) { m_anchors.append({from, to}); }
    void finish()
    {
        std::stable_sort(m_anchors.begin(), m_anchors.end(), [](auto &a, auto &b) { return a.first < b.first; });
        QVector<std::pair<double, double>> kept;
        for (const auto &a : m_anchors) {
            if (!kept.isEmpty() && sameTime(kept.last().first, a.first))
                continue;
            kept.append({a.first, kept.isEmpty() ? a.second : std::max(a.second, kept.last().second)});
        }
        m_anchors = kept;
    }
    double operator()(double t) const
    {
        if (m_anchors.isEmpty() || t <= m_anchors.first().first)
            return m_anchors.isEmpty() ? t : t + (m_anchors.first().second - m_anchors.first().first);
        if (t >= m_anchors.last().first)
            return t + (m_anchors.last().second - m_anchors.last().first);
        const auto hi = std::upper_bound(m_anchors.begin(), m_anchors.end(), t,
            [](double v, const std::pair<double, double> &a) { return v < a.first; });
        const auto lo = hi - 1;
        if (sameTime(lo->first, t))
            return lo->second;
        const double s = (t - lo->first) / (hi->first - lo->first);
        return lo->second + (hi->second - lo->second) * s;
    }

private:
    QVector<std::pair<double, double>> m_anchors;
};

QVector<ShapeKey> retimedShapes(const LipsyncSyllable &syllable, double start, double end)
{
    QVector<ShapeKey> keys = syllable.shapes;
    if (!syllable.pinyin.isEmpty() && !keys.isEmpty()) {
        QVector<MouthShape> shapes;
        for (const ShapeKey &k : keys)
            shapes.append(k.shape);
        return syllableShapeKeys(shapes, start, end - start);
    }
    const double oldLength = syllable.end - syllable.start;
    for (ShapeKey &k : keys) {
        const double s = oldLength > 0 ? (k.start - syllable.start) / oldLength : 0.0;
        k.start = start + s * (end - start);
    }
    return keys;
}

// Every time on the timeline (for an anchor past all of them).
double latestTime(const Animation &a)
{
    double t = a.timeline.duration();
    for (const LipsyncSyllable &s : a.syllables)
        t = std::max(t, s.end);
    return t;
}

} // namespace

QVector<Span> dragSpanEdge(QVector<Span> spans, int index, SpanEdge edge, double to, double minSpan)
{
    if (index < 0 || index >= spans.size())
        return spans;
    QVector<Span> out = dragSpanEdgeOnce(spans, index, edge, to, minSpan);
    if (edge == SpanEdge::Start) {
        double lowest = 0;
        for (int j = 0; j <= index; ++j)
            lowest = std::min(lowest, out[j].start);
        if (lowest < 0)
            out = dragSpanEdgeOnce(spans, index, edge, to - lowest, minSpan);
    }
    return out;
}

double moveSpans(QVector<Span> &spans, const QVector<int> &indices, double dt, double minSpan)
{
    QVector<int> sorted = indices;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    sorted.removeIf([&](int i) { return i < 0 || i >= spans.size(); });
    if (sorted.isEmpty())
        return 0;
    QVector<std::pair<int, int>> runs;
    for (int i : sorted) {
        if (!runs.isEmpty() && runs.last().second + 1 == i)
            runs.last().second = i;
        else
            runs.append({i, i});
    }
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (const auto &[a, b] : runs) {
        lo = std::max(lo, -spans[a].start);
        if (a > 0)
            lo = std::max(lo, spans[a - 1].start + minSpan - spans[a].start);
        if (b + 1 < spans.size())
            hi = std::min(hi, spans[b + 1].end - minSpan - spans[b].end);
    }
    dt = lo > hi ? 0.0 : std::clamp(dt, lo, hi);
    for (const auto &[a, b] : runs) {
        const double oldStart = spans[a].start, oldEnd = spans[b].end;
        for (int i = a; i <= b; ++i) {
            spans[i].start += dt;
            spans[i].end += dt;
        }
        if (a > 0 && (sameTime(spans[a - 1].end, oldStart) || spans[a - 1].end > spans[a].start))
            spans[a - 1].end = spans[a].start;
        if (b + 1 < spans.size() && (sameTime(spans[b + 1].start, oldEnd) || spans[b + 1].start < spans[b].end))
            spans[b + 1].start = spans[b].end;
    }
    return dt;
}

int itemCount(const Animation &a, ItemKind kind)
{
    const Timeline &tl = a.timeline;
    switch (kind) {
    case ItemKind::Syllable: return int(a.syllables.size());
    case ItemKind::Mouth: return int(tl.mouthKeys().size());
    case ItemKind::Emotion: return int(tl.emotionClips().size());
    case ItemKind::Blink: return int(tl.blinks().size());
    case ItemKind::Head: return int(tl.headKeys().size());
    case ItemKind::Gaze: return int(tl.gazeKeys().size());
    case ItemKind::Pose: return int(poseKeyTimes(tl).size());
    case ItemKind::Audio: return int(tl.audioClips().size());
    }
    return 0;
}

QVector<Span> itemSpans(const Animation &a, ItemKind kind)
{
    QVector<Span> spans;
    switch (kind) {
    case ItemKind::Syllable:
        for (const LipsyncSyllable &s : a.syllables)
            spans.append({s.start, s.end});
        break;
    case ItemKind::Mouth:
        for (const MouthCue &c : a.timeline.mouthCues())
            spans.append({c.start, c.end});
        break;
    case ItemKind::Emotion:
        for (const EmotionClip &c : a.timeline.emotionClips())
            spans.append({c.start, c.end});
        break;
    case ItemKind::Blink:
        for (const BlinkEvent &b : a.timeline.blinks())
            spans.append({b.time, b.time + b.duration});
        break;
    case ItemKind::Audio:
        for (const AudioClip &c : a.timeline.audioClips())
            spans.append({c.start(), c.end()});
        break;
    default:
        for (double t : keyTimes(a, kind))
            spans.append({t, t});
        break;
    }
    return spans;
}

void setItemSpans(Animation &a, ItemKind kind, const QVector<Span> &spans)
{
    Timeline &tl = a.timeline;
    switch (kind) {
    case ItemKind::Syllable: a = retimeSyllables(a, spans); break;
    case ItemKind::Mouth: {
        const QVector<Span> before = itemSpans(a, ItemKind::Mouth);
        QVector<MouthKey> keys = tl.mouthKeys();
        for (qsizetype i = 0; i < keys.size() && i < spans.size(); ++i) {
            keys[i].time = spans[i].start;
            if (keys[i].duration || !sameTime(spans[i].end, before[i].end)
                || !sameTime(spans[i].start, before[i].start))
                keys[i].duration = std::max(0.0, spans[i].end - spans[i].start);
        }
        tl.setMouthKeys(keys);
        break;
    }
    case ItemKind::Emotion: {
        QVector<EmotionClip> clips = tl.emotionClips();
        for (qsizetype i = 0; i < clips.size() && i < spans.size(); ++i) {
            clips[i].start = spans[i].start;
            clips[i].end = spans[i].end;
        }
        tl.setEmotionClips(clips);
        break;
    }
    case ItemKind::Blink: {
        QVector<BlinkEvent> blinks = tl.blinks();
        for (qsizetype i = 0; i < blinks.size() && i < spans.size(); ++i) {
            blinks[i].time = spans[i].start;
            blinks[i].duration = spans[i].end - spans[i].start;
        }
        tl.setBlinks(blinks);
        break;
    }
    case ItemKind::Audio: break; // moved and trimmed by audioclipedits.h
    default: {
        QVector<double> t;
        for (const Span &s : spans)
            t.append(s.start);
        setKeyTimes(a, kind, t);
        break;
    }
    }
}

double itemTime(const Animation &a, const ItemRef &item)
{
    const QVector<Span> spans = itemSpans(a, item.kind);
    return item.index >= 0 && item.index < spans.size() ? spans[item.index].start : 0.0;
}

Animation retimeSyllables(const Animation &animation, const QVector<Span> &times)
{
    Animation out = animation;
    TimeMap map;
    bool changed = false;
    for (qsizetype i = 0; i < out.syllables.size() && i < times.size(); ++i) {
        const LipsyncSyllable &old = animation.syllables[i];
        const Span &t = times[i];
        if (sameTime(old.start, t.start) && sameTime(old.end, t.end)) {
            map.add(old.start, old.start);
            map.add(old.end, old.end);
            continue;
        }
        changed = true;
        LipsyncSyllable &syl = out.syllables[i];
        syl.shapes = retimedShapes(old, t.start, t.end);
        syl.start = t.start;
        syl.end = t.end;
        map.add(old.start, t.start);
        for (qsizetype k = 0; k < old.shapes.size() && k < syl.shapes.size(); ++k)
            map.add(old.shapes[k].start, syl.shapes[k].start);
        map.add(old.end, t.end);
    }
    if (!changed)
        return animation;
    map.add(0, 0);
    const double far = std::max(latestTime(animation), latestTime(out)) + 1.0;
    map.add(far, far);
    map.finish();
    QVector<MouthKey> keys = out.timeline.mouthKeys();
    for (MouthKey &k : keys) {
        const double start = map(k.time);
        if (k.duration)
            k.duration = std::max(0.0, map(k.time + *k.duration) - start);
        k.time = start;
    }
    out.timeline.setMouthKeys(keys);
    return out;
}

Animation dragItemEdge(const Animation &animation, ItemRef item, SpanEdge edge, double to, double minSpan)
{
    if (!hasSpans(item.kind))
        return animation;
    if (item.kind == ItemKind::Audio)
        return trimAudioClip(animation, item.index, edge, to, minSpan);
    Animation out = animation;
    setItemSpans(out, item.kind, dragSpanEdge(itemSpans(animation, item.kind), item.index, edge, to, minSpan));
    return out;
}

Animation moveItems(const Animation &animation, const Selection &selection, double dt, double minSpan, double *applied)
{
    if (selection.hasKind(ItemKind::Audio))
        return moveAudioClips(animation, selection.indices(ItemKind::Audio), dt, applied);
    // The most restrictive clamp of every kind, so that all move together.
    for (int k = 0; k < kItemKindCount; ++k) {
        const auto kind = ItemKind(k);
        const QVector<int> indices = selection.indices(kind);
        if (indices.isEmpty())
            continue;
        if (hasSpans(kind)) {
            QVector<Span> spans = itemSpans(animation, kind);
            dt = moveSpans(spans, indices, dt, minSpan);
        } else {
            dt = clampKeyMove(keyTimes(animation, kind), indices, dt);
        }
    }
    if (applied)
        *applied = dt;
    if (dt == 0)
        return animation; // exactly: spans written back would differ in their last bits
    Animation out = animation;
    for (int k = 0; k < kItemKindCount; ++k) {
        const auto kind = ItemKind(k);
        const QVector<int> indices = selection.indices(kind);
        if (indices.isEmpty())
            continue;
        if (hasSpans(kind)) {
            QVector<Span> spans = itemSpans(out, kind);
            moveSpans(spans, indices, dt, minSpan);
            setItemSpans(out, kind, spans);
        } else {
            QVector<double> times = keyTimes(out, kind);
            for (int i : indices)
                if (i >= 0 && i < times.size())
                    times[i] += dt;
            setKeyTimes(out, kind, times);
        }
    }
    return out;
}

Animation deleteItems(const Animation &animation, const Selection &selection)
{
    Animation out = animation;
    Timeline &tl = out.timeline;

    // Syllables first: their silence is written as mouth keys, which later steps index.
    QVector<int> syllables = selection.indices(ItemKind::Syllable);
    QVector<int> mouth = selection.indices(ItemKind::Mouth);
    if (!syllables.isEmpty()) {
        QVector<MouthKey> keys = tl.mouthKeys();
        QVector<MouthKey> removed;
        for (qsizetype i = 0; i < keys.size(); ++i) {
            const bool inside = std::any_of(syllables.begin(), syllables.end(), [&](int s) {
                const LipsyncSyllable &syl = animation.syllables[s];
                return keys[i].time >= syl.start - kSameTime && keys[i].time < syl.end - kSameTime;
            });
            if (inside || mouth.contains(int(i)))
                removed.append(keys[i]);
        }
        keys.removeIf([&](const MouthKey &k) { return removed.contains(k); });
        for (int s : syllables) {
            const LipsyncSyllable &syl = animation.syllables[s];
            keys.append({syl.start, MouthShape::M, 1.0, syl.end - syl.start});
        }
        tl.setMouthKeys(keys);
        removeIndices(out.syllables, syllables);
        mouth.clear(); // removed with the syllables' keys above
    }
    if (!mouth.isEmpty()) {
        QVector<Span> spans = itemSpans(out, ItemKind::Mouth);
        QVector<MouthKey> keys = tl.mouthKeys();
        std::sort(mouth.begin(), mouth.end(), std::greater<int>());
        for (int i : mouth) {
            if (i <= 0 || i >= keys.size())
                continue;
            if (sameTime(spans[i - 1].end, spans[i].start)) {
                spans[i - 1].end = spans[i].end;
                keys[i - 1].duration = spans[i - 1].end - spans[i - 1].start;
            }
        }
        removeIndices(keys, mouth);
        tl.setMouthKeys(keys);
    }
    QVector<EmotionClip> clips = tl.emotionClips();
    removeIndices(clips, selection.indices(ItemKind::Emotion));
    tl.setEmotionClips(clips);
    QVector<BlinkEvent> blinks = tl.blinks();
    removeIndices(blinks, selection.indices(ItemKind::Blink));
    tl.setBlinks(blinks);
    QVector<HeadKey> head = tl.headKeys();
    removeIndices(head, selection.indices(ItemKind::Head));
    tl.setHeadKeys(head);
    QVector<GazeKey> gaze = tl.gazeKeys();
    removeIndices(gaze, selection.indices(ItemKind::Gaze));
    tl.setGazeKeys(gaze);
    removePoseKeys(tl, selection.indices(ItemKind::Pose));
    // Last: the clips' spans are as before, and their syllables and keys go with them.
    return removeAudioClips(out, selection.indices(ItemKind::Audio));
}

namespace {

// `animation` with `change` applied to each of its mouth keys at `keys` (indices out of range
// are passed over).
template<typename Change>
Animation withMouthKeys(const Animation &animation, const QVector<int> &keys, Change change)
{
    Animation out = animation;
    QVector<MouthKey> mouth = out.timeline.mouthKeys();
    for (int i : keys)
        if (i >= 0 && i < mouth.size())
            change(mouth[i]);
    out.timeline.setMouthKeys(mouth);
    return out;
}

} // namespace

Animation setMouthShape(const Animation &animation, const QVector<int> &keys, MouthShape shape)
{
    return withMouthKeys(animation, keys, [shape](MouthKey &k) { k.shape = shape; });
}

Animation setMouthWeight(const Animation &animation, const QVector<int> &keys, double weight)
{
    const double w = std::clamp(weight, 0.0, 1.0);
    return withMouthKeys(animation, keys, [w](MouthKey &k) { k.weight = w; });
}

Animation insertMouthKey(const Animation &animation, double time, MouthShape shape, double minSpan, int *index)
{
    Animation out = animation;
    const QVector<Span> spans = itemSpans(animation, ItemKind::Mouth);
    QVector<MouthKey> keys = out.timeline.mouthKeys();
    time = std::max(0.0, time);
    MouthKey added {time, shape, 1.0, kInsertedHold};
    for (qsizetype i = 0; i < spans.size(); ++i) {
        if (sameTime(spans[i].start, time)) {
            keys[i].shape = shape;
            out.timeline.setMouthKeys(keys);
            if (index)
                *index = int(i);
            return out;
        }
        if (spans[i].start < time && time < spans[i].end) {
            const double at = std::clamp(
                time, spans[i].start + minSpan, std::max(spans[i].start + minSpan, spans[i].end - minSpan));
            keys[i].duration = at - spans[i].start;
            added = {at, shape, 1.0, std::max(minSpan, spans[i].end - at)};
            break;
        }
        if (spans[i].start > time) {
            added.duration = std::min(kInsertedHold, spans[i].start - time);
            break;
        }
    }
    keys.append(added);
    out.timeline.setMouthKeys(keys);
    if (index)
        *index = int(out.timeline.mouthKeys().indexOf(added));
    return out;
}

Animation setEmotionIntensity(const Animation &animation, int clip, double intensity)
{
    Animation out = animation;
    QVector<EmotionClip> clips = out.timeline.emotionClips();
    if (clip >= 0 && clip < clips.size())
        clips[clip].intensity = std::clamp(intensity, 0.0, 1.0);
    out.timeline.setEmotionClips(clips);
    return out;
}

Animation setEmotionFades(const Animation &animation, int clip, double fadeIn, double fadeOut)
{
    Animation out = animation;
    QVector<EmotionClip> clips = out.timeline.emotionClips();
    if (clip < 0 || clip >= clips.size())
        return out;
    EmotionClip &c = clips[clip];
    const double length = std::max(0.0, c.end - c.start);
    c.fadeIn = std::clamp(fadeIn, 0.0, length);
    c.fadeOut = std::clamp(fadeOut, 0.0, length - c.fadeIn);
    out.timeline.setEmotionClips(clips);
    return out;
}

Animation insertEmotion(
    const Animation &animation, Emotion emotion, double start, double end, double intensity, int *index)
{
    Animation out = animation;
    start = std::max(0.0, start);
    if (end <= start)
        return out;
    QVector<EmotionClip> clips;
    auto keep = [&](EmotionClip c) {
        if (c.end - c.start < kKeyGap)
            return;
        const double length = c.end - c.start;
        c.fadeIn = std::min(c.fadeIn, length);
        c.fadeOut = std::min(c.fadeOut, length - c.fadeIn);
        clips.append(c);
    };
    for (const EmotionClip &c : animation.timeline.emotionClips()) {
        if (c.end <= start || c.start >= end) {
            clips.append(c);
            continue;
        }
        EmotionClip before = c, after = c;
        before.end = start;
        after.start = end;
        if (c.start < start)
            keep(before);
        if (c.end > end)
            keep(after);
    }
    const double length = end - start;
    EmotionClip added {
        start, end, emotion, std::clamp(intensity, 0.0, 1.0), std::min(0.3, length / 4), std::min(0.3, length / 4)};
    clips.append(added);
    out.timeline.setEmotionClips(clips);
    if (index)
        *index = int(out.timeline.emotionClips().indexOf(added));
    return out;
}

std::optional<Animation> setSyllablePinyin(
    const Animation &animation, int syllable, const QString &text, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (syllable < 0 || syllable >= animation.syllables.size())
        return fail(QCoreApplication::translate("toonface::TimelineEdits", "no syllable %1").arg(syllable));
    const LipsyncSyllable &old = animation.syllables[syllable];
    if (old.pinyin.isEmpty())
        return fail(QCoreApplication::translate("toonface::TimelineEdits", "'%1' is an English word: it has no pinyin")
                        .arg(old.text));
    const std::optional<PinyinSyllable> parsed = parsePinyinSyllable(text.trimmed());
    const QVector<MouthShape> shapes = parsed ? syllableShapes(parsed->pinyin) : QVector<MouthShape>();
    if (shapes.isEmpty())
        return fail(QCoreApplication::translate("toonface::TimelineEdits", "'%1' is not a Mandarin syllable")
                        .arg(text.trimmed()));

    Animation out = animation;
    LipsyncSyllable &syl = out.syllables[syllable];
    syl.pinyin = parsed->pinyin;
    syl.tone = parsed->tone;
    syl.shapes = syllableShapeKeys(shapes, syl.start, syl.end - syl.start);

    // The syllable's keys are replaced; a key before it that holds into it is cut at its start;
    // the last new key holds as long as the last old one did.
    const QVector<Span> spans = itemSpans(animation, ItemKind::Mouth);
    QVector<MouthKey> keys = out.timeline.mouthKeys();
    double holdUntil = syl.end;
    QVector<MouthKey> kept;
    for (qsizetype i = 0; i < keys.size(); ++i) {
        MouthKey k = keys[i];
        if (k.time >= syl.start - kSameTime && k.time < syl.end - kSameTime) {
            holdUntil = std::max(syl.end, spans[i].end);
            continue;
        }
        if (k.time < syl.start && spans[i].end > syl.start + kSameTime)
            k.duration = syl.start - k.time;
        kept.append(k);
    }
    for (qsizetype k = 0; k < syl.shapes.size(); ++k) {
        const double from = syl.shapes[k].start;
        const double to = k + 1 < syl.shapes.size() ? syl.shapes[k + 1].start : holdUntil;
        kept.append({from, syl.shapes[k].shape, 1.0, to - from});
    }
    out.timeline.setMouthKeys(kept);
    return out;
}

Animation regenerateBlinks(const Animation &animation, quint32 seed)
{
    Animation out = animation;
    out.timeline.generateBlinks(seed, std::max(animation.timeline.duration(), latestTime(animation)));
    return out;
}

Animation addShake(const Animation &animation, double start, double end)
{
    Animation out = animation;
    if (start < end)
        out.timeline.addShake(start, end);
    return out;
}

Animation addNod(const Animation &animation, double start, double end)
{
    Animation out = animation;
    if (start < end)
        out.timeline.addNod(start, end);
    return out;
}

std::optional<Span> selectionRange(const Animation &animation, const Selection &selection)
{
    std::optional<Span> range;
    for (int k = 0; k < kItemKindCount; ++k) {
        const auto kind = ItemKind(k);
        const QVector<int> indices = selection.indices(kind);
        if (indices.isEmpty())
            continue;
        const QVector<Span> spans = itemSpans(animation, kind);
        for (int i : indices) {
            if (i < 0 || i >= spans.size())
                continue;
            if (!range)
                range = spans[i];
            range->start = std::min(range->start, spans[i].start);
            range->end = std::max(range->end, spans[i].end);
        }
    }
    return range;
}

double snapTime(double t, double fps, const QVector<double> &boundaries, double tolerance)
{
    const auto at = std::lower_bound(boundaries.begin(), boundaries.end(), t);
    double best = std::numeric_limits<double>::infinity();
    if (at != boundaries.end())
        best = *at;
    if (at != boundaries.begin() && std::abs(*(at - 1) - t) < std::abs(best - t))
        best = *(at - 1);
    if (std::abs(best - t) <= tolerance)
        return best;
    return fps > 0 ? std::round(t * fps) / fps : t;
}

QVector<double> syllableBoundaries(const Animation &animation)
{
    QVector<double> b;
    for (const LipsyncSyllable &s : animation.syllables) {
        b.append(s.start);
        b.append(s.end);
    }
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
}

} // namespace toonface
