#include "playbackfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "anim/easing.h"
#include "anim/timelineevaluator.h"
#include "face/fapu.h"
#include "playback/playhead.h"
#include "render/svgface.h"
#include "views/posekeydrag.h"
#include "views/previewview.h"

#include <QAction>
#include <QHBoxLayout>
#include <QUndoStack>
#include <QtTest>

using namespace toonface;

namespace {

// A press, several moves and a release, from `from` by `by` (widget pixels).
void drag(QWidget *widget, QPoint from, QPoint by, int steps = 5)
{
    QTest::mousePress(widget, Qt::LeftButton, Qt::NoModifier, from);
    for (int s = 1; s <= steps; ++s)
        QTest::mouseMove(widget, from + by * s / steps);
    QTest::mouseRelease(widget, Qt::LeftButton, Qt::NoModifier, from + by);
}

bool near(QPointF a, QPointF b, double tolerance)
{
    return QLineF(a, b).length() <= tolerance;
}

QString describe(QPointF p)
{
    return QStringLiteral("(%1, %2)").arg(p.x()).arg(p.y());
}

} // namespace

// Pose key frames (thesis 2.2.4) set by dragging control points on the preview at the playhead.
class TestPoseKeys : public QObject
{
    Q_OBJECT

    Document *m_doc = nullptr;
    Playhead *m_playhead = nullptr;
    QWidget *m_window = nullptr;
    PreviewView *m_preview = nullptr;

    QPointF handle(const char *id)
    {
        m_preview->svg(); // up to date
        const std::optional<QPointF> at = m_preview->handlePosition(QString::fromLatin1(id));
        return at.value_or(QPointF(-1, -1));
    }
    // Drags handle `id` at time `t` by `by`; returns where the press was.
    QPoint dragHandle(const char *id, double t, QPoint by)
    {
        m_playhead->setTime(t);
        const QPoint from = handle(id).toPoint();
        drag(m_preview, from, by);
        return from;
    }
    double es0() const { return m_doc->face().fapu().es0; }
    QPointF keyOffset(int key, const char *id) const
    {
        return m_doc->timeline().poseKeys().at(key).offsetsEs0.value(QString::fromLatin1(id));
    }

private Q_SLOTS:
    void init()
    {
        m_doc = new Document;
        fixture::fill(*m_doc);
        fixture::setTimeline(*m_doc, fixture::talkingTimeline(4.0));
        m_doc->undoStack()->clear();
        m_playhead = new Playhead;
        m_window = new QWidget;
        auto *layout = new QHBoxLayout(m_window);
        m_preview = new PreviewView(m_doc, m_playhead);
        layout->addWidget(m_preview);
        m_window->resize(420, 480);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        m_preview->editPoseAction()->setChecked(true);
    }

    void cleanup()
    {
        delete m_window;
        delete m_playhead;
        delete m_doc;
    }

    void handlesShowOnlyWhileEditingPose()
    {
        QVERIFY(m_preview->handlePosition(QStringLiteral("8.4")).has_value());
        QVERIFY(!m_preview->handlePosition(QStringLiteral("9.15")).has_value()); // the nose tip is no handle
        m_playhead->setPlaying(true); // they rest while the animation plays
        QVERIFY(!m_preview->handlePosition(QStringLiteral("8.4")).has_value());
        m_playhead->setPlaying(false);
        m_preview->editPoseAction()->setChecked(false);
        QVERIFY(!m_preview->handlePosition(QStringLiteral("8.4")).has_value());
        // Without handles a drag on the mouth corner changes nothing.
        m_preview->editPoseAction()->setChecked(true);
        const QPoint corner = handle("8.4").toPoint();
        m_preview->editPoseAction()->setChecked(false);
        drag(m_preview, corner, QPoint(-12, -8));
        QCOMPARE(m_doc->undoStack()->count(), 0);
        QVERIFY(m_doc->timeline().poseKeys().isEmpty());
    }

