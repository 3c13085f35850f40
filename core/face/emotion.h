#pragma once

#include <QPointF>
#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace toonface {

class FaceModel;
struct Pose;

// The five emotion presets of thesis Fig. 5.12.
enum class Emotion { Neutral, Smile, Sad, Angry, Surprise };

inline constexpr std::array<Emotion, 5> kAllEmotions
    = {Emotion::Neutral, Emotion::Smile, Emotion::Sad, Emotion::Angry, Emotion::Surprise};

QString emotionName(Emotion emotion); // "neutral", "smile", "sad", "angry", "surprise"
std::optional<Emotion> emotionFromName(const QString &name);

// An emotion at full intensity: displacements of control points in units of ES0, given for
// the image-left side and the centre line; the image-right side mirrors them.
struct EmotionPreset
{
    struct Move
    {
        const char *id;
        QPointF offsetEs0;
    };
    std::vector<Move> moves;
    double eyeOpenScale = 1.0; // multiplies the lid opening (1 = unchanged)
};

const EmotionPreset &emotionPreset(Emotion emotion);

// How much of a preset's full displacement an intensity draws: 1 - (1 - i)^2 over 0..1, so half
// intensity draws three quarters of it and a low-key emotion still reads (a cartoon keeps an
// expression's shape and eases off late); 0 and 1 are unchanged, and past 1 it grows as i does.
// Odd: a negative intensity draws the opposite.
double emotionWeight(double intensity);

// The pose of `emotion` at `intensity` (0..1) on `face`: to be added to a speech pose. It starts
// from the face at rest (restingFacePose: the photo's own frown, raised brows or smile taken out;
// neutral is that alone) and keeps raised brows under the hairline (keepBrowsUnderHairline).
// Linear in emotionWeight(intensity), the full pose times that weight, wherever the hairline
// does not stop a brow.
Pose emotionPose(const FaceModel &face, Emotion emotion, double intensity);

// The still drawing of `emotion` at `intensity`: what the animation draws for a clip of it
// where nothing is said (the mouth at rest, its lips shut: restingMouth, plus emotionPose). A
// cartoon, a preview or a thumbnail of an emotion is this pose.
Pose stillEmotionPose(const FaceModel &face, Emotion emotion, double intensity);

// The image-right counterpart of an image-left point ID ("4.6" -> "4.5"), or the ID itself
// for points on the centre line.
const char *mirrorPointId(const char *id);

} // namespace toonface
