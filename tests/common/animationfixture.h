#pragma once

// A face and a ten-second timeline that uses every track, shared by the export tests.

#include "anim/timeline.h"
#include "face/averageface.h"
#include "face/facemodel.h"
#include "face/mouthshape.h"

#include <QFile>
#include <QString>
#include <QtEndian>

#include <cmath>
#include <numbers>
#include <random>

namespace toonface::test {

inline FaceModel animationFace()
{
    return averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
}

// Three phrases of speech with pauses between them (every shape, f with its lips pressed
// together, n keeping the corners of the shape before); a smile fading in and out over
// speech, a surprise that starts with no fade (a jump), a brief anger; random blinks; gaze
// moves; a head shake and a nod. The audio clip, when given, lasts the whole 10 s.
inline Timeline animationTimeline(const QString &audioPath = {})
{
    Timeline t;
    t.setFrameRate(25);
    const MouthShape shapes[] = {MouthShape::H, MouthShape::A, MouthShape::U, MouthShape::M, MouthShape::I,
        MouthShape::E, MouthShape::F, MouthShape::O, MouthShape::N, MouthShape::A, MouthShape::E, MouthShape::I};
    const double lengths[] = {0.12, 0.2, 0.08, 0.15, 0.25, 0.1, 0.18, 0.07, 0.22, 0.3, 0.05, 0.14, 0.09};
    QVector<MouthCue> cues;
    int k = 0;
    for (const auto &[start, end] : {std::pair {0.4, 2.3}, std::pair {3.2, 6.0}, std::pair {7.2, 9.1}}) {
        for (double s = start; s < end; ++k) {
            const double length = lengths[k % std::size(lengths)];
            cues.append({s, s + length, shapes[k % std::size(shapes)]});
            s += length;
        }
    }
    t.addMouthCues(cues);
    t.addEmotionClip({1.0, 4.0, Emotion::Smile, 0.8, 0.5, 0.5});
    t.addEmotionClip({5.0, 6.5, Emotion::Surprise, 0.9, 0.0, 0.3});
    t.addEmotionClip({8.0, 9.5, Emotion::Angry, 0.6, 0.2, 0.2});
    t.generateBlinks(11, 10.0);
    t.addGazeKey({0.0, {0, 0}});
    t.addGazeKey({2.5, {0.06, 0.02}});
    t.addGazeKey({4.0, {-0.05, -0.03}});
    t.addGazeKey({8.0, {0, 0}});
    t.addShake(2.0, 3.0);
    t.addNod(6.8, 7.8);
    t.setAudioClips({AudioClip {audioPath, 0.0, 10.0}});
    return t;
}

// A random and busy timeline of `length` seconds, the same for the same seed: cues of
// 0.05-0.3 s of any shape with short pauses, overlapping emotion clips of any fades (none
// included) every 4-12 s, blinks, gaze moves every 0.5-5 s, shakes and nods.
inline Timeline busyTimeline(quint32 seed, double length)
{
    std::mt19937 rng(seed);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    QVector<MouthCue> cues;
    double t = 0.3;
    for (int n = 1; t < length - 1; ++n) {
        const double d = uniform(0.05, 0.3);
        cues.append({t, t + d, kAllMouthShapes[rng() % kAllMouthShapes.size()]});
        t += d + (n % 15 == 0 ? uniform(0.2, 1.0) : 0.0);
    }
    Timeline timeline;
    timeline.addMouthCues(cues);
    for (double s = 1; s < length - 5; s += uniform(4, 12)) {
        const double end = s + uniform(0.3, 6);
        timeline.addEmotionClip(
            {s, end, kAllEmotions[1 + rng() % 4], uniform(0.3, 1), uniform(0, 0.8), uniform(0, 0.8)});
    }
    timeline.generateBlinks(rng(), length);
    for (double s = 0; s < length; s += uniform(0.5, 5))
        timeline.addGazeKey({s, {uniform(-0.1, 0.1), uniform(-0.05, 0.05)}});
    for (double s = 2; s < length - 3; s += uniform(5, 20)) {
        if (rng() % 2)
            timeline.addShake(s, s + uniform(0.5, 2));
        else
            timeline.addNod(s, s + uniform(0.5, 2));
    }
    return timeline;
}

// A time at which the mouth holds a wide-open `a` (the tenth cue, held from its start until
// 0.1 s before the next), and one in the pause after the second phrase when it is shut; the head
// is at rest at both.
inline double openVowelTime()
{
    return 0.4 + 0.12 + 0.2 + 0.08 + 0.15 + 0.25 + 0.1 + 0.18 + 0.07 + 0.22 + 0.06;
}
inline double silenceTime()
{
    return 6.6;
}

// A mono 16-bit PCM WAV of a quiet 220 Hz tone.
inline bool writeToneWav(const QString &path, double seconds, int rate = 8000)
{
    const int samples = int(seconds * rate);
    QByteArray data(samples * 2, Qt::Uninitialized);
    for (int i = 0; i < samples; ++i)
        qToLittleEndian<qint16>(qint16(3000 * std::sin(2 * std::numbers::pi * 220.0 * i / rate)), data.data() + 2 * i);
    QByteArray header;
    auto u32 = [&](quint32 v) {
        char b[4];
        qToLittleEndian(v, b);
        header.append(b, 4);
    };
    auto u16 = [&](quint16 v) {
        char b[2];
        qToLittleEndian(v, b);
        header.append(b, 2);
    };
    header += "RIFF";
    u32(36 + quint32(data.size()));
    header += "WAVEfmt ";
    u32(16);
    u16(1);
    u16(1);
    u32(quint32(rate));
    u32(quint32(rate * 2));
    u16(2);
    u16(16);
    header += "data";
    u32(quint32(data.size()));
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(header + data) == header.size() + data.size();
}

} // namespace toonface::test
