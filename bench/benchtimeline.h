#pragma once

#include "anim/timeline.h"
#include "face/emotion.h"
#include "face/mouthshape.h"

#include <random>

namespace toonface::bench {

// Ten minutes of speech as lip sync would give it: syllables of 0.15-0.35 s holding one to
// four shapes at the thesis' fractions (ch. 5.3), a pause every dozen syllables, with emotions,
// blinks, gaze and head motion over the whole length.
inline Timeline tenMinuteTimeline()
{
    constexpr double length = 600.0;
    static const double fractions[4][4] = {{0}, {0, 0.8095}, {0, 0.4337, 0.8312}, {0, 0.245, 0.4565, 0.7153}};
    std::mt19937 rng(1);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    QVector<MouthCue> cues;
    double t = 0.5;
    int syllable = 0;
    while (t < length - 1.0) {
        const double duration = uniform(0.15, 0.35);
        const int shapes = 1 + int(rng() % 4);
        for (int k = 0; k < shapes; ++k) {
            const double start = t + fractions[shapes - 1][k] * duration;
            const double end = k + 1 < shapes ? t + fractions[shapes - 1][k + 1] * duration : t + duration;
            cues.append({start, end, kAllMouthShapes[1 + rng() % 8]});
        }
        t += duration;
        if (++syllable % 12 == 0)
            t += uniform(0.3, 0.9);
    }
    Timeline timeline;
    timeline.addMouthCues(cues);
    for (double s = 0; s < length; s += 30.0)
        timeline.addEmotionClip({s + 2.0, s + 20.0, kAllEmotions[1 + int(s / 30) % 4], 0.8, 0.5, 0.5});
    timeline.generateBlinks(7, length);
    for (double s = 0; s < length; s += 2.0)
        timeline.addGazeKey({s, {uniform(-0.05, 0.05), uniform(-0.02, 0.02)}});
    for (double s = 10; s < length; s += 40.0) {
        timeline.addShake(s, s + 1.0);
        timeline.addNod(s + 20.0, s + 21.0);
    }
    timeline.setAudioClips({AudioClip {QStringLiteral("speech.wav"), 0.0, length}});
    return timeline;
}

} // namespace toonface::bench
