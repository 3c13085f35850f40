#include "track/retarget.h"

#include <algorithm>
#include <tuple>

namespace toonface {

namespace {

// Blink durations are clamped to the blink generator's range.
constexpr double kShutMiddle = 0.5 * (kBlinkPhases.closing + (kBlinkPhases.closing + kBlinkPhases.shut));

} // namespace

double blinkMiddle(const BlinkEvent &blink)
{
    return blink.time + kShutMiddle * blink.duration;
}

QVector<BlinkEvent> detectBlinks(
    const QVector<double> &times, const QVector<double> &openness, double fps, double closedBelow)
{
    QVector<BlinkEvent> blinks;
    const qsizetype n = std::min(times.size(), openness.size());
    if (n < 3)
        return blinks;
    QVector<double> sorted(openness.cbegin(), openness.cbegin() + n);
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[n / 2];
    if (!(median > 0))
        return blinks;
    const double period = fps > 0 ? 1.0 / fps : (times[n - 1] - times[0]) / double(n - 1);
    const double limit = closedBelow * median;
    qsizetype i = 0;
    while (i < n) {
        if (openness[i] >= limit) {
            ++i;
            continue;
        }
        qsizetype last = i;
        // The run, bridging single open frames.
        for (qsizetype j = i + 1; j < n; ++j) {
            if (openness[j] < limit)
                last = j;
            else if (j - last > 1)
                break;
        }
        const double first = times[i];
        const double end = times[last];
        const double middle = (first + end) / 2;
        const double duration
            = std::clamp(end - first + 3 * period, Timeline::kBlinkDurationMin, Timeline::kBlinkDurationMax);
        blinks.append({std::max(0.0, middle - kShutMiddle * duration), duration});
        i = last + 1;
    }
    return blinks;
}

namespace {

// `before` without its keys in [from, to], plus `added`, in time order.
template<typename Key>
QVector<Key> spliced(const QVector<Key> &before, const QVector<Key> &added, double from, double to)
{
    constexpr double eps = 1e-9;
    QVector<Key> out;
    for (const Key &k : before) {
        if (k.time < from - eps || k.time > to + eps)
            out.append(k);
    }
    out += added;
    std::stable_sort(out.begin(), out.end(), [](const Key &a, const Key &b) { return a.time < b.time; });
    return out;
}

// The blinks of `before` that do not touch [from, to], plus `added`, in time order.
QVector<BlinkEvent> splicedBlinks(
    const QVector<BlinkEvent> &before, const QVector<BlinkEvent> &added, double from, double to)
{
    QVector<BlinkEvent> out;
    for (const BlinkEvent &b : before) {
        if (b.time + b.duration < from || b.time > to)
            out.append(b);
    }
    out += added;
    std::stable_sort(out.begin(), out.end(), [](const BlinkEvent &a, const BlinkEvent &b) { return a.time < b.time; });
    return out;
}

// Mouth keys `added` in place of those of `timeline` in [from, to]; a shut key starts the span
// when a key before it would otherwise sound on into it.
void spliceMouth(Timeline *timeline, QVector<MouthKey> added, double from, double to)
{
    const bool keyBefore = std::any_of(timeline->mouthKeys().cbegin(), timeline->mouthKeys().cend(),
        [from](const MouthKey &k) { return k.time < from - 1e-9; });
    if (keyBefore && (added.isEmpty() || added.first().time > from + 1e-9))
        added.prepend({from, MouthShape::M, 1.0, 0.0});
    timeline->setMouthKeys(spliced(timeline->mouthKeys(), added, from, to));
}

} // namespace

void addTrackToTimeline(
    const QVector<TrackedFrame> &frames, double fps, Timeline *timeline, const RetargetOptions &options, double offset)
{
    if (frames.isEmpty())
        return;
    QVector<const char *> ids = {"8.9", "8.2", "8.4", "8.3", "4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"};
    bool snapped = options.mouthKeysFromShapes;
    for (const TrackedFrame &f : frames)
        snapped = snapped && (f.lost || f.mouthShape);
    if (snapped)
        ids.remove(0, 4);

    const double period = fps > 0 ? 1.0 / fps : 0.04;
    const double from = frames.first().time + offset;
    const double to = frames.last().time + offset + period;
    QVector<PoseKey> pose;
    QVector<GazeKey> gaze;
    QVector<HeadKey> head;
    QVector<MouthKey> mouth;
    QVector<double> times, open;
    for (const TrackedFrame &f : frames) {
        if (f.lost)
            continue;
        const double t = f.time + offset;
        PoseKey key;
        key.time = t;
        for (const char *id : std::as_const(ids))
            key.offsetsEs0.insert(QString::fromLatin1(id), f.motion.displacementEs0[pt::idx(id)]);
        pose.append(key);
        gaze.append({t, f.motion.gazeEs0});
        head.append({t, f.motion.rotationDeg, f.motion.translationEs0, f.motion.scale});
        if (snapped && f.mouthShape && (mouth.isEmpty() || mouth.last().shape != *f.mouthShape))
            mouth.append({t, *f.mouthShape, 1.0, std::nullopt});
        times.append(t);
        open.append((f.motion.leftEyeOpen + f.motion.rightEyeOpen) / 2);
    }
    if (options.pose)
        timeline->setPoseKeys(spliced(timeline->poseKeys(), pose, from, to));
    if (options.gaze)
        timeline->setGazeKeys(spliced(timeline->gazeKeys(), gaze, from, to));
    if (options.head)
        timeline->setHeadKeys(spliced(timeline->headKeys(), head, from, to));
    if (options.blinks)
        timeline->setBlinks(splicedBlinks(timeline->blinks(), detectBlinks(times, open, fps), from, to));
    // Each shape sounds until the next one (the last until the last frame's end).
    for (qsizetype k = 0; k < mouth.size(); ++k) {
        const double end = k + 1 < mouth.size() ? mouth[k + 1].time : times.last() + period;
        mouth[k].duration = std::max(0.0, end - mouth[k].time);
    }
    if (snapped && options.pose) {
        // Tracked shapes follow each other at the frame rate: no minimum hold or anticipation
        // beyond a frame, and the mouth shuts only in real pauses.
        MouthSmoothing smoothing = timeline->smoothing();
        smoothing.minHold = std::min(smoothing.minHold, period);
        smoothing.coarticulation = std::min(smoothing.coarticulation, period);
        timeline->setSmoothing(smoothing);
        spliceMouth(timeline, mouth, from, to);
    } else if (options.pose) {
        // The tracked mouth is in the pose keys: mouth keys in the span would add a second mouth.
        spliceMouth(timeline, {}, from, to);
    }
}

namespace {

// The take as live mode showed it with the sound's mouth while the face was lost: lost frames
// hold the last tracked pose (the neutral before any) with the mouth controls at rest, and the
// sound's keys (times from the take's start) cover only those stretches.
std::pair<QVector<TrackedFrame>, QVector<MouthKey>> soundWhileLostTake(
    QVector<TrackedFrame> frames, const QVector<MouthKey> &sound, double duration)
{
    QVector<MouthKey> mouth;
    FaceMotion held;
    double lostFrom = -1;
    auto endSpan = [&](double to) {
        if (lostFrom < 0)
            return;
        // The shape sounding when the face was lost, from then on, and the sound's keys after.
        std::optional<MouthKey> sounding;
        QVector<MouthKey> span;
        for (const MouthKey &k : sound) {
            if (k.time <= lostFrom + 1e-9)
                sounding = k;
            else if (k.time < to - 1e-9)
                span.append(k);
        }
        if (sounding) {
            sounding->time = lostFrom;
            sounding->duration.reset();
            span.prepend(*sounding);
        }
        mouth += span;
        if (to < duration - 1e-9)
            mouth.append({to, MouthShape::M, 1.0, 0.0});
        lostFrom = -1;
    };
    for (TrackedFrame &f : frames) {
        if (!f.lost) {
            endSpan(f.time);
            held = f.motion;
            continue;
        }
        if (lostFrom < 0)
            lostFrom = f.time;
        f.motion = held;
        for (const char *id : kMouthControlIds)
            f.motion.displacementEs0[pt::idx(id)] = QPointF();
        f.lost = false;
    }
    endSpan(duration);
    return {frames, mouth};
}

} // namespace

void addTakeToTimeline(const QVector<TrackedFrame> &recorded, double fps, double duration,
    const QVector<MouthKey> &recordedSound, Timeline *timeline, double at, bool soundWhileLost)
{
    QVector<TrackedFrame> frames = recorded;
    QVector<MouthKey> soundMouth = recordedSound;
    if (soundWhileLost)
        std::tie(frames, soundMouth) = soundWhileLostTake(recorded, recordedSound, duration);
    const double end = at + std::max(0.0, duration);
    Timeline take;
    RetargetOptions options;
    options.mouthKeysFromShapes = false;
    addTrackToTimeline(frames, fps, &take, options, at);

    QVector<PoseKey> pose = take.poseKeys();
    if (!soundMouth.isEmpty() && !soundWhileLost) {
        for (PoseKey &k : pose) {
            for (const char *id : kMouthControlIds)
                k.offsetsEs0.remove(QString::fromLatin1(id));
        }
    }
    if (!recorded.isEmpty()) {
        timeline->setPoseKeys(spliced(timeline->poseKeys(), pose, at, end));
        timeline->setGazeKeys(spliced(timeline->gazeKeys(), take.gazeKeys(), at, end));
        timeline->setHeadKeys(spliced(timeline->headKeys(), take.headKeys(), at, end));
        timeline->setBlinks(splicedBlinks(timeline->blinks(), take.blinks(), at, end));
    }

    QVector<MouthKey> mouth;
    for (MouthKey k : soundMouth) {
        k.time += at;
        mouth.append(k);
    }
    spliceMouth(timeline, mouth, at, end);
}

} // namespace toonface
