#include "anim/timelineevaluator.h"

#include "anim/easing.h"
#include "anim/keycurve.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pointtable.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toonface {

namespace {

using Mouth = std::array<QPointF, 4>;

Mouth lerpMouth(const Mouth &a, const Mouth &b, double s)
{
    Mouth m;
    for (int k = 0; k < 4; ++k)
        m[k] = a[k] + (b[k] - a[k]) * s;
    return m;
}

QPointF lerpPoint(const QPointF &a, const QPointF &b, double s)
{
    return a + (b - a) * s;
}

HeadPose lerpHead(const HeadPose &a, const HeadPose &b, double s)
{
    HeadPose h;
    h.rotationDeg = a.rotationDeg + (b.rotationDeg - a.rotationDeg) * s;
    h.translation = a.translation + (b.translation - a.translation) * s;
    h.scale = a.scale + (b.scale - a.scale) * s;
    return h;
}

// Indices of the intervals active at t among intervals sorted by start, with endsSoFar[i] the
// latest end among intervals 0..i: scanning back from the last start <= t may stop as soon as
// no earlier interval reaches past t.
template<class Visit>
void forActive(const QVector<double> &starts, const QVector<double> &endsSoFar, double t, Visit visit)
{
    for (qsizetype i = segmentAt(starts, t); i >= 0 && endsSoFar[i] > t; --i)
        visit(i);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

} // namespace

double TimelineEvaluator::Envelope::at(double t) const
{
    if (t < start || t >= end)
        return 0.0;
    if (t < fadeInEnd)
        return intensity * ease((t - start) / (fadeInEnd - start));
    if (t > fadeOutStart)
        return intensity * ease((end - t) / (end - fadeOutStart));
    return intensity;
}

double TimelineEvaluator::Blink::openAt(double t) const
{
    if (t <= start || t >= end)
        return 1.0;
    if (t < shutAt)
        return 1.0 - ease((t - start) / (shutAt - start));
    if (t <= openingAt)
        return 0.0;
    return ease((t - openingAt) / (end - openingAt));
}

TimelineEvaluator::TimelineEvaluator(const Timeline &timeline, const FaceModel &face, const MouthShapeSet &shapes)
    : m_duration(timeline.duration())
{
    const Fapu fapu = face.fapu();
    for (int k = 0; k < 4; ++k)
        m_mouthIndex[k] = pt::idx(kMouthControlIds[k]);
    m_restingMouth = shapes.displacements(MouthShape::M, face);
    buildMouth(timeline, face, shapes);

    for (Emotion e : kAllEmotions) {
        // emotionPose is linear in its intensity's weight (emotionWeight): cache it once at full
        // intensity.
        const Pose full = emotionPose(face, e, 1.0);
        EmotionCache &cache = m_emotionCache[int(e)];
        for (int i = 0; i < kPointCount; ++i) {
            if (!full.offset[i].isNull()) {
                cache.points.append(i);
                cache.offsets.append(full.offset[i]);
            }
        }
        cache.lidScaleDelta = full.leftEyeOpen - 1.0;
    }
    double endsSoFar = -kInf;
    for (const EmotionClip &c : timeline.emotionClips()) {
        const double length = std::max(0.0, c.end - c.start);
        double fadeIn = std::max(0.0, c.fadeIn);
        double fadeOut = std::max(0.0, c.fadeOut);
        if (fadeIn + fadeOut > length) {
            const double shrink = length / (fadeIn + fadeOut);
            fadeIn *= shrink;
            fadeOut *= shrink;
        }
        // Held at the weight emotionPose gives the clip's intensity; faded in and out from it
        // along the ease the exports' key splines draw.
        m_clips.append({c.start, c.start + fadeIn, c.start + length - fadeOut, c.start + length,
            emotionWeight(c.intensity), int(c.emotion)});
        m_clipStarts.append(c.start);
        endsSoFar = std::max(endsSoFar, c.start + length);
        m_clipEndsSoFar.append(endsSoFar);
    }

    endsSoFar = -kInf;
    for (const BlinkEvent &b : timeline.blinks()) {
        const double d = std::max(0.0, b.duration);
        const double shutAt = b.time + d * kBlinkPhases.closing;
        m_blinks.append({b.time, shutAt, shutAt + d * kBlinkPhases.shut, b.time + d});
        m_blinkStarts.append(b.time);
        endsSoFar = std::max(endsSoFar, b.time + d);
        m_blinkEndsSoFar.append(endsSoFar);
    }

    m_leftEyeball = pt::idx("3.6");
    m_rightEyeball = pt::idx("3.5");
    for (const GazeKey &g : timeline.gazeKeys()) {
        m_gazeTimes.append(g.time);
        m_gazeValues.append(g.offsetEs0 * fapu.es0);
    }
    for (const HeadKey &h : timeline.headKeys()) {
        m_headTimes.append(h.time);
        m_headValues.append(HeadPose {h.rotationDeg, h.translationEs0 * fapu.es0, h.scale});
    }
    buildPose(timeline, fapu.es0);
}

void TimelineEvaluator::buildPose(const Timeline &timeline, double es0)
{
    const QVector<PoseKey> &keys = timeline.poseKeys();
    for (const PoseKey &k : keys) {
        for (auto it = k.offsetsEs0.cbegin(); it != k.offsetsEs0.cend(); ++it) {
            const int index = pointIndex(it.key());
            if (index >= 0 && !m_posePoints.contains(index))
                m_posePoints.append(index);
        }
    }
    std::sort(m_posePoints.begin(), m_posePoints.end());
    const qsizetype stride = m_posePoints.size();
    for (int index : std::as_const(m_posePoints)) {
        // The jaw handle keys the lower lip (8.2); the chin follows it by rule.
        const bool mouth = pointTable()[index].group == PointGroup::Mouth;
        m_poseOnMouth.append(mouth ? 1 : 0);
        m_poseMovesMouth = m_poseMovesMouth || mouth;
    }
    for (const AudioClip &clip : timeline.audioClips()) {
        if (clip.end() > clip.start())
            m_speechSpans.append({clip.start(), clip.end()});
    }
    if (m_speechSpans.isEmpty() && m_mouthTimes.size() >= 2)
        m_speechSpans.append({m_mouthTimes.first(), m_mouthTimes.last()});
    std::sort(m_speechSpans.begin(), m_speechSpans.end());
    for (const PoseKey &k : keys) {
        if (m_poseTimes.isEmpty() || m_poseTimes.last() != k.time) {
            m_poseTimes.append(k.time);
            m_poseValues.resize(m_poseValues.size() + stride);
        }
        QPointF *values = m_poseValues.data() + (m_poseTimes.size() - 1) * stride;
        for (qsizetype j = 0; j < stride; ++j)
            values[j] = k.offsetsEs0.value(pointId(m_posePoints[j])) * es0;
    }
}

double TimelineEvaluator::speechWeightAt(double t) const
{
    double weight = 0;
    for (const auto &[start, end] : m_speechSpans) {
        if (start - kSpeechFade > t)
            break;
        if (t >= start && t <= end)
            return 1.0;
        const double away = t < start ? start - t : t - end;
        if (away < kSpeechFade)
            weight = std::max(weight, ease(1.0 - away / kSpeechFade));
    }
    return weight;
}

double TimelineEvaluator::poseOnMouthWeightAt(double t) const
{
    const double speech = speechWeightAt(t);
    if (speech == 0.0)
        return 1.0;
    double near = 0;
    const auto after = std::lower_bound(m_poseTimes.cbegin(), m_poseTimes.cend(), t);
    for (auto it : {after, after == m_poseTimes.cbegin() ? m_poseTimes.cend() : after - 1}) {
        if (it == m_poseTimes.cend())
            continue;
        const double away = std::abs(*it - t);
        if (away < kPoseKeyReach)
            near = std::max(near, ease(1.0 - away / kPoseKeyReach));
    }
    return std::max(1.0 - speech, near);
}

QVector<QPointF> TimelineEvaluator::poseOffsetsAt(double t) const
{
    const qsizetype stride = m_posePoints.size();
    QVector<QPointF> out(stride);
    if (m_poseTimes.isEmpty())
        return out;
    qsizetype i = segmentAt(m_poseTimes, t);
    double s = 0;
    if (i < 0) {
        i = 0;
    } else if (i + 1 < m_poseTimes.size()) {
        s = ease((t - m_poseTimes[i]) / (m_poseTimes[i + 1] - m_poseTimes[i]));
    }
    const QPointF *a = m_poseValues.constData() + i * stride;
    for (qsizetype j = 0; j < stride; ++j)
        out[j] = s == 0 ? a[j] : a[j] + (a[j + stride] - a[j]) * s;
    return out;
}

void TimelineEvaluator::buildMouth(const Timeline &timeline, const FaceModel &face, const MouthShapeSet &shapes)
{
    const MouthSmoothing &sm = timeline.smoothing();
    const double minHold = std::max(0.0, sm.minHold);
    const double coart = std::max(1e-6, sm.coarticulation);

    // Keys at equal times: the later one wins.
    QVector<MouthKey> keys;
    for (const MouthKey &k : timeline.mouthKeys()) {
        if (!keys.isEmpty() && keys.last().time == k.time)
            keys.last() = k;
        else
            keys.append(k);
    }
    const qsizetype n = keys.size();
    if (n == 0)
        return;

    // The nine shapes on this face; `n`-like shapes take their corners from the shape before.
    std::array<Mouth, kMouthShapeCount> shapeCache;
    for (MouthShape s : kAllMouthShapes)
        shapeCache[int(s)] = shapes.displacements(s, face);

    // Per key: when its shape stops (holdEnd) and whether silence follows.
    struct Resolved
    {
        double time;
        Mouth value;
        double holdEnd; // meaningful when silenceAfter
        bool silenceAfter;
    };
    QVector<Resolved> raw;
    raw.reserve(n);
    Mouth previous {};
    for (qsizetype i = 0; i < n; ++i) {
        const MouthKey &k = keys[i];
        const double soundEnd = k.time + std::max(0.0, k.duration.value_or(0.0));
        const double holdEnd = std::max(soundEnd, k.time + minHold);
        const double next = i + 1 < n ? keys[i + 1].time : kInf;
        const bool silenceAfter = next - soundEnd > sm.silenceHold && next > holdEnd;
        Mouth value = shapeCache[int(k.shape)];
        for (QPointF &d : value)
            d *= k.weight;
        if (shapes.preset(k.shape).cornersFromPrevious) {
            value[Left] = previous[Left];
            value[Right] = previous[Right];
        }
        raw.append({k.time, value, holdEnd, silenceAfter});
        previous = silenceAfter ? Mouth {} : value;
    }

    // Minimum hold: a run of keys each shown shorter than minHold becomes one key at the run's
    // start, mixing their shapes by how long each was shown (the last counted up to minHold).
    QVector<Resolved> keysHeld;
    for (qsizetype i = 0; i < n;) {
        const double start = raw[i].time;
        Mouth sum {};
        double weights = 0;
        qsizetype j = i;
        while (true) {
            const Resolved &r = raw[j];
            const double shown = r.silenceAfter ? r.holdEnd - r.time : raw[j + 1].time - r.time;
            // The tolerance keeps keys spaced exactly minHold apart (up to rounding) separate.
            if (!r.silenceAfter && (r.time - start) + shown < minHold - 1e-9 && j + 1 < n) {
                for (int k = 0; k < 4; ++k)
                    sum[k] += r.value[k] * shown;
                weights += shown;
                ++j;
                continue;
            }
            const double w = weights > 0 ? std::min(shown, minHold) : 1.0;
            for (int k = 0; k < 4; ++k)
                sum[k] = (sum[k] + r.value[k] * w) / (weights + w);
            keysHeld.append({start, sum, r.holdEnd, r.silenceAfter});
            break;
        }
        i = j + 1;
    }

    auto node = [&](double t, const Mouth &v) {
        m_mouthTimes.append(t);
        m_mouthValues.append(v);
    };
    const Mouth shut {};
    node(keysHeld.first().time - coart, shut);
    for (qsizetype r = 0; r < keysHeld.size(); ++r) {
        const Resolved &k = keysHeld[r];
        node(k.time, k.value);
        const bool last = r + 1 == keysHeld.size();
        if (k.silenceAfter) {
            const double gap = last ? kInf : keysHeld[r + 1].time - k.holdEnd;
            const double c = std::min(coart, gap / 2);
            if (k.holdEnd > k.time)
                node(k.holdEnd, k.value);
            node(k.holdEnd + c, shut);
            if (!last && keysHeld[r + 1].time - c > k.holdEnd + c)
                node(keysHeld[r + 1].time - c, shut);
        } else {
            const double slot = keysHeld[r + 1].time - k.time;
            const double w = std::min(coart, slot);
            if (w < slot)
                node(keysHeld[r + 1].time - w, k.value);
        }
    }
}

std::array<QPointF, 4> TimelineEvaluator::mouthAt(double t) const
{
    if (m_mouthTimes.isEmpty())
        return m_restingMouth;
    return easedAt(m_mouthTimes, m_mouthValues, t, lerpMouth);
}

double TimelineEvaluator::blinkOpenAt(double t) const
{
    double open = 1.0;
    forActive(m_blinkStarts, m_blinkEndsSoFar, t, [&](qsizetype i) { open = std::min(open, m_blinks[i].openAt(t)); });
    return open;
}

double TimelineEvaluator::emotionEnvelopeAt(qsizetype index, double t) const
{
    return m_clips.at(index).at(t);
}

Pose TimelineEvaluator::evaluate(double t) const
{
    Pose pose;
    const Mouth mouth = mouthAt(t);
    for (int k = 0; k < 4; ++k)
        pose.offset[m_mouthIndex[k]] = mouth[k];

    double lidScale = 1.0;
    forActive(m_clipStarts, m_clipEndsSoFar, t, [&](qsizetype i) {
        const Envelope &clip = m_clips[i];
        const double amount = clip.at(t);
        if (amount == 0.0)
            return;
        const EmotionCache &cache = m_emotionCache[clip.emotion];
        for (qsizetype j = 0; j < cache.points.size(); ++j)
            pose.offset[cache.points[j]] += cache.offsets[j] * amount;
        lidScale *= 1.0 + cache.lidScaleDelta * amount;
    });

    if (!m_gazeTimes.isEmpty()) {
        const QPointF gaze = easedAt(m_gazeTimes, m_gazeValues, t, lerpPoint);
        pose.offset[m_leftEyeball] += gaze;
        pose.offset[m_rightEyeball] += gaze;
    }

    const double open = lidScale * blinkOpenAt(t);
    pose.leftEyeOpen = open;
    pose.rightEyeOpen = open;

    if (!m_headTimes.isEmpty())
        pose.head = easedAt(m_headTimes, m_headValues, t, lerpHead);

    if (!m_poseTimes.isEmpty()) {
        const QVector<QPointF> offsets = poseOffsetsAt(t);
        const double onMouth = m_poseMovesMouth ? poseOnMouthWeightAt(t) : 1.0;
        for (qsizetype j = 0; j < offsets.size(); ++j)
            pose.offset[m_posePoints[j]] += m_poseOnMouth[j] ? offsets[j] * onMouth : offsets[j];
    }
    return pose;
}

TimelineEvaluator::ExportKeys TimelineEvaluator::exportKeys(Tracks tracks) const
{
    struct Motion
    {
        double from, to;
    };
    QVector<double> times {0.0, m_duration};
    QVector<Motion> motions;
    auto addCurve = [&](const QVector<double> &keyTimes, auto differs) {
        for (qsizetype i = 0; i < keyTimes.size(); ++i) {
            times.append(keyTimes[i]);
            if (i + 1 < keyTimes.size() && keyTimes[i] < keyTimes[i + 1] && differs(i))
                motions.append({keyTimes[i], keyTimes[i + 1]});
        }
    };
    auto addMotion = [&](double from, double to) {
        times.append(from);
        times.append(to);
        if (from < to)
            motions.append({from, to});
    };

    if (tracks & Track::Mouth)
        addCurve(m_mouthTimes, [&](qsizetype i) { return m_mouthValues[i] != m_mouthValues[i + 1]; });
    if (tracks & Track::Emotion) {
        for (const Envelope &c : m_clips) {
            if (c.intensity == 0.0 || !(c.start < c.end))
                continue;
            addMotion(c.start, c.fadeInEnd);
            addMotion(c.fadeOutStart, c.end);
        }
    }
    if (tracks & Track::Blink) {
        for (const Blink &b : m_blinks) {
            if (!(b.start < b.end))
                continue;
            addMotion(b.start, b.shutAt);
            addMotion(b.openingAt, b.end);
        }
    }
    if (tracks & Track::Gaze)
        addCurve(m_gazeTimes, [&](qsizetype i) { return m_gazeValues[i] != m_gazeValues[i + 1]; });
    if (tracks & Track::Head)
        addCurve(m_headTimes, [&](qsizetype i) { return !(m_headValues[i] == m_headValues[i + 1]); });
    if (tracks & Track::Pose) {
        const qsizetype stride = m_posePoints.size();
        addCurve(m_poseTimes, [&](qsizetype i) {
            const QPointF *a = m_poseValues.constData() + i * stride;
            return !std::equal(a, a + stride, a + stride);
        });
        // The speech taking the mouth over from the pose track and giving it back, and the
        // pose keys' reach into the speech.
        if (m_poseMovesMouth && !m_speechSpans.isEmpty()) {
            for (const auto &[start, end] : m_speechSpans) {
                addMotion(start - kSpeechFade, start);
                addMotion(end, end + kSpeechFade);
            }
            for (double key : m_poseTimes) {
                addMotion(key - kPoseKeyReach, key);
                addMotion(key, key + kPoseKeyReach);
            }
        }
    }

    // Times closer than a microsecond are one time (sums like start + fade may round apart).
    constexpr double eps = 1e-6;
    ExportKeys keys;
    std::sort(times.begin(), times.end());
    for (double t : times) {
        if (t < 0.0 || t > m_duration)
            continue;
        if (keys.times.isEmpty() || t - keys.times.last() > eps)
            keys.times.append(t);
    }
    if (keys.times.size() < 2) {
        keys.times = {0.0};
        return keys;
    }
    const qsizetype segments = keys.times.size() - 1;
    QVector<char> exact(segments, 0);
    QVector<char> partial(segments, 0);
    auto indexOf = [&](double t) {
        const auto it = std::lower_bound(keys.times.cbegin(), keys.times.cend(), t - eps);
        return qsizetype(it - keys.times.cbegin());
    };
    for (const Motion &m : motions) {
        const double from = std::max(m.from, 0.0);
        const double to = std::min(m.to, m_duration);
        if (!(to - from > eps))
            continue;
        const bool clipped = from != m.from || to != m.to;
        const qsizetype a = indexOf(from);
        const qsizetype b = indexOf(to);
        for (qsizetype s = a; s < b && s < segments; ++s)
            (b == a + 1 && !clipped ? exact : partial)[s] = 1;
    }
    keys.segments.reserve(segments);
    for (qsizetype s = 0; s < segments; ++s)
        keys.segments.append(partial[s] ? Segment::Mixed : exact[s] ? Segment::Ease : Segment::Hold);
    return keys;
}

} // namespace toonface
