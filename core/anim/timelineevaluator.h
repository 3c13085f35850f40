#pragma once

#include "anim/timeline.h"
#include "face/pose.h"

#include <QPointF>
#include <QVector>

#include <array>

namespace toonface {

class FaceModel;
class MouthShapeSet;

// A Timeline bound to one face and its mouth shapes, answering "which Pose at time t?".
//
// The constructor does all the work that does not depend on t (O(keys)): it resolves the
// mouth track into eased nodes (minimum hold, coarticulation, return to `m` in silence, the
// `n` shape's corners from the shape before), caches the displacements of the nine shapes and
// the five emotions for this face, and indexes clips and blinks; evaluate(t) is then a few
// binary searches (O(log keys), well under 0.1 ms). It keeps no reference to its arguments.
// Immutable after construction: one evaluator may be shared by threads.
//
// The pose at t is composed as speech + emotion + gaze + blink + head:
// - mouth: the displacement of 8.9, 8.2, 8.4, 8.3 eased between resolved key frames. A key's
//   shape is reached at its key time and held until the mouth moves on toward the next key
//   (over smoothing().coarticulation, or the whole interval when it is shorter). Keys shown
//   shorter than minHold are merged with the keys after them, their displacements averaged by
//   the time each is shown. After a shape's sound ends (its key time plus its duration, the key
//   time alone when that is unknown), a pause longer than silenceHold shuts the mouth: the shape
//   holds for at least minHold, then eases to `m` and reopens in time for the next key. The
//   mouth is shut before the first key and after the last.
// - emotion: every clip active at t adds emotionPose(face, emotion, envelope(t)), the envelope
//   easing from 0 to its intensity over fadeIn and back over fadeOut; added to the mouth, so a
//   smiling face still speaks. The emotion's lid scale multiplies the lid opening.
// - gaze: the eyeball offset eased between gaze keys, in pixels (ES0 units times ES0).
// - blink: the lid opening eases 1 -> 0 over the blink's closing phase, stays 0, eases back to
//   1 over the (longer) opening phase (kBlinkPhases); overlapping blinks take the smaller opening.
// - head: eased between head keys (translation in pixels).
// - pose: the pose track's control-point offsets (ES0 units times this face's ES0, pixels) eased
//   between pose keys and added last, on top of speech, emotion and gaze (derived points follow
//   by the control rules in posedPoints()); a point absent from a key is at 0 there.
// Between two key values every quantity follows ease() (see easing.h); before the first key of
// a gaze, head or pose track its first value holds, after the last its last value.
class TimelineEvaluator
{
public:
    TimelineEvaluator(const Timeline &timeline, const FaceModel &face, const MouthShapeSet &shapes);

    Pose evaluate(double t) const;

    // The parts of evaluate(t).
    // Displacements of the mouth controls 8.9, 8.2, 8.4, 8.3 by speech alone (kMouthControlIds order).
    std::array<QPointF, 4> mouthAt(double t) const;
    // Lid opening from blinks alone: 1 open, 0 shut.
    double blinkOpenAt(double t) const;
    // The envelope of emotion clip `index` of the timeline's emotionClips() at t: the share of the
    // emotion's full pose drawn, 0..emotionWeight(intensity).
    double emotionEnvelopeAt(qsizetype index, double t) const;

    double duration() const { return m_duration; }

    // Key times for an exporter that writes SMIL <animate> values/keyTimes instead of one
    // group per frame. `times` holds 0, duration() and every time in [0, duration()] where one of
    // the chosen tracks has a key value or an ease starts or ends, sorted and distinct.
    // segments[i] tells how the pose moves on [times[i], times[i+1]]:
    // - Hold: nothing moves; every quantity keeps its value at times[i].
    // - Ease: each quantity moves from its value at times[i] to the one at times[i+1] along
    //   exactly one ease(), so calcMode="spline" with kEaseKeySpline reproduces evaluate() exactly
    //   (as it does any quantity that depends linearly on the pose).
    // - Mixed: eases of different spans overlap (say an emotion fading in while the mouth talks)
    //   or a product of moving factors (lid scale times blink); each quantity is still smooth,
    //   but an exporter has to sample inside the segment, e.g. at frame times.
    // A value jumps only at the edge of an emotion clip with no fade (fadeIn or fadeOut 0).
    // An exporter asks, per animated element, for the tracks that move it, so each element gets
    // only its own key times: the mouth and jaw Mouth | Emotion, the lids Blink | Emotion, the
    // eyeballs Gaze, the brows Emotion, the head transform Head; Pose moves whichever control points
    // its keys name (poseTrackPoints()).
    enum class Segment { Hold, Ease, Mixed };
    struct ExportKeys
    {
        QVector<double> times;
        QVector<Segment> segments; // times.size() - 1 entries
    };
    ExportKeys exportKeys(Tracks tracks = kAllTracks) const;
    QVector<double> keyTimes(Tracks tracks = kAllTracks) const { return exportKeys(tracks).times; }

