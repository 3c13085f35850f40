#pragma once

#include "face/emotion.h"
#include "face/mouthshape.h"

#include <QFlags>
#include <QJsonObject>
#include <QMap>
#include <QPointF>
#include <QString>
#include <QVector>

#include <algorithm>
#include <optional>

namespace toonface {

class FaceModel;
struct Pose;

// Times are seconds from the start of the animation. Every track keeps its entries sorted by
// time (stable: entries at equal times keep their insertion order, and the later one wins).

// A mouth key frame: from `time` the mouth takes `shape`. `weight` scales the shape's
// displacement from the shut mouth (1 = the full preset). `duration`, when known (a lip-sync
// cue gives it), is how long the shape is sounded; it tells the end of speech from a pause.
struct MouthKey
{
    double time = 0;
    MouthShape shape = MouthShape::M;
    double weight = 1.0;
    std::optional<double> duration;

    bool operator==(const MouthKey &) const = default;
};

// One shape of a lip-sync result: sounded from start to end.
struct MouthCue
{
    double start = 0;
    double end = 0;
    MouthShape shape = MouthShape::M;

    bool operator==(const MouthCue &) const = default;
};

// An emotion held from start to end at `intensity` (0..1), fading in over the first `fadeIn`
// seconds and out over the last `fadeOut` (both shrink in proportion when the clip is shorter
// than their sum).
struct EmotionClip
{
    double start = 0;
    double end = 0;
    Emotion emotion = Emotion::Neutral;
    double intensity = 1.0;
    double fadeIn = 0.3;
    double fadeOut = 0.3;

    bool operator==(const EmotionClip &) const = default;
};

// A blink starting at `time`: the lids close in its first quarter, stay shut briefly and
// open over the last 60 %, so closing is faster than opening (see kBlinkPhases).
struct BlinkEvent
{
    double time = 0;
    double duration = 0.18;

    bool operator==(const BlinkEvent &) const = default;
};

// Fractions of a blink's duration: closing, shut, opening.
struct BlinkPhases
{
    double closing;
    double shut;
    double opening;
};
inline constexpr BlinkPhases kBlinkPhases = {0.25, 0.15, 0.60};

// Where both eyeballs look: an offset of the eyeball centres 3.6 and 3.5 in ES0 units
// (the posed face keeps each eyeball between its eye corners).
struct GazeKey
{
    double time = 0;
    QPointF offsetEs0;

    bool operator==(const GazeKey &) const = default;
};

// Rigid head motion at a key frame; translation in ES0 units (so a preset fits every photo).
struct HeadKey
{
    double time = 0;
    double rotationDeg = 0;
    QPointF translationEs0;
    double scale = 1.0;

    bool operator==(const HeadKey &) const = default;
};

// A key frame of control-point displacements (thesis 2.2.4: "the positions of the control points
// are defined in corresponding key frames"; frames between are interpolated with ease()).
// Offsets are keyed by point ID (face-model.md, e.g. "8.4") and expressed in ES0 units (the
// eyeball distance of the face being animated), so one pose track animates any face
// (retargeting). A point absent from a key has offset 0 there. Tracked video lands here.
struct PoseKey
{
    double time = 0;
    QMap<QString, QPointF> offsetsEs0;

    bool operator==(const PoseKey &) const = default;
};

// One recording on the audio track: the file starts `offset` seconds into the animation and
// lasts `duration` seconds (0 when unknown); `trimIn` seconds of its start and `trimOut` of its
// end are not heard, so it sounds over [start(), end()]. Trimming moves nothing: the file's
// time t stays at offset + t. `script` is what the recording says and `language` its
// language ("cmn", "en" or empty); the syllables and mouth keys timed to it are those inside
// its span (Animation keeps them, at timeline times).
struct AudioClip
{
    AudioClip() = default;
    AudioClip(QString path, double offset, double duration)
        : path(std::move(path))
        , offset(offset)
        , duration(duration)
    { }

    QString path;
    double offset = 0;
    double duration = 0;
    double trimIn = 0;
    double trimOut = 0;
    QString script;
    QString language;

    // Where the clip is heard on the timeline.
    double start() const { return offset + trimIn; }
    double end() const { return std::max(start(), offset + duration - trimOut); }
    double length() const { return end() - start(); }

