#pragma once

#include "document/animation.h"
#include "document/document.h"
#include "speech/lipsync.h"
#include "speech/syllableshapes.h"
#include "uifixture.h"

// A talking animation made in code for the timeline tests: five Mandarin syllables (a phrase,
// a pause, two more), the mouth keys lip sync makes of them, a smile, blinks and head keys.
namespace toonface::fixture {

inline LipsyncSyllable syllable(const QString &text, const QString &pinyin, int tone, double start, double end)
{
    return {text, pinyin, tone, start, end, 0.9, syllableShapeKeys(syllableShapes(pinyin), start, end - start)};
}

inline constexpr double kTalkDuration = 3.0;

inline Animation talkingAnimation()
{
    Animation a;
    a.syllables = {
        syllable(QStringLiteral("你"), QStringLiteral("ni"), 3, 0.2, 0.5),
        syllable(QStringLiteral("好"), QStringLiteral("hao"), 3, 0.5, 0.8),
        syllable(QStringLiteral("吗"), QStringLiteral("ma"), 5, 0.8, 1.1),
        syllable(QStringLiteral("明"), QStringLiteral("ming"), 2, 1.6, 2.0),
        syllable(QStringLiteral("天"), QStringLiteral("tian"), 1, 2.0, 2.4),
    };
    a.timeline.setFrameRate(25);
    a.timeline.addMouthCues(mouthCues(a.syllables, kTalkDuration));
    a.timeline.addEmotionClip({0.3, 1.5, Emotion::Smile, 0.8, 0.2, 0.3});
    a.timeline.addBlink({0.9, 0.18});
    a.timeline.addBlink({2.6, 0.2});
    a.timeline.addHeadKey({0.0, 0, {}, 1});
    a.timeline.addHeadKey({1.0, 4, {}, 1});
    a.timeline.addHeadKey({2.0, -3, {}, 1});
    a.timeline.addGazeKey({1.2, QPointF(0.1, 0)});
    a.timeline.addPoseKey({0.6, {{QStringLiteral("8.4"), QPointF(0.02, -0.03)}}});
    a.timeline.addPoseKey({1.4, {{QStringLiteral("8.4"), QPointF(0, 0)}}});
    return a;
}

// A document holding the fixture face and photo with talkingAnimation() on its timeline,
// unmodified.
inline void fillTalking(Document &document)
{
    Project project;
    project.face = face();
    project.style = Style::preset(QStringLiteral("normal"));
    const Animation a = talkingAnimation();
    project.timeline = a.timeline;
    project.syllables = a.syllables;
    document.reset(project, photo(), {}, true);
}

// The index of the mouth key at `time` (within a microsecond), or -1.
inline int mouthKeyAt(const Animation &a, double time)
{
    const QVector<MouthKey> &keys = a.timeline.mouthKeys();
    for (int i = 0; i < keys.size(); ++i)
        if (std::abs(keys[i].time - time) < 1e-6)
            return i;
    return -1;
}

// The shape the mouth track holds at `time` (lip sync merges equal neighbours, so a shape may
// start inside a cue of the same shape rather than at a key of its own).
inline std::optional<MouthShape> mouthShapeAt(const Animation &a, double time)
{
    const QVector<MouthCue> cues = a.timeline.mouthCues();
    for (const MouthCue &c : cues)
        if (c.start <= time + 1e-9 && time < c.end - 1e-9)
            return c.shape;
    return std::nullopt;
}

} // namespace toonface::fixture
