#include "dialogs/animationedits.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace toonface {

std::optional<Animation> withSpeech(
    const Animation &before, const LipsyncResult &result, const SpeechPlacement &placement, ClipPlace *placed)
{
    const std::optional<ClipPlace> place
        = placeAudioClip(before.timeline, placement.audioPath, placement.offset, result.duration, placement.overlap);
    if (!place)
        return std::nullopt;
    if (placed)
        *placed = *place;
    Animation after = removeAudioClips(before, place->replaced);
    const double from = place->start;
    const double to = from + result.duration;

    QVector<MouthCue> cues = result.mouthCues;
    for (MouthCue &cue : cues) {
        cue.start += from;
        cue.end += from;
    }
    // The cues cover [0, duration]; an empty result still clears its range.
    if (cues.isEmpty() && result.duration > 0)
        cues.append({from, to, MouthShape::M});
    after.timeline.addMouthCues(cues);

    QVector<LipsyncSyllable> syllables;
    for (const LipsyncSyllable &s : after.syllables) {
        const bool inside = s.end > from && s.start < to;
        if (!inside)
            syllables.append(s);
    }
    for (LipsyncSyllable s : result.syllables) {
        s.start += from;
        s.end += from;
        for (ShapeKey &key : s.shapes)
            key.start += from;
        syllables.append(s);
    }
    std::stable_sort(syllables.begin(), syllables.end(),
        [](const LipsyncSyllable &a, const LipsyncSyllable &b) { return a.start < b.start; });
    after.syllables = syllables;

    AudioClip clip;
    clip.path = placement.audioPath;
    clip.offset = from;
    clip.duration = result.duration;
    clip.script = placement.script;
    clip.language = languageCode(result.language);
    after.timeline.addAudioClip(clip);
    return after;
}

QString placementNote(const Timeline &before, const ClipPlace &placed, double wanted)
{
    const QVector<AudioClip> &clips = before.audioClips();
    QStringList names;
    for (int i : placed.overlapped)
        if (i >= 0 && i < clips.size())
            names << QFileInfo(clips[i].path).fileName();
    if (names.isEmpty())
        return {};
    const QString list = names.join(QStringLiteral(", "));
    if (std::abs(placed.start - std::max(0.0, wanted)) > 1e-9)
        return QCoreApplication::translate(
            "toonface::AnimationEdits", "placed after %1, at %2 s (it would have played over it)")
            .arg(list)
            .arg(placed.start, 0, 'f', 2);
    bool replaced = true;
    for (int i : placed.overlapped)
        replaced = replaced && placed.replaced.contains(i);
    return replaced ? QCoreApplication::translate("toonface::AnimationEdits", "replaced %1").arg(list)
                    : QCoreApplication::translate("toonface::AnimationEdits", "plays together with %1").arg(list);
}

Animation withBlinks(const Animation &before, quint32 seed, double start, double end)
{
    Animation after = before;
    QVector<BlinkEvent> blinks;
    for (const BlinkEvent &b : before.timeline.blinks())
        if (b.time < start || b.time >= end)
            blinks.append(b);
    for (BlinkEvent b : Timeline::randomBlinks(seed, end - start)) {
        b.time += start;
        if (b.time < end)
            blinks.append(b);
    }
    after.timeline.setBlinks(blinks);
    return after;
}

namespace {

// `clip` cut to [start, end], its fades no longer than the part kept.
EmotionClip cutTo(EmotionClip clip, double start, double end)
{
    clip.start = start;
    clip.end = end;
    const double length = end - start;
    clip.fadeIn = std::min(clip.fadeIn, length);
    clip.fadeOut = std::min(clip.fadeOut, length);
    return clip;
}

} // namespace

Animation withEmotion(const Animation &before, const EmotionClip &clip, bool replace)
{
    Animation after = before;
    QVector<EmotionClip> clips;
    for (const EmotionClip &c : before.timeline.emotionClips()) {
        if (!replace || c.end <= clip.start || c.start >= clip.end) {
            clips.append(c);
            continue;
        }
        if (c.start < clip.start)
            clips.append(cutTo(c, c.start, clip.start));
        if (c.end > clip.end)
            clips.append(cutTo(c, clip.end, c.end));
    }
    clips.append(clip);
    after.timeline.setEmotionClips(clips);
    return after;
}

} // namespace toonface