    bool operator==(const AudioClip &) const = default;
};

// The video the animation was tracked from (Import Video), shown beside the cartoon: its first
// frame is at `offset` seconds into the animation; it lasts `duration` seconds at `fps` frames
// a second (0 when unknown). Only a reference: the clip plays no part in the pose.
struct VideoClip
{
    QString path;
    double offset = 0;
    double duration = 0;
    double fps = 0;

    bool operator==(const VideoClip &) const = default;
};

// How the mouth track is smoothed (the thesis' contribution 8), in seconds.
struct MouthSmoothing
{
    // A shape shown for less than this (before the next one starts) is blended into the
    // next shape instead of flashing by.
    double minHold = 0.06;
    // The mouth starts moving toward a shape this long before its key (anticipation), and
    // takes as long to close when speech stops. Shorter intervals ease over the whole interval.
    double coarticulation = 0.1;
    // A pause longer than this after a shape's sound (after its key, when its duration is
    // unknown) shuts the mouth (`m`); shorter pauses keep the shape.
    double silenceHold = 0.3;

    bool operator==(const MouthSmoothing &) const = default;
};

// The tracks of a timeline, for selecting which ones a question is about.
enum class Track { Mouth = 0x1, Emotion = 0x2, Blink = 0x4, Gaze = 0x8, Head = 0x10, Pose = 0x20 };
Q_DECLARE_FLAGS(Tracks, Track)
Q_DECLARE_OPERATORS_FOR_FLAGS(Tracks)
inline constexpr Tracks kAllTracks = Tracks(0x3f);

// The key frames of one animation: mouth shapes, emotions, blinks, gaze, head motion, control-point
// poses and the audio track they play with. A plain value type holding no face: the same timeline animates
// any FaceModel through TimelineEvaluator, which turns it into a Pose at time t.
class Timeline
{
public:
    Timeline() = default;

    double frameRate() const { return m_frameRate; }
    // requires: fps > 0
    void setFrameRate(double fps) { m_frameRate = fps; }
    // The last audio clip's end, or the last key or clip end when that is later.
    double duration() const;
    // Frames of duration() at frameRate(), frame i showing time i / frameRate().
    int frameCount() const;

    const MouthSmoothing &smoothing() const { return m_smoothing; }
    void setSmoothing(const MouthSmoothing &smoothing) { m_smoothing = smoothing; }

    const QVector<MouthKey> &mouthKeys() const { return m_mouth; }
    void setMouthKeys(QVector<MouthKey> keys);
    void addMouthKey(const MouthKey &key);
    // Turns a lip-sync result into keys: one key per cue at its start, sounded until its end.
    // Existing mouth keys inside [first start, last end] are replaced.
    void addMouthCues(const QVector<MouthCue> &cues);
    // The mouth keys as cues; a key of unknown duration lasts until the next key, the last
    // one for smoothing().silenceHold. addMouthCues(mouthCues()) leaves the timeline unchanged
    // when every key has a duration.
    QVector<MouthCue> mouthCues() const;

    const QVector<EmotionClip> &emotionClips() const { return m_emotion; }
    void setEmotionClips(QVector<EmotionClip> clips);
    void addEmotionClip(const EmotionClip &clip);

    const QVector<BlinkEvent> &blinks() const { return m_blinks; }
    void setBlinks(QVector<BlinkEvent> blinks);
    void addBlink(const BlinkEvent &blink);
    // Replaces the blink track by randomBlinks(seed, duration).
    void generateBlinks(quint32 seed, double duration);
    // Human-like blinks over [0, duration], the same for the same seed on every platform:
    // gaps between blinks log-normal with a median of 3 s (mean start-to-start interval about
    // 3.5 s, clamped to [kBlinkGapMin, kBlinkGapMax]), one blink in ten doubled after a short
    // gap, durations about 0.17 s within [kBlinkDurationMin, kBlinkDurationMax].
    static QVector<BlinkEvent> randomBlinks(quint32 seed, double duration);
    static constexpr double kBlinkDurationMin = 0.1;
    static constexpr double kBlinkDurationMax = 0.4;
    static constexpr double kBlinkGapMin = 0.8;
    static constexpr double kBlinkGapMax = 10.0;
    static constexpr double kDoubleBlinkGapMin = 0.08;
    static constexpr double kDoubleBlinkGapMax = 0.25;

