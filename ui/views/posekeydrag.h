#pragma once

#include "document/animation.h"

#include <QCoreApplication>
#include <QPointF>
#include <QString>
#include <QVector>

#include <memory>

namespace toonface {

class Document;
class TimelineEvaluator;

// A point of the preview the user drags to key a pose (thesis 2.2.4): shown at `shownAt`, it
// keys the pose-track offset of the control point `control` (the chin shows the jaw, which is
// the lower lip's control 8.2: the chin keeps its distance below it by the rules of face-model.md).
struct PoseHandle
{
    const char *shownAt;
    const char *control;
    const char *label; // for the user, translated in the PoseKeyDrag context
};

// Mouth corners and lips, lids, brows and the jaw, in drawing order.
const QVector<PoseHandle> &poseHandles();

// The animation with a pose key at `time` giving control point `control` the pose-track offset
// `offsetEs0`. A key already at that time (within Timeline::kPoseTimeTolerance) keeps its other
// offsets; a new key takes the offsets the cartoon shows at `time` for every point the track moves
// (from `evaluator`, built on the same timeline, and `es0`: on the mouth's points in speech, as
// much of the track as TimelineEvaluator::poseOnMouthWeightAt() lets through), so nothing else
// moves where the key is added.
Animation withPoseOffset(const Animation &animation, const TimelineEvaluator &evaluator, double es0, double time,
    const QString &control, QPointF offsetEs0);

// The pose track's offset of `control` at `time` as the cartoon shows it, ES0 units.
QPointF poseTrackOffsetEs0(const TimelineEvaluator &evaluator, double es0, double time, const QString &control);

// One drag of a pose handle: every move replaces the animation as it was when the drag began by
// that animation with the dragged offset, pushed with one merge id (commit on release), so a
// drag is one undo step and undo restores the exact previous state. Nothing is pushed for a
// press without a move.
class PoseKeyDrag
{
    Q_DECLARE_TR_FUNCTIONS(PoseKeyDrag)

public:
    // requires: document has a face; evaluator built on the document's current animation.
    PoseKeyDrag(Document *document, std::shared_ptr<const TimelineEvaluator> evaluator, int handle, double time);

    int handle() const { return m_handle; }
    double time() const { return m_time; }
    // The mouse has moved by `photoDelta` (photo pixels, head motion undone) since the press.
    void moveBy(QPointF photoDelta);
    // Ends the drag (commits the step when anything moved).
    void finish();
    bool hasMoved() const { return m_moved; }

private:
    Animation after(QPointF photoDelta) const;

    Document *m_document;
    std::shared_ptr<const TimelineEvaluator> m_evaluator;
    int m_handle;
    double m_time;
    double m_es0;
    Animation m_before;
    QPointF m_startOffsetEs0;
    QPointF m_lastDelta;
    int m_mergeId;
    bool m_moved = false;
};

} // namespace toonface