    // Indices (pointTable()) of the points the pose track moves, ascending.
    const QVector<int> &poseTrackPoints() const { return m_posePoints; }
    // The pose track's offsets at t, pixels, in poseTrackPoints() order.
    QVector<QPointF> poseOffsetsAt(double t) const;
    // How much the speech owns the mouth at t, 0..1: 1 over each recording on the audio track
    // (over the mouth track when there is none), easing to 0 within kSpeechFade of its edges.
    double speechWeightAt(double t) const;
    // How much the pose track's keys on the mouth's points (lips, corners, the jaw by 8.2) count
    // at t, 0..1: fully where the character is silent, and in speech only around a pose key
    // (easing to 0 within kPoseKeyReach of it), so an Edit Pose jaw key opens the jaw at its
    // time, the key the user dragged shows, and the speech's mouth wins the rest of the speech
    // (a jaw key held the mouth open through all of it). Evaluate() and the export apply it.
    double poseOnMouthWeightAt(double t) const;
    static constexpr double kSpeechFade = 0.15;
    static constexpr double kPoseKeyReach = 0.2;

    // The resolved mouth track: the mouth displacements of kMouthControlIds at these times, eased
    // between neighbours (for inspection and tests; mouthAt() samples it).
    const QVector<double> &mouthNodeTimes() const { return m_mouthTimes; }
    const QVector<std::array<QPointF, 4>> &mouthNodeValues() const { return m_mouthValues; }

private:
    struct Envelope
    {
        double start, fadeInEnd, fadeOutStart, end, intensity; // intensity: the held weight
        int emotion;
        double at(double t) const;
    };
    struct Blink
    {
        double start, shutAt, openingAt, end;
        double openAt(double t) const;
    };
    struct EmotionCache
    {
        QVector<int> points; // indices of the points the emotion moves
        QVector<QPointF> offsets; // their displacement at full intensity, pixels
        double lidScaleDelta = 0; // lid scale at full intensity minus 1
    };

    void buildMouth(const Timeline &timeline, const FaceModel &face, const MouthShapeSet &shapes);
    void buildPose(const Timeline &timeline, double es0);

    double m_duration = 0;
    std::array<int, 4> m_mouthIndex {};
    std::array<QPointF, 4> m_restingMouth {}; // the mouth with no mouth track: shut
    QVector<double> m_mouthTimes;
    QVector<std::array<QPointF, 4>> m_mouthValues;

    std::array<EmotionCache, 5> m_emotionCache;
    QVector<Envelope> m_clips; // in the timeline's order (sorted by start)
    QVector<double> m_clipStarts;
    QVector<double> m_clipEndsSoFar; // the latest end among clips 0..i

    QVector<Blink> m_blinks;
    QVector<double> m_blinkStarts;
    QVector<double> m_blinkEndsSoFar;

    int m_leftEyeball = 0;
    int m_rightEyeball = 0;
    QVector<double> m_gazeTimes;
    QVector<QPointF> m_gazeValues; // pixels

    QVector<double> m_headTimes;
    QVector<HeadPose> m_headValues; // translation in pixels

    QVector<int> m_posePoints;
    QVector<double> m_poseTimes; // distinct, ascending (the later of equal-time keys wins)
    QVector<QPointF> m_poseValues; // pixels, m_posePoints.size() per key, key after key
    QVector<char> m_poseOnMouth; // per m_posePoints: a point of the mouth (speech wins there)
    bool m_poseMovesMouth = false;
    QVector<std::pair<double, double>> m_speechSpans; // sorted by start
};

} // namespace toonface
