#include "anim/timeline.h"

#include "anim/keycurve.h"
#include "anim/timelineevaluator.h"
#include "face/pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace toonface {

namespace {

template<class T, class Time>
void sortByTime(QVector<T> &items, Time time)
{
    std::stable_sort(items.begin(), items.end(), [&](const T &a, const T &b) { return time(a) < time(b); });
}

// Inserts after every item of the same time, so the newest of equal-time items wins.
template<class T, class Time>
void insertByTime(QVector<T> &items, const T &item, Time time)
{
    const auto at
        = std::upper_bound(items.begin(), items.end(), item, [&](const T &a, const T &b) { return time(a) < time(b); });
    items.insert(at, item);
}

auto mouthTime = [](const MouthKey &k) { return k.time; };
auto clipTime = [](const EmotionClip &c) { return c.start; };
auto blinkTime = [](const BlinkEvent &b) { return b.time; };
auto gazeTime = [](const GazeKey &k) { return k.time; };
auto headTime = [](const HeadKey &k) { return k.time; };
auto poseTime = [](const PoseKey &k) { return k.time; };
auto audioTime = [](const AudioClip &c) { return c.start(); };

HeadKey lerpHead(const HeadKey &a, const HeadKey &b, double s)
{
    HeadKey h;
    h.rotationDeg = a.rotationDeg + (b.rotationDeg - a.rotationDeg) * s;
    h.translationEs0 = a.translationEs0 + (b.translationEs0 - a.translationEs0) * s;
    h.scale = a.scale + (b.scale - a.scale) * s;
    return h;
}

// Uniform doubles and normal deviates from mt19937's raw output, whose sequence the C++
// standard fixes (the library's distributions are implementation-defined), so a seed gives the
// same blinks everywhere.
class PortableRandom
{
public:
    explicit PortableRandom(quint32 seed)
        : m_engine(seed)
    { }

