#pragma once

#include "detect/detector.h"
#include "face/mouthshape.h"
#include "track/facemeasure.h"
#include "track/framesource.h"
#include "track/oneeuro.h"

#include <QImage>
#include <QString>

#include <array>
#include <memory>
#include <optional>

namespace toonface {

class TrackingMethod;

struct TrackerOptions
{
    // As detection: auto uses the landmarks, the classic method (thesis ch. 6) when the
    // landmark model is missing or finds no face on the neutral frame.
    DetectionMethod method = DetectionMethod::Auto;
    // Jitter filtering (one-euro) of the points and head; off gives the raw measurements.
    bool smooth = true;
    // Point displacements and head translation in ES0 units: jitter of a still face (a few
    // thousandths of ES0) stays under the 1 Hz cut-off, a mouth opening at 2-3 ES0/s raises it
    // to 20-30 Hz, i.e. about one frame of lag at 25 fps.
    OneEuroParams points {1.0, 10.0, 1.0};
    // Lid openings (1 = neutral): blinks close in 2-3 frames, so the lids pass faster.
    OneEuroParams lids {2.0, 4.0, 1.0};
    // Snap each frame's mouth to the nearest of the nine shapes (thesis 6.4).
    bool snapMouth = false;
    MouthShapeSet shapes; // the shapes to snap to
    // The landmark method checks with the face detector every n-th frame that a face is there,
    // and at once when the face region looks different from the frame before.
    int verifyInterval = 5;
};

// One tracked frame.
struct TrackedFrame
{
    int index = 0;
    double time = 0;
    // No face this frame: the points and motion repeat the last good frame's.
    bool lost = false;
    double confidence = 0;
    // The 72 points in the frame's pixels.
    std::array<QPointF, kPointCount> points {};
    // Motion relative to the neutral face (ES0 units of the neutral face), filtered.
    FaceMotion motion;
    // With snapMouth: the shape the mouth was snapped to (its controls then hold that shape).
    std::optional<MouthShape> mouthShape;
};

// Turns frames into per-frame control-point motion relative to a neutral face.
//
// setNeutral() detects the face on the neutral frame (the clip's first, or the rest pose of
// live mode) and measures it with the tracking method; track() then measures each frame,
// starting from the frame before, filters the jitter and tells lost frames (a lost face holds
// the last pose, marked lost, and is searched for on every frame until found again).
//
// Thread safety: one Tracker is used by one thread at a time (it keeps the previous frame's
// state); separate Trackers may run on separate threads (they share the landmark model).
// track() takes 1-3 ms a frame at 360x288 with the landmarks: fit for live use.
class Tracker
{
public:
    explicit Tracker(TrackerOptions options = {});
    ~Tracker();
    Tracker(Tracker &&) noexcept;
    Tracker &operator=(Tracker &&) noexcept;

    const TrackerOptions &options() const { return m_options; }

    // Detects the neutral face in `frame`. False with *error (naming no file: the caller knows
    // it) and *status (NoFace, ModelMissing, BadImage) when there is none.
    bool setNeutral(const QImage &frame, QString *error, DetectStatus *status = nullptr);
    bool hasNeutral() const { return bool(m_method); }
    // The neutral frame's detection: the face to draw, the regions, the tracking seed.
    const DetectionResult &neutralDetection() const { return m_neutral; }
    // The tracking method's measurement of the neutral frame (what motion is relative to).
    const FaceMeasurement &neutralMeasurement() const { return m_neutralMeasure; }
    double neutralEs0() const;
    // "landmarks" or "classic".
    QString methodName() const;

    // requires: hasNeutral()
    TrackedFrame track(const VideoFrame &frame);
    TrackedFrame track(const QImage &image, double time, int index = 0)
    {
        return track(VideoFrame {image, time, index});
    }
    // Forgets the frames before (filters, last pose, where the face was); keeps the neutral.
    void restart();

    // The nearest of the nine shapes (but `n`, whose corners depend on the shape before) to
    // mouth control displacements (8.9, 8.2, 8.4, 8.3) in ES0 units, on the neutral face.
    MouthShape nearestMouthShape(const std::array<QPointF, 4> &mouthEs0) const;
    // A shape's displacements of 8.9, 8.2, 8.4, 8.3 from `m` on the neutral face, in ES0 units
    // (what a snapped frame's mouth controls hold). requires: hasNeutral()
    const std::array<QPointF, 4> &mouthShapeEs0(MouthShape shape) const { return m_shapesEs0[int(shape)]; }

private:
    TrackerOptions m_options;
    DetectionResult m_neutral;
    FaceMeasurement m_neutralMeasure;
    std::unique_ptr<TrackingMethod> m_method;
    struct Filters;
    std::unique_ptr<Filters> m_filters;
    std::optional<TrackedFrame> m_last;
    std::array<std::array<QPointF, 4>, kMouthShapeCount> m_shapesEs0 {};
};

} // namespace toonface
