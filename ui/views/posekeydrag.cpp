#include "views/posekeydrag.h"

#include "anim/timelineevaluator.h"
#include "document/document.h"
#include "face/fapu.h"
#include "face/pointtable.h"

#include <cmath>

namespace toonface {

namespace {

// Merge ids of pose drags: one per drag, so two drags never merge.
int nextMergeId()
{
    static int id = 0x50000;
    return ++id;
}

} // namespace

const QVector<PoseHandle> &poseHandles()
{
    static const QVector<PoseHandle> handles = {
        {"4.6", "4.6", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left brow, outer")},
        {"4.4a", "4.4a", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left brow, outer middle")},
        {"4.4", "4.4", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left brow, inner middle")},
        {"4.2", "4.2", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left brow, inner")},
        {"4.1", "4.1", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right brow, inner")},
        {"4.3", "4.3", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right brow, inner middle")},
        {"4.3a", "4.3a", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right brow, outer middle")},
        {"4.5", "4.5", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right brow, outer")},
        {"3.2", "3.2", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left upper lid")},
        {"3.4", "3.4", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left lower lid")},
        {"3.1", "3.1", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right upper lid")},
        {"3.3", "3.3", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right lower lid")},
        {"8.4", "8.4", QT_TRANSLATE_NOOP("PoseKeyDrag", "Left mouth corner")},
        {"8.3", "8.3", QT_TRANSLATE_NOOP("PoseKeyDrag", "Right mouth corner")},
        {"8.9", "8.9", QT_TRANSLATE_NOOP("PoseKeyDrag", "Upper lip")},
        {"8.2", "8.2", QT_TRANSLATE_NOOP("PoseKeyDrag", "Lower lip")},
        {"2.1", "8.2", QT_TRANSLATE_NOOP("PoseKeyDrag", "Jaw (moves the lower lip and the chin)")},
    };
    return handles;
}

namespace {

// What the pose track adds to a point at `time` as the cartoon shows it: on the mouth's points
// in speech, only as much as TimelineEvaluator::poseOnMouthWeightAt() lets through.
QPointF shownOffset(const TimelineEvaluator &evaluator, int index, QPointF raw, double time)
{
    return pointTable()[index].group == PointGroup::Mouth ? raw * evaluator.poseOnMouthWeightAt(time) : raw;
}

} // namespace

QPointF poseTrackOffsetEs0(const TimelineEvaluator &evaluator, double es0, double time, const QString &control)
{
    const int index = pointIndex(control);
    const qsizetype at = evaluator.poseTrackPoints().indexOf(index);
    if (at < 0 || !(es0 > 0))
        return {};
    return shownOffset(evaluator, index, evaluator.poseOffsetsAt(time).at(at), time) / es0;
}

Animation withPoseOffset(const Animation &animation, const TimelineEvaluator &evaluator, double es0, double time,
    const QString &control, QPointF offsetEs0)
{
    Animation out = animation;
    const QVector<PoseKey> &keys = animation.timeline.poseKeys();
    PoseKey key;
    key.time = time;
    bool found = false;
    for (const PoseKey &k : keys) {
        if (std::abs(k.time - time) <= Timeline::kPoseTimeTolerance) {
            key = k;
            found = true;
        }
    }
    if (!found && es0 > 0) {
        const QVector<int> &points = evaluator.poseTrackPoints();
        const QVector<QPointF> offsets = evaluator.poseOffsetsAt(time);
        // The new key holds what each point shows now, so that adding it moves nothing else.
        for (qsizetype i = 0; i < points.size(); ++i)
            key.offsetsEs0.insert(pointId(points[i]), shownOffset(evaluator, points[i], offsets[i], time) / es0);
    }
    key.offsetsEs0.insert(control, offsetEs0);
    out.timeline.addPoseKey(key);
    return out;
}

PoseKeyDrag::PoseKeyDrag(
    Document *document, std::shared_ptr<const TimelineEvaluator> evaluator, int handle, double time)
    : m_document(document)
    , m_evaluator(std::move(evaluator))
    , m_handle(handle)
    , m_time(time)
    , m_es0(document->face().fapu().es0)
    , m_before(document->animation())
    , m_mergeId(nextMergeId())
{
    m_startOffsetEs0
        = poseTrackOffsetEs0(*m_evaluator, m_es0, m_time, QString::fromLatin1(poseHandles().at(m_handle).control));
}

Animation PoseKeyDrag::after(QPointF photoDelta) const
{
    const QPointF offset = m_startOffsetEs0 + (m_es0 > 0 ? photoDelta / m_es0 : QPointF());
    return withPoseOffset(
        m_before, *m_evaluator, m_es0, m_time, QString::fromLatin1(poseHandles().at(m_handle).control), offset);
}

void PoseKeyDrag::moveBy(QPointF photoDelta)
{
    if (!m_moved && photoDelta.isNull())
        return;
    m_moved = true;
    m_lastDelta = photoDelta;
    m_document->changeAnimation(after(photoDelta), tr("Set Pose Key"), m_mergeId, false);
}

void PoseKeyDrag::finish()
{
    if (m_moved)
        m_document->changeAnimation(after(m_lastDelta), tr("Set Pose Key"), m_mergeId, true);
}

} // namespace toonface
