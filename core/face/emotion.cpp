#include "face/emotion.h"

#include "face/averageface.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "face/restingface.h"

#include <algorithm>
#include <cstring>

namespace toonface {

namespace {

// The lids' moves are drawn for the average face's eyes; on a face they move by the same share
// of its own eyes' opening, so narrow eyes (a squint, a photo taken smiling) are lowered, not
// shut or turned inside out, and wide eyes move as visibly. Both eyes take their mean, so the
// sides stay mirror images.
double lidScale(const Fapu &f)
{
    static const double average = [] {
        const Fapu a = averageFace(QRectF(0, 0, 200, 240), QSize(400, 500)).fapu();
        return (a.leftEyeH + a.rightEyeH) / 2.0 / a.es0;
    }();
    return f.es0 > 0 ? (f.leftEyeH + f.rightEyeH) / 2.0 / f.es0 / average : 1.0;
}

bool isLid(const char *id)
{
    return std::strcmp(id, "3.2") == 0 || std::strcmp(id, "3.4") == 0;
}

} // namespace

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
    // Offsets in ES0 (eye distance) units, y down; the image-left side and centre only, so +x
    // is toward the face's middle for the brows and lids and -x is outward for the mouth corner.
    // 4.6 outer brow end, 4.4a, 4.4, 4.2 inner end; 3.2 upper lid, 3.4 lower lid;
    // 8.4 left mouth corner, 8.9 upper lip, 8.2 lower lip (and with it the jaw).
    //
    // Drawn as a cartoonist draws them, past the small MPEG-4 ranges of a real face, so that
    // each reads at a glance and still reads at half intensity (which draws 3/4 of each move:
    // emotionWeight); SvgFace
    // adds the drawn cues that follow these moves (creases, blush: render/svgexpression.h):
    // - smile: corners well up and back, the mouth open on the teeth, lower lids up (the cheeks
    //   push them: the eyes smile), brows lifted a little;
    // - sad: inner brow ends high and outer ends low (the brows slant down outward), heavy
    //   upper lids, corners well down under a lower lip pushed up (a pout's arch);
    // - angry: inner brow ends down and together and outer ends up (a V), upper lids lowered
    //   onto a glare, lower lids tensed, the lips pressed together into a thin, tight line (the
    //   upper lip down and the lower up, the corners drawn in and a little down) - not sad's
    //   downturned pout, so that the two never read alike;
    // - surprise: brows high and arched, eyes wide open round the whole iris, the jaw dropped
    //   under rounded lips (an O).
    static const std::array<EmotionPreset, 5> presets = {{
        {{}, 1.0},
        {{{"4.6", {0, -0.03}}, {"4.4a", {0, -0.05}}, {"4.4", {0, -0.05}}, {"4.2", {0, -0.03}}, {"3.2", {0, 0.02}},
             {"3.4", {0, -0.07}}, {"8.4", {-0.11, -0.18}}, {"8.9", {0, -0.03}}, {"8.2", {0, 0.17}}},
            0.85},
        {{{"4.6", {0, 0.1}}, {"4.4a", {0, -0.02}}, {"4.4", {0.015, -0.13}}, {"4.2", {0.03, -0.24}}, {"3.2", {0, 0.04}},
             {"8.4", {0.05, 0.24}}, {"8.9", {0, 0.02}}, {"8.2", {0, -0.07}}},
            0.75},
        {{{"4.6", {0, -0.08}}, {"4.4a", {0.01, 0.02}}, {"4.4", {0.03, 0.1}}, {"4.2", {0.07, 0.19}}, {"3.2", {0, 0.07}},
             {"3.4", {0, -0.05}}, {"8.4", {0.05, 0.05}}, {"8.9", {0, 0.03}}, {"8.2", {0, -0.04}}},
            0.8},
        {{{"4.6", {0, -0.19}}, {"4.4a", {0, -0.26}}, {"4.4", {0, -0.26}}, {"4.2", {0, -0.2}}, {"3.2", {0, -0.08}},
             {"3.4", {0, 0.04}}, {"8.4", {0.11, 0.04}}, {"8.9", {0, -0.05}}, {"8.2", {0, 0.42}}},
            1.6},
    }};
    return presets[int(emotion)];
}

double emotionWeight(double intensity)
{
    const double i = std::abs(intensity);
    const double w = i < 1.0 ? 1.0 - (1.0 - i) * (1.0 - i) : i;
    return intensity < 0 ? -w : w;
}

Pose emotionPose(const FaceModel &face, Emotion emotion, double intensity)
{
    const double weight = emotionWeight(intensity);
    const Fapu fapu = face.fapu();
    const double es0 = fapu.es0;
    const double lids = lidScale(fapu);
    const EmotionPreset &preset = emotionPreset(emotion);
    Pose pose;
    for (const auto &move : preset.moves) {
        const QPointF d = move.offsetEs0 * es0 * weight * (isLid(move.id) ? lids : 1.0);
        pose.offset[pt::idx(move.id)] += d;
        const char *mirror = mirrorPointId(move.id);
        // 8.9 and 8.2 lie on or follow the centre line; 8.10 follows 8.9 by rule.
        if (std::strcmp(mirror, move.id) != 0 && std::strcmp(move.id, "8.9") != 0)
            pose.offset[pt::idx(mirror)] += QPointF(-d.x(), d.y());
    }
    // Every preset starts from the face at rest (restingface.h): the photo's own frown or raised
    // brows would otherwise show through every emotion (a frowning photo reads angry at neutral,
    // and its sad reads cross), and a photo taken smiling would smile through every emotion. Its
    // brows come to where people's rest, its mouth corners onto the line where its lips meet (lips
    // photographed apart are shut by the rest under speech, restingMouth, which stillEmotionPose
    // adds where nothing is said). The smile keeps the photo's own mouth and adds its own.
    Pose rest = restingFacePose(face);
    if (emotion == Emotion::Smile)
        for (const char *id : {"8.4", "8.3"})
            rest.offset[pt::idx(id)] = {};
    for (int i = 0; i < kPointCount; ++i)
        pose.offset[i] += rest.offset[i] * weight;
    // Brows raised by a preset stay under the hairline, where a hat's brim is drawn.
    keepBrowsUnderHairline(face, &pose);
    const double scale = 1.0 + (preset.eyeOpenScale - 1.0) * weight;
    pose.leftEyeOpen = scale;
    pose.rightEyeOpen = scale;
    return pose;
}

Pose stillEmotionPose(const FaceModel &face, Emotion emotion, double intensity)
{
    Pose pose = emotionPose(face, emotion, intensity);
    const std::array<QPointF, 4> rest = restingMouth(face);
    for (int k = 0; k < 4; ++k)
        pose.offset[pt::idx(kMouthControlIds[k])] += rest[k];
    return pose;
}

} // namespace toonface