    const QVector<GazeKey> &gazeKeys() const { return m_gaze; }
    void setGazeKeys(QVector<GazeKey> keys);
    void addGazeKey(const GazeKey &key);

    const QVector<HeadKey> &headKeys() const { return m_head; }
    void setHeadKeys(QVector<HeadKey> keys);
    void addHeadKey(const HeadKey &key);
    // The head at time t from the head keys alone (identity when there are none).
    HeadKey headAt(double t) const;
    // Head presets (thesis Fig. 7.11). Each replaces the head keys in [start, end] by an
    // oscillation added to the head motion the keys gave before (so it starts and ends there):
    // shake: side to side, the rotation alternating +amplitude and -amplitude degrees;
    // nod: down by amplitude (ES0) and up by a quarter of it, alternating. Both make
    // `swingsPerSecond` extremes a second (at least two), damping to 70 % by the last one.
    // requires: start < end
    void addShake(double start, double end, double amplitudeDeg = 8.0, double swingsPerSecond = 5.0);
    void addNod(double start, double end, double amplitudeEs0 = 0.06, double swingsPerSecond = 4.0);

    // The pose track: control-point displacements per key frame, sorted by time.
    const QVector<PoseKey> &poseKeys() const { return m_pose; }
    void setPoseKeys(QVector<PoseKey> keys);
    // Replaces a key at the same time (within kPoseTimeTolerance), else inserts in time order.
    void addPoseKey(const PoseKey &key);
    static constexpr double kPoseTimeTolerance = 1e-9;

    // The audio track: the recordings the animation plays, sorted by start() (stable). Clips
    // may overlap (their sound is mixed); the editor places new ones where none plays.
    const QVector<AudioClip> &audioClips() const { return m_audio; }
    void setAudioClips(QVector<AudioClip> clips);
    // Inserts in start order (after clips of the same start); returns its index.
    int addAudioClip(const AudioClip &clip);
    // The clip heard at time t (the last to start, when several are), or -1.
    int audioClipAt(double t) const;

    // The clip the motion was tracked from, if any.
    const std::optional<VideoClip> &video() const { return m_video; }
    void setVideo(std::optional<VideoClip> video) { m_video = std::move(video); }

    // The pose at time t on `face` with `shapes`. Convenient for one time; it builds a
    // TimelineEvaluator every call, so sample many times through one evaluator instead.
    Pose evaluate(double t, const FaceModel &face, const MouthShapeSet &shapes) const;

    // The timeline as the project file's `timeline` object: {version, fps, smoothing, mouth,
    // emotion, blink, gaze, head, pose, audio [{path, offset, duration, trimIn, trimOut, script,
    // language}], video {path, offset, duration, fps}}; a pose key is {time, offsets: {ID:
    // [dx, dy]}}. Version 1 held one clip as an `audio` object {path, offset, duration}: it is
    // read as a track of that clip. Lossless: fromJson(toJson()) == *this.
    QJsonObject toJson() const;
    // Validates every field; on failure returns nullopt with *error naming the field by its
    // path, e.g. "mouth[3].shape: unknown mouth shape 'x'". Unknown fields are ignored.
    static std::optional<Timeline> fromJson(const QJsonObject &json, QString *error);
    static constexpr int kJsonVersion = 2;
    // The longest span a timeline keeps: four hours (an audio book's chapter fits many times);
    // a time further from 0 in a file is refused by name.
    static constexpr double kMaxSeconds = 4 * 3600.0;

    bool operator==(const Timeline &) const = default;

private:
    double m_frameRate = 25.0;
    MouthSmoothing m_smoothing;
    QVector<MouthKey> m_mouth;
    QVector<EmotionClip> m_emotion;
    QVector<BlinkEvent> m_blinks;
    QVector<GazeKey> m_gaze;
    QVector<HeadKey> m_head;
    QVector<PoseKey> m_pose;
    QVector<AudioClip> m_audio;
    std::optional<VideoClip> m_video;
};

} // namespace toonface
