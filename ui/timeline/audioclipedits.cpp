#include "timeline/audioclipedits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toonface {

namespace {

bool owns(const AudioClip &clip, double t)
{
    return t >= clip.start() && t < clip.end();
}

} // namespace

QVector<int> audioClipsOverlapping(const Timeline &timeline, double start, double end, int except)
{
    QVector<int> out;
    const QVector<AudioClip> &clips = timeline.audioClips();
    for (qsizetype i = 0; i < clips.size(); ++i)
        if (int(i) != except && clips[i].end() > start && clips[i].start() < end)
            out.append(int(i));
    return out;
}

double freeAudioTime(const Timeline &timeline, double start, double length)
{
    double t = std::max(0.0, start);
    // Each pass moves past a clip in the way; clips are sorted, so a few passes settle it.
    for (bool moved = true; moved;) {
        moved = false;
        for (const AudioClip &clip : timeline.audioClips()) {
            if (clip.end() > t && clip.start() < t + length) {
                t = clip.end();
                moved = true;
            }
        }
    }
    return t;
}

Animation moveAudioClips(const Animation &animation, const QVector<int> &indices, double dt, double *applied)
{
    const QVector<AudioClip> &clips = animation.timeline.audioClips();
    QVector<bool> moved(clips.size(), false);
    for (int i : indices)
        if (i >= 0 && i < clips.size())
            moved[i] = true;
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (qsizetype i = 0; i < clips.size(); ++i) {
        if (!moved[i])
            continue;
        lo = std::max(lo, -clips[i].start());
        hi = std::min(hi, Timeline::kMaxSeconds - clips[i].end());
        for (qsizetype j = 0; j < clips.size(); ++j) {
            if (moved[j] || (clips[j].end() > clips[i].start() && clips[j].start() < clips[i].end()))
                continue; // moved along, or overlapping already
            if (clips[j].start() >= clips[i].end())
                hi = std::min(hi, clips[j].start() - clips[i].end());
            else
                lo = std::max(lo, clips[j].end() - clips[i].start());
        }
    }
    const double d = (lo > hi || !std::isfinite(dt)) ? 0.0 : std::clamp(dt, lo, hi);
    if (applied)
        *applied = d;
    if (d == 0)
        return animation;

    Animation after = animation;
    const auto ownedByMoved = [&](double t) {
        for (qsizetype i = 0; i < clips.size(); ++i)
            if (moved[i] && owns(clips[i], t))
                return true;
        return false;
    };
    QVector<MouthKey> keys = animation.timeline.mouthKeys();
    for (MouthKey &k : keys)
        if (ownedByMoved(k.time))
            k.time += d;
    for (LipsyncSyllable &s : after.syllables) {
        if (!ownedByMoved(s.start))
            continue;
        s.start += d;
        s.end += d;
        for (ShapeKey &key : s.shapes)
            key.start += d;
    }
    std::stable_sort(after.syllables.begin(), after.syllables.end(),
        [](const LipsyncSyllable &a, const LipsyncSyllable &b) { return a.start < b.start; });
    QVector<AudioClip> track = clips;
    for (qsizetype i = 0; i < track.size(); ++i)
        if (moved[i])
            track[i].offset += d;
    after.timeline.setMouthKeys(keys);
    after.timeline.setAudioClips(track);
    return after;
}

Animation trimAudioClip(const Animation &animation, int index, SpanEdge edge, double to, double minSpan)
{
    const QVector<AudioClip> &clips = animation.timeline.audioClips();
    if (index < 0 || index >= clips.size() || !std::isfinite(to))
        return animation;
    AudioClip clip = clips[index];
    // The file's end, when its length is known; else the clip's end cannot grow.
    const double fileEnd = clip.duration > 0 ? clip.offset + clip.duration : clip.end();
    if (edge == SpanEdge::Start) {
        double lo = std::max({clip.offset, 0.0});
        for (qsizetype j = 0; j < clips.size(); ++j)
            if (j != index && clips[j].end() <= clip.start())
                lo = std::max(lo, clips[j].end());
        const double t = std::clamp(to, lo, std::max(lo, clip.end() - minSpan));
        clip.trimIn = t - clip.offset;
    } else {
        double hi = std::min(fileEnd, Timeline::kMaxSeconds);
        for (qsizetype j = 0; j < clips.size(); ++j)
            if (j != index && clips[j].start() >= clip.end())
                hi = std::min(hi, clips[j].start());
        const double t = std::clamp(to, std::min(hi, clip.start() + minSpan), hi);
        if (clip.duration > 0)
            clip.trimOut = std::max(0.0, clip.offset + clip.duration - t);
    }
    Animation after = animation;
    QVector<AudioClip> track = clips;
    track[index] = clip;
    after.timeline.setAudioClips(track);
    return after;
}

Animation removeAudioClips(const Animation &animation, const QVector<int> &indices)
{
    const QVector<AudioClip> &clips = animation.timeline.audioClips();
    QVector<AudioClip> kept, removed;
    for (qsizetype i = 0; i < clips.size(); ++i)
        (indices.contains(int(i)) ? removed : kept).append(clips[i]);
    if (removed.isEmpty())
        return animation;
    const auto owned = [&](double t) {
        return std::any_of(removed.cbegin(), removed.cend(), [t](const AudioClip &c) { return owns(c, t); });
    };
    Animation after = animation;
    QVector<MouthKey> keys = animation.timeline.mouthKeys();
    keys.removeIf([&](const MouthKey &k) { return owned(k.time); });
    after.syllables.removeIf([&](const LipsyncSyllable &s) { return owned(s.start); });
    after.timeline.setMouthKeys(keys);
    after.timeline.setAudioClips(kept);
    return after;
}

std::optional<ClipPlace> placeAudioClip(
    const Timeline &timeline, const QString &path, double start, double length, ClipOverlap overlap)
{
    ClipPlace place;
    place.start = std::max(0.0, start);
    const QVector<AudioClip> &clips = timeline.audioClips();
    for (qsizetype i = 0; i < clips.size(); ++i)
        if (clips[i].path == path && std::abs(clips[i].offset - place.start) < 1e-6)
            place.replaced.append(int(i));
    Timeline others = timeline;
    QVector<AudioClip> rest;
    for (qsizetype i = 0; i < clips.size(); ++i)
        if (!place.replaced.contains(int(i)))
            rest.append(clips[i]);
    others.setAudioClips(rest);
    for (int j : audioClipsOverlapping(timeline, place.start, place.start + length))
        if (!place.replaced.contains(j))
            place.overlapped.append(j);
    if (!place.overlapped.isEmpty()) {
        if (overlap == ClipOverlap::Replace) {
            place.replaced += place.overlapped;
            std::sort(place.replaced.begin(), place.replaced.end());
        } else if (overlap == ClipOverlap::PlaceAfter) {
            place.start = freeAudioTime(others, place.start, length);
        }
    }
    if (place.start + length > Timeline::kMaxSeconds)
        return std::nullopt;
    return place;
}

} // namespace toonface
