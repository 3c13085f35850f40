#include "face/emotion.h"

#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/pose.h"

#include <cstring>

namespace toonface {

QString emotionName(Emotion emotion)
{
    static const char *const names[] = {"neutral", "smile", "sad", "angry", "surprise"};
    return QString::fromLatin1(names[int(emotion)]);
}

std::optional<Emotion> emotionFromName(const QString &name)
{
    for (Emotion e : kAllEmotions) {
        if (emotionName(e) == name)
            return e;
    }
    return std::nullopt;
}

const char *mirrorPointId(const char *id)
{
    static const char *const pairs[][2]
        = {{"4.6", "4.5"}, {"4.4a", "4.3a"}, {"4.4", "4.3"}, {"4.2", "4.1"}, {"3.12", "3.7"}, {"3.2", "3.1"},
            {"3.8", "3.11"}, {"3.4", "3.3"}, {"3.6", "3.5"}, {"8.4", "8.3"}, {"8.9", "8.10"}};
    for (const auto &p : pairs) {
        if (std::strcmp(p[0], id) == 0)
            return p[1];
        if (std::strcmp(p[1], id) == 0)
            return p[0];
    }
    return id;
}

const EmotionPreset &emotionPreset(Emotion emotion)
{
    // Offsets in ES0 (eye distance) units, y down; the image-left side and centre only.
    // 4.6 outer brow end, 4.4a, 4.4, 4.2 inner end; 3.2 upper lid, 3.4 lower lid;
    // 8.4 left mouth corner, 8.9 upper lip, 8.2 lower lip.
    static const std::array<EmotionPreset, 5> presets = {{
        {{}, 1.0},
        {{{"4.6", {0, -0.02}}, {"4.4a", {0, -0.04}}, {"4.4", {0, -0.04}}, {"4.2", {0, -0.02}}, {"3.4", {0, -0.03}},
             {"8.4", {-0.05, -0.08}}, {"8.9", {0, -0.01}}, {"8.2", {0, 0.03}}},
            0.9},
        {{{"4.6", {0, 0.05}}, {"4.4a", {0, 0.0}}, {"4.4", {0, -0.05}}, {"4.2", {0.01, -0.09}}, {"3.2", {0, 0.03}},
             {"8.4", {0.02, 0.08}}, {"8.2", {0, 0.01}}},
            0.85},
        {{{"4.6", {0, -0.02}}, {"4.4a", {0, 0.03}}, {"4.4", {0.01, 0.06}}, {"4.2", {0.04, 0.10}}, {"3.2", {0, 0.03}},
             {"3.4", {0, -0.02}}, {"8.4", {0.03, 0.04}}, {"8.9", {0, 0.01}}},
            0.9},
        {{{"4.6", {0, -0.12}}, {"4.4a", {0, -0.15}}, {"4.4", {0, -0.15}}, {"4.2", {0, -0.12}}, {"3.2", {0, -0.04}},
             {"3.4", {0, 0.02}}, {"8.4", {0.06, 0.02}}, {"8.9", {0, -0.02}}, {"8.2", {0, 0.18}}},
            1.15},
    }};
    return presets[int(emotion)];
}

Pose emotionPose(const FaceModel &face, Emotion emotion, double intensity)
{
    const double es0 = face.fapu().es0;
    const EmotionPreset &preset = emotionPreset(emotion);
    Pose pose;
    for (const auto &move : preset.moves) {
        const QPointF d = move.offsetEs0 * es0 * intensity;
        pose.offset[pt::idx(move.id)] += d;
        const char *mirror = mirrorPointId(move.id);
        // 8.9 and 8.2 lie on or follow the centre line; 8.10 follows 8.9 by rule.
        if (std::strcmp(mirror, move.id) != 0 && std::strcmp(move.id, "8.9") != 0)
            pose.offset[pt::idx(mirror)] += QPointF(-d.x(), d.y());
    }
    const double scale = 1.0 + (preset.eyeOpenScale - 1.0) * intensity;
    pose.leftEyeOpen = scale;
    pose.rightEyeOpen = scale;
    return pose;
}

} // namespace toonface