    // Two drags of the left mouth corner at two times: two key frames, the frame between them
    // interpolated with the timeline's ease, each drag one undo step, undo exact.
    void dragMouthCornerAtTwoTimesMakesTwoKeys()
    {
        const Animation before = m_doc->animation();
        const QByteArray svgAtT2Before = (m_playhead->setTime(1.2), m_preview->svg());
        const double t1 = 0.4;
        const double t2 = 1.2;

        m_playhead->setTime(t1);
        const QPointF cornerBefore = handle("8.4");
        const QImage imageBefore = m_preview->image();
        const QPoint by1(-14, -9);
        dragHandle("8.4", t1, by1);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(m_doc->timeline().poseKeys().size(), 1);
        QCOMPARE(m_doc->timeline().poseKeys().at(0).time, t1);
        // The corner followed the mouse; the key holds its offset in ES0 units.
        QVERIFY2(near(handle("8.4"), cornerBefore + QPointF(by1), 0.75),
            qPrintable(describe(handle("8.4")) + QStringLiteral(" vs ") + describe(cornerBefore + QPointF(by1))));
        const QPointF a = keyOffset(0, "8.4");
        QVERIFY(a.x() < 0 && a.y() < 0);
        QVERIFY(std::abs(a.x() / a.y() - 14.0 / 9.0) < 0.15);
        QVERIFY(m_preview->image() != imageBefore);

        m_playhead->setTime(t2);
        const QPointF cornerAtT2 = handle("8.4");
        const QPoint by2(10, 12);
        dragHandle("8.4", t2, by2);
        QCOMPARE(m_doc->undoStack()->count(), 2);
        QCOMPARE(m_doc->timeline().poseKeys().size(), 2);
        QCOMPARE(m_doc->timeline().poseKeys().at(1).time, t2);
        QVERIFY(near(handle("8.4"), cornerAtT2 + QPointF(by2), 0.75));
        const QPointF b = keyOffset(1, "8.4");
        // The second key starts from the track's value there (a's, held after the last key).
        QVERIFY(b.x() > a.x() && b.y() > a.y());

        // Between the keys the offset is eased: at a quarter of the way, ease(0.25) of it.
        const double tq = t1 + (t2 - t1) * 0.25;
        const TimelineEvaluator evaluator(m_doc->timeline(), m_doc->face(), m_doc->mouthShapes());
        const qsizetype i = evaluator.poseTrackPoints().indexOf(pt::idx("8.4"));
        QVERIFY(i >= 0);
        const QPointF between = evaluator.poseOffsetsAt(tq).at(i) / es0();
        const QPointF expected = a + (b - a) * ease(0.25);
        QVERIFY2(
            near(between, expected, 1e-9), qPrintable(describe(between) + QStringLiteral(" vs ") + describe(expected)));
        QVERIFY(!near(between, a, 1e-3) && !near(between, b, 1e-3));
        // ... and that is what the preview shows there.
        m_playhead->setTime(tq);
        SvgFace face(m_doc->face(), m_doc->style());
        face.setFrame(m_preview->frame());
        QCOMPARE(m_preview->svg(), face.svg(evaluator.evaluate(tq)));

        // Undo restores the exact previous states, redo the keys.
        const Animation withTwo = m_doc->animation();
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->timeline().poseKeys().size(), 1);
        m_doc->undoStack()->undo();
        QVERIFY(m_doc->animation() == before);
        m_playhead->setTime(t2);
        QCOMPARE(m_preview->svg(), svgAtT2Before);
        m_doc->undoStack()->redo();
        m_doc->undoStack()->redo();
        QVERIFY(m_doc->animation() == withTwo);
    }

    void draggingAgainAtAKeyEditsThatKey()
    {
        dragHandle("8.3", 0.8, QPoint(8, -6));
        const QPointF first = keyOffset(0, "8.3");
        dragHandle("8.3", 0.8, QPoint(6, 0));
        QCOMPARE(m_doc->timeline().poseKeys().size(), 1);
        QCOMPARE(m_doc->undoStack()->count(), 2);
        QVERIFY(keyOffset(0, "8.3").x() > first.x());
        QVERIFY(std::abs(keyOffset(0, "8.3").y() - first.y()) < 0.02);
    }

    // A key added later keeps the other points where the track had them at its time.
    void aNewKeyKeepsTheTrackOfTheOtherPoints()
    {
        dragHandle("4.2", 0.4, QPoint(0, -10)); // raise the left brow's inner end
        const QPointF brow = keyOffset(0, "4.2");
        QVERIFY(brow.y() < 0);
        const QPointF browOnScreen = (m_playhead->setTime(1.6), handle("4.2"));
        dragHandle("8.4", 1.6, QPoint(-8, 0));
        QCOMPARE(m_doc->timeline().poseKeys().size(), 2);
        QVERIFY(near(keyOffset(1, "4.2"), brow, 1e-12));
        QVERIFY(near(handle("4.2"), browOnScreen, 1e-6)); // the brow did not move
    }

    void theChinDragsTheJaw()
    {
        const QPointF lipBefore = (m_playhead->setTime(0.6), handle("8.2"));
        dragHandle("2.1", 0.6, QPoint(0, 12));
        QCOMPARE(m_doc->timeline().poseKeys().size(), 1);
        const PoseKey &key = m_doc->timeline().poseKeys().at(0);
        QVERIFY(key.offsetsEs0.contains(QStringLiteral("8.2")));
        QVERIFY(!key.offsetsEs0.contains(QStringLiteral("2.1")));
        QVERIFY(key.offsetsEs0.value(QStringLiteral("8.2")).y() > 0);
        QVERIFY(near(handle("8.2"), lipBefore + QPointF(0, 12), 0.75)); // the lower lip drops with it
    }

    void aClickWithoutMovingChangesNothing()
    {
        m_playhead->setTime(0.4);
        const QPoint at = handle("3.2").toPoint();
        QTest::mouseClick(m_preview, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(m_doc->undoStack()->count(), 0);
        QVERIFY(m_doc->timeline().poseKeys().isEmpty());
    }

    // The pieces of a key without the mouse.
    void withPoseOffsetReplacesOrInserts()
    {
        Animation animation = m_doc->animation();
        PoseKey key;
        key.time = 1.0;
        key.offsetsEs0.insert(QStringLiteral("4.1"), QPointF(0, -0.05));
        animation.timeline.addPoseKey(key);
        const TimelineEvaluator evaluator(animation.timeline, m_doc->face(), m_doc->mouthShapes());

        const Animation same = withPoseOffset(animation, evaluator, es0(), 1.0, QStringLiteral("8.4"), QPointF(0.1, 0));
        QCOMPARE(same.timeline.poseKeys().size(), 1);
        QCOMPARE(same.timeline.poseKeys().at(0).offsetsEs0.value(QStringLiteral("4.1")), QPointF(0, -0.05));
        QCOMPARE(same.timeline.poseKeys().at(0).offsetsEs0.value(QStringLiteral("8.4")), QPointF(0.1, 0));

        const Animation added
            = withPoseOffset(animation, evaluator, es0(), 0.5, QStringLiteral("8.4"), QPointF(0.1, 0));
        QCOMPARE(added.timeline.poseKeys().size(), 2);
        QCOMPARE(added.timeline.poseKeys().at(0).time, 0.5);
        QVERIFY(
            near(added.timeline.poseKeys().at(0).offsetsEs0.value(QStringLiteral("4.1")), QPointF(0, -0.05), 1e-12));
        QVERIFY(std::abs(poseTrackOffsetEs0(evaluator, es0(), 3.0, QStringLiteral("4.1")).y() + 0.05) < 1e-12);
    }
};

TOONFACE_TEST_MAIN(TestPoseKeys)
#include "tst_posekeys.moc"