    // In [0, 1), 53 random bits.
    double uniform()
    {
        const double a = double(m_engine() >> 5);
        const double b = double(m_engine() >> 6);
        return (a * 67108864.0 + b) / 9007199254740992.0;
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    double normal(double mean, double sigma)
    {
        const double u1 = 1.0 - uniform(); // (0, 1]
        const double u2 = uniform();
        return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

private:
    std::mt19937 m_engine;
};

} // namespace

double Timeline::duration() const
{
    double end = 0;
    for (const AudioClip &clip : m_audio)
        end = std::max(end, clip.end());
    for (const MouthKey &k : m_mouth)
        end = std::max(end, k.time + std::max(0.0, k.duration.value_or(0.0)));
    for (const EmotionClip &c : m_emotion)
        end = std::max(end, c.end);
    for (const BlinkEvent &b : m_blinks)
        end = std::max(end, b.time + b.duration);
    if (!m_gaze.isEmpty())
        end = std::max(end, m_gaze.last().time);
    if (!m_head.isEmpty())
        end = std::max(end, m_head.last().time);
    if (!m_pose.isEmpty())
        end = std::max(end, m_pose.last().time);
    return end;
}

void Timeline::setAudioClips(QVector<AudioClip> clips)
{
    sortByTime(clips, audioTime);
    m_audio = std::move(clips);
}

int Timeline::addAudioClip(const AudioClip &clip)
{
    insertByTime(m_audio, clip, audioTime);
    const auto at = std::upper_bound(
        m_audio.begin(), m_audio.end(), clip.start(), [](double t, const AudioClip &c) { return t < c.start(); });
    return int(at - m_audio.begin()) - 1;
}

int Timeline::audioClipAt(double t) const
{
    for (qsizetype i = m_audio.size() - 1; i >= 0; --i)
        if (t >= m_audio[i].start() && t < m_audio[i].end())
            return int(i);
    return -1;
}

int Timeline::frameCount() const
{
    // The small tolerance keeps an exact 10 s at 25 fps at 250 frames despite rounding.
    return int(std::ceil(duration() * m_frameRate - 1e-6));
}

void Timeline::setMouthKeys(QVector<MouthKey> keys)
{
    sortByTime(keys, mouthTime);
    m_mouth = std::move(keys);
}

void Timeline::addMouthKey(const MouthKey &key)
{
    insertByTime(m_mouth, key, mouthTime);
}

void Timeline::addMouthCues(const QVector<MouthCue> &cues)
{
    if (cues.isEmpty())
        return;
    QVector<MouthCue> sorted = cues;
    std::stable_sort(
        sorted.begin(), sorted.end(), [](const MouthCue &a, const MouthCue &b) { return a.start < b.start; });
    const double first = sorted.first().start;
    double last = first;
    for (const MouthCue &c : sorted)
        last = std::max(last, c.end);
    m_mouth.removeIf([&](const MouthKey &k) { return k.time >= first && k.time <= last; });
    for (const MouthCue &c : sorted)
        addMouthKey({c.start, c.shape, 1.0, std::max(0.0, c.end - c.start)});
}

QVector<MouthCue> Timeline::mouthCues() const
{
    QVector<MouthCue> cues;
    cues.reserve(m_mouth.size());
    for (qsizetype i = 0; i < m_mouth.size(); ++i) {
        const MouthKey &k = m_mouth[i];
        double end = k.time + m_smoothing.silenceHold;
        if (k.duration)
            end = k.time + *k.duration;
        else if (i + 1 < m_mouth.size())
            end = m_mouth[i + 1].time;
        cues.append({k.time, end, k.shape});
    }
    return cues;
}

void Timeline::setEmotionClips(QVector<EmotionClip> clips)
{
    sortByTime(clips, clipTime);
    m_emotion = std::move(clips);
}

void Timeline::addEmotionClip(const EmotionClip &clip)
{
    insertByTime(m_emotion, clip, clipTime);
}

void Timeline::setBlinks(QVector<BlinkEvent> blinks)
{
    sortByTime(blinks, blinkTime);
    m_blinks = std::move(blinks);
}

void Timeline::addBlink(const BlinkEvent &blink)
{
    insertByTime(m_blinks, blink, blinkTime);
}

void Timeline::generateBlinks(quint32 seed, double duration)
{
    m_blinks = randomBlinks(seed, duration);
}

QVector<BlinkEvent> Timeline::randomBlinks(quint32 seed, double duration)
{
    // Spontaneous blinking runs at 15-20 a minute in conversation, with a long-tailed
    // spread of intervals and the odd double blink; a blink takes 100-400 ms.
    PortableRandom rng(seed);
    auto blinkDuration = [&] { return std::clamp(rng.normal(0.17, 0.04), kBlinkDurationMin, kBlinkDurationMax); };
    auto gap = [&] { return std::clamp(3.0 * std::exp(rng.normal(0.0, 0.5)), kBlinkGapMin, kBlinkGapMax); };

    QVector<BlinkEvent> blinks;
    double t = rng.uniform(0.3, 2.5);
    while (true) {
        const double d = blinkDuration();
        if (t + d > duration)
            break;
        blinks.append({t, d});
        double end = t + d;
        if (rng.uniform() < 0.1) {
            const double t2 = end + rng.uniform(kDoubleBlinkGapMin, kDoubleBlinkGapMax);
            const double d2 = blinkDuration();
            if (t2 + d2 > duration)
                break;
            blinks.append({t2, d2});
            end = t2 + d2;
        }
        t = end + gap();
    }
    return blinks;
}

void Timeline::setGazeKeys(QVector<GazeKey> keys)
{
    sortByTime(keys, gazeTime);
    m_gaze = std::move(keys);
}

void Timeline::addGazeKey(const GazeKey &key)
{
    insertByTime(m_gaze, key, gazeTime);
}

void Timeline::setHeadKeys(QVector<HeadKey> keys)
{
    sortByTime(keys, headTime);
    m_head = std::move(keys);
}

void Timeline::addHeadKey(const HeadKey &key)
{
    insertByTime(m_head, key, headTime);
}

void Timeline::setPoseKeys(QVector<PoseKey> keys)
{
    sortByTime(keys, poseTime);
    m_pose = std::move(keys);
}

void Timeline::addPoseKey(const PoseKey &key)
{
    const auto at = std::lower_bound(m_pose.begin(), m_pose.end(), key.time - kPoseTimeTolerance,
        [](const PoseKey &k, double t) { return k.time < t; });
    if (at != m_pose.end() && std::abs(at->time - key.time) <= kPoseTimeTolerance)
        *at = key;
    else
        m_pose.insert(at, key);
}

HeadKey Timeline::headAt(double t) const
{
    if (m_head.isEmpty())
        return HeadKey {t, 0, {}, 1.0};
    QVector<double> times;
    times.reserve(m_head.size());
    for (const HeadKey &k : m_head)
        times.append(k.time);
    HeadKey h = easedAt(times, m_head, t, lerpHead);
    h.time = t;
    return h;
}

namespace {

// Replaces the keys in [start, end] by `extremes` alternating extremes added to the old head
// motion; extreme j is displaced by offset(j) scaled by a damping from 1 down to 0.7.
template<class Offset>
void insertOscillation(Timeline &timeline, double start, double end, double swingsPerSecond, Offset offset)
{
    if (!(start < end))
        return;
    const int extremes = std::max(2, int(std::lround((end - start) * swingsPerSecond)));
    QVector<HeadKey> added;
    added.append(timeline.headAt(start));
    for (int j = 0; j < extremes; ++j) {
        const double t = start + (end - start) * (2 * j + 1) / (2.0 * extremes);
        const double damping = 1.0 - 0.3 * j / (extremes - 1);
        HeadKey k = timeline.headAt(t);
        offset(k, j, damping);
        added.append(k);
    }
    added.append(timeline.headAt(end));
    QVector<HeadKey> keys = timeline.headKeys();
    keys.removeIf([&](const HeadKey &k) { return k.time >= start && k.time <= end; });
    keys.append(added);
    timeline.setHeadKeys(std::move(keys));
}

} // namespace

void Timeline::addShake(double start, double end, double amplitudeDeg, double swingsPerSecond)
{
    insertOscillation(*this, start, end, swingsPerSecond, [&](HeadKey &k, int j, double damping) {
        k.rotationDeg += (j % 2 == 0 ? 1.0 : -1.0) * amplitudeDeg * damping;
    });
}

void Timeline::addNod(double start, double end, double amplitudeEs0, double swingsPerSecond)
{
    insertOscillation(*this, start, end, swingsPerSecond, [&](HeadKey &k, int j, double damping) {
        k.translationEs0.ry() += (j % 2 == 0 ? 1.0 : -0.25) * amplitudeEs0 * damping;
    });
}

Pose Timeline::evaluate(double t, const FaceModel &face, const MouthShapeSet &shapes) const
{
    return TimelineEvaluator(*this, face, shapes).evaluate(t);
}

} // namespace toonface
