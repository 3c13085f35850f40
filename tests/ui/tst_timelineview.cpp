#include "testmain.h"
#include "timelinefixture.h"
#include "uifixture.h"

#include "playback/playhead.h"
#include "timeline/emotionpalette.h"
#include "timeline/shapepalette.h"
#include "timeline/timelineview.h"
#include "timeline/timelinewidget.h"
#include "views/tonemarkfont.h"

#include <QApplication>
#include <QFontDatabase>
#include <QInputDialog>
#include <QLineEdit>
#include <QMimeData>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace toonface;

Q_DECLARE_METATYPE(QVector<toonface::Span>)

namespace {

constexpr double kPps = 300; // pixels per second in these tests: 3 s in 900 pixels

void drag(QWidget *viewport, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = Qt::NoModifier, int steps = 6)
{
    QTest::mousePress(viewport, Qt::LeftButton, modifiers, from);
    for (int s = 1; s <= steps; ++s)
        QTest::mouseMove(viewport, from + (to - from) * s / steps);
    QTest::mouseRelease(viewport, Qt::LeftButton, modifiers, to);
}

bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) < tolerance;
}

} // namespace

class TestTimelineView : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<Document> m_doc;
    std::unique_ptr<Playhead> m_playhead;
    std::unique_ptr<TimelineWidget> m_widget;
    TimelineView *m_view = nullptr;
    Animation m_before;

    QWidget *viewport() const { return m_view->viewport(); }
    QPoint at(double t, RowKind row, double dy = 0) const
    {
        const QRect r = m_view->timelineLayout().rowRect(row, viewport()->width());
        return QPoint(int(std::lround(m_view->xOf(t))), int(r.center().y() + dy));
    }
    QPoint centre(const ItemRef &item) const { return m_view->itemRect(item).center().toPoint(); }
    int undoCount() const { return m_doc->undoStack()->count(); }
    // Undoes back to the fixture and checks the document holds it exactly.
    void undoAllAndCompare()
    {
        while (m_doc->undoStack()->canUndo())
            m_doc->undoStack()->undo();
        QCOMPARE(m_doc->animation(), m_before);
    }

private Q_SLOTS:
    void init()
    {
        m_doc = std::make_unique<Document>();
        fixture::fillTalking(*m_doc);
        m_before = m_doc->animation();
        m_playhead = std::make_unique<Playhead>();
        m_widget = std::make_unique<TimelineWidget>(m_doc.get(), m_playhead.get());
        m_widget->resize(1200, 440);
        m_widget->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_widget.get()));
        m_view = m_widget->view();
        m_view->setPixelsPerSecond(kPps, TimelineLayout::kLabelWidth);
        m_view->setFocus();
        QCOMPARE(m_view->timelineLayout().scrollTime(), 0.0);
    }

    void cleanup()
    {
        m_widget.reset();
        m_playhead.reset();
        m_doc.reset();
    }

    // Dragging the end of a cue moves the boundary: the next cue (touching it) gives way.
    void dragCueEdge()
    {
        const int a = fixture::mouthKeyAt(m_before, 0.5); // hao's a, then its u
        QVERIFY(a >= 0);
        const QVector<Span> before = itemSpans(m_before, ItemKind::Mouth);
        const QRectF block = m_view->itemRect({ItemKind::Mouth, a});
        const QPoint grab(int(std::lround(block.right())), int(block.center().y()));
        QCOMPARE(m_view->hitAt(grab).part, HitPart::EndEdge);
        const int steps = undoCount();
        drag(viewport(), grab, grab + QPoint(30, 0)); // 0.1 s later
        QCOMPARE(undoCount(), steps + 1); // one drag, one step
        const QVector<Span> after = itemSpans(m_doc->animation(), ItemKind::Mouth);
        const double expected = std::round((before[a].end + 0.1) * 25) / 25; // snapped to a frame
        QVERIFY2(near(after[a].end, expected, 1e-3), qPrintable(QString::number(after[a].end)));
        QVERIFY(near(after[a + 1].start, after[a].end));
        QVERIFY(near(after[a + 1].end, before[a + 1].end) || after[a + 1].end > before[a + 1].end);
        QCOMPARE(after.size(), before.size());
        undoAllAndCompare();
    }

    // A drag that ends where it began (or is clamped at once) changes nothing and leaves no step.
    void dragThatChangesNothing()
    {
        const QPoint body = centre({ItemKind::Blink, 0});
        drag(viewport(), body, body + QPoint(0, 6)); // vertical: no time moved
        QCOMPARE(m_doc->undoStack()->count(), 0);
        QCOMPARE(m_doc->animation(), m_before);
    }

    void dragSyllableEdge()
    {
        const QRectF hao = m_view->itemRect({ItemKind::Syllable, 1});
        const QPoint grab(int(std::lround(hao.right())) - 1, int(hao.center().y()));
        QCOMPARE(m_view->hitAt(grab).part, HitPart::EndEdge);
        const double target = m_before.syllables[1].end + 27 / kPps; // 0.89: frame 22 is 0.88
        drag(viewport(), grab, grab + QPoint(27, 0));
        const Animation after = m_doc->animation();
        const LipsyncSyllable &syl = after.syllables[1];
        QVERIFY2(near(syl.end, std::round(target * 25) / 25, 1e-6), qPrintable(QString::number(syl.end)));
        QVERIFY(near(syl.shapes[1].start, syl.start + shapeStartFraction(2, 1) * (syl.end - syl.start)));
        QVERIFY(fixture::mouthKeyAt(after, syl.shapes[1].start) >= 0); // the u key went with it
        QVERIFY(near(after.syllables[2].start, syl.end)); // ma gave way
        QCOMPARE(m_doc->undoStack()->count(), 1);
        undoAllAndCompare();
    }

    void dragEmotionClip()
    {
        const EmotionClip clip = m_before.timeline.emotionClips()[0]; // smile 0.3 .. 1.5
        // Its body (below the intensity line, away from the handles) moves it.
        const QRectF r = m_view->itemRect({ItemKind::Emotion, 0});
        const QPoint body(int(r.center().x()), int(r.bottom()) - 3);
        QCOMPARE(m_view->hitAt(body).part, HitPart::Body);
        drag(viewport(), body, body + QPoint(60, 0));
        EmotionClip moved = m_doc->timeline().emotionClips()[0];
        QVERIFY(near(moved.start, clip.start + 0.2, 1e-3) && near(moved.end, clip.end + 0.2, 1e-3));
        QCOMPARE(moved.intensity, clip.intensity);

        // The fade-in handle sets the fade; the intensity line, dragged up, the intensity.
        const QPoint fadeIn = m_view->emotionHandle(0, HitPart::FadeIn).toPoint();
        QCOMPARE(m_view->hitAt(fadeIn).part, HitPart::FadeIn);
        drag(viewport(), fadeIn, fadeIn + QPoint(45, 0));
        moved = m_doc->timeline().emotionClips()[0];
        QVERIFY2(near(moved.fadeIn, clip.fadeIn + 0.15, 0.021), qPrintable(QString::number(moved.fadeIn)));
        const QPoint line = m_view->emotionHandle(0, HitPart::Intensity).toPoint();
        QCOMPARE(m_view->hitAt(line).part, HitPart::Intensity);
        drag(viewport(), line, line - QPoint(0, 30));
        QCOMPARE(m_doc->timeline().emotionClips()[0].intensity, 1.0);
        QCOMPARE(m_doc->undoStack()->count(), 3);
        undoAllAndCompare();
    }

    void keyboardReplacesShape()
    {
        const int a = fixture::mouthKeyAt(m_before, 0.5);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Mouth, a}));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Mouth, a}}));
        QCOMPARE(m_view->focusRow(), std::optional(RowKind::Mouth));
        QTest::keyClick(m_view, Qt::Key_O);
        QCOMPARE(m_doc->timeline().mouthKeys()[a].shape, MouthShape::O);
        Animation expected = m_before;
        QVector<MouthKey> keys = expected.timeline.mouthKeys();
        keys[a].shape = MouthShape::O;
        expected.timeline.setMouthKeys(keys);
        QCOMPARE(m_doc->animation(), expected); // nothing else changed

        // Nothing selected: a key is inserted at the playhead.
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, at(2.9, RowKind::Mouth, -10));
        m_playhead->setTime(2.7);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, at(0.05, RowKind::Script)); // empty: clears
        QVERIFY(m_view->selection().isEmpty());
        m_view->setFocusRow(RowKind::Mouth);
        QTest::keyClick(m_view, Qt::Key_E);
        const int e = fixture::mouthKeyAt(m_doc->animation(), 2.72); // snapped to frame 68
        QVERIFY(e >= 0 || fixture::mouthKeyAt(m_doc->animation(), 2.68) >= 0);
        QCOMPARE(m_doc->undoStack()->count(), 2);
        undoAllAndCompare();
    }

    void shapePaletteShowsTheLips()
    {
        const MouthIcons &icons = m_view->mouthIcons();
        for (MouthShape shape : kAllMouthShapes)
            QVERIFY(!icons.icon(shape).isNull());
        QVERIFY(icons.icon(MouthShape::A) != icons.icon(MouthShape::M)); // open and shut differ
        // New presets rebuild the pictures.
        const int builds = icons.buildCount();
        const QImage a = icons.icon(MouthShape::A);
        MouthShapeSet shapes = m_doc->mouthShapes();
        shapes.setPreset(MouthShape::A, shapes.preset(MouthShape::O));
        m_doc->changeMouthShapes(shapes, QStringLiteral("edit"));
        QCOMPARE(icons.buildCount(), builds + 1);
        QVERIFY(icons.icon(MouthShape::A) != a);
        // The palette's button replaces the selected key's shape.
        m_view->setSelection({{ItemKind::Mouth, 1}});
        auto *button = m_widget->findChild<QToolButton *>(QStringLiteral("shape-u"));
        QVERIFY(button);
        button->click();
        QCOMPARE(m_doc->timeline().mouthKeys()[1].shape, MouthShape::U);
    }

    void dropEmotionPreset()
    {
        const QPoint pos = at(2.0, RowKind::Emotion);
        std::unique_ptr<QMimeData> mime(emotionMimeData(Emotion::Angry));
        QDragEnterEvent enter(pos, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport(), &enter);
        QVERIFY(enter.isAccepted());
        QDragMoveEvent move(pos, Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport(), &move);
        QVERIFY(move.isAccepted());
        QDropEvent drop(QPointF(pos), Qt::CopyAction, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport(), &drop);
        const QVector<EmotionClip> &clips = m_doc->timeline().emotionClips();
        QCOMPARE(clips.size(), 2);
        QCOMPARE(clips[1].emotion, Emotion::Angry);
        QVERIFY(near(clips[1].start, 2.0, 0.021));
        QVERIFY(near(clips[1].end - clips[1].start, 2.0));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Emotion, 1}}));
        // A preset applied to a selected range fills it.
        m_view->setSelection({{ItemKind::Syllable, 0}, {ItemKind::Syllable, 2}});
        m_widget->findChild<QToolButton *>(QStringLiteral("emotion-sad"))->click();
        bool found = false;
        for (const EmotionClip &c : m_doc->timeline().emotionClips())
            found = found || (c.emotion == Emotion::Sad && near(c.start, 0.2) && near(c.end, 1.1));
        QVERIFY(found);
        undoAllAndCompare();

        // Dropped inside a selected phrase it fills the phrase; inside one short shape it does
        // not shrink to the shape: it starts where it was dropped.
        const auto dropAt = [this](QPoint p, Emotion e) {
            std::unique_ptr<QMimeData> data(emotionMimeData(e));
            QDragEnterEvent enter(p, Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(viewport(), &enter);
            QDropEvent drop(QPointF(p), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(viewport(), &drop);
            return m_doc->timeline().emotionClips().value(m_view->selection().indices(ItemKind::Emotion).value(0));
        };
        m_view->setSelection({{ItemKind::Syllable, 0}, {ItemKind::Syllable, 1}, {ItemKind::Syllable, 2}});
        EmotionClip filled = dropAt(at(0.7, RowKind::Emotion), Emotion::Surprise);
        QVERIFY(filled.emotion == Emotion::Surprise && near(filled.start, 0.2) && near(filled.end, 1.1));
        const int shortKey = fixture::mouthKeyAt(m_before, 0.5);
        const QVector<MouthCue> cues = m_doc->timeline().mouthCues();
        QVERIFY(cues.size() > 2);
        m_view->setSelection({{ItemKind::Mouth, shortKey}});
        const std::optional<Span> one = selectionRange(m_doc->animation(), m_view->selection());
        QVERIFY(one && one->end - one->start < 0.5);
        const double inside = (one->start + one->end) / 2;
        EmotionClip placed = dropAt(at(inside, RowKind::Emotion), Emotion::Angry);
        QCOMPARE(placed.emotion, Emotion::Angry);
        QVERIFY2(near(placed.end - placed.start, 2.0), qPrintable(QString::number(placed.end - placed.start)));
        undoAllAndCompare();
    }

    void rubberBandSelectAndDelete()
    {
        // From the empty start of the script row to the pause, across the mouth row.
        drag(viewport(), at(0.05, RowKind::Script, -8), at(1.3, RowKind::Mouth));
        const Selection selected = m_view->selection();
        QCOMPARE(selected.indices(ItemKind::Syllable), QVector<int>({0, 1, 2}));
        QVERIFY(selected.indices(ItemKind::Mouth).size() >= 5);
        QVERIFY(!selected.hasKind(ItemKind::Emotion)); // rows outside the band are not taken
        QTest::keyClick(m_view, Qt::Key_Delete);
        QCOMPARE(m_doc->syllables().size(), 2);
        QCOMPARE(m_doc->syllables()[0].text, QStringLiteral("明"));
        QVERIFY(m_view->selection().isEmpty());
        QCOMPARE(m_doc->undoStack()->count(), 1);
        undoAllAndCompare();
    }

    void shiftAndCtrlClick()
    {
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Blink, 0}));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, centre({ItemKind::Blink, 1}));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Blink, 0}, {ItemKind::Blink, 1}}));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier, centre({ItemKind::Blink, 0}));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Blink, 1}}));
        // Shift+click extends from the last clicked item of the row, as in a list: a phrase.
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Syllable, 0}));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, centre({ItemKind::Syllable, 2}));
        QCOMPARE(m_view->selection().indices(ItemKind::Syllable), QVector<int>({0, 1, 2}));
        QCOMPARE(m_view->selection().size(), 3);
        QCOMPARE(m_doc->undoStack()->count(), 0); // selecting is no edit
    }

    // Clicking a mouth key puts the playhead inside it, so the cartoon shows the shape chosen;
    // a wider selection or playback leaves the playhead alone.
    void selectedMouthKeyIsShown()
    {
        const QVector<MouthKey> keys = m_doc->timeline().mouthKeys();
        QVERIFY(keys.size() >= 4);
        m_playhead->setTime(0);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Mouth, 2}));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Mouth, 2}}));
        const double t = m_playhead->time();
        QVERIFY2(t > keys[2].time && t < keys[3].time, qPrintable(QString::number(t)));
        QCOMPARE(fixture::mouthShapeAt(m_doc->animation(), t), std::optional<MouthShape>(keys[2].shape));

        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, centre({ItemKind::Mouth, 3}));
        QCOMPARE(m_view->selection().size(), 2);
        QCOMPARE(m_playhead->time(), t);
        m_playhead->setPlaying(true);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Mouth, 1}));
        QCOMPARE(m_view->selection(), Selection({{ItemKind::Mouth, 1}}));
        QCOMPARE(m_playhead->time(), t);
        m_playhead->setPlaying(false);
        QCOMPARE(m_doc->undoStack()->count(), 0);
    }

    // An emotion's intensity as a number: double-click the clip (or its menu's Intensity…),
    // type the percentage; one undo step.
    void emotionIntensityByNumber()
    {
        QCOMPARE(m_doc->timeline().emotionClips().first().intensity, 0.8);
        bool answered = false;
        QTimer::singleShot(50, this, [&answered] {
            auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            QCOMPARE(dialog->objectName(), QStringLiteral("emotionIntensityDialog"));
            QCOMPARE(dialog->intValue(), 80);
            QVERIFY2(dialog->labelText().contains(QStringLiteral("Smile")), qPrintable(dialog->labelText()));
            dialog->setIntValue(35);
            dialog->accept();
            answered = true;
        });
        QTest::mouseDClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Emotion, 0}));
        QVERIFY(answered);
        QCOMPARE(m_doc->timeline().emotionClips().first().intensity, 0.35);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->timeline().emotionClips().first().intensity, 0.8);

        // Cancelled: nothing changes.
        QTimer::singleShot(50, this, [] {
            if (auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget()))
                dialog->reject();
        });
        m_widget->editEmotionIntensity(0);
        QCOMPARE(m_doc->timeline().emotionClips().first().intensity, 0.8);
        QCOMPARE(m_doc->undoStack()->index(), 0);
    }

    void copyAndPaste()
    {
        const int a = fixture::mouthKeyAt(m_before, 0.5);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Mouth, a}));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier, centre({ItemKind::Mouth, a + 1}));
        QTest::keyClick(m_view, Qt::Key_C, Qt::ControlModifier);
        m_playhead->setTime(2.6);
        QTest::keyClick(m_view, Qt::Key_V, Qt::ControlModifier);
        const Animation after = m_doc->animation();
        const int pasted = fixture::mouthKeyAt(after, 2.6);
        QVERIFY(pasted >= 0);
        QCOMPARE(after.timeline.mouthKeys()[pasted].shape, m_before.timeline.mouthKeys()[a].shape);
        const double gap = m_before.timeline.mouthKeys()[a + 1].time - m_before.timeline.mouthKeys()[a].time;
        QCOMPARE(after.timeline.mouthKeys()[pasted + 1].shape, m_before.timeline.mouthKeys()[a + 1].shape);
        QVERIFY(near(after.timeline.mouthKeys()[pasted + 1].time, 2.6 + gap));
        QCOMPARE(m_view->selection().indices(ItemKind::Mouth), QVector<int>({pasted, pasted + 1}));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        undoAllAndCompare();
    }

    void mouthWeightFromTheBlockTop()
    {
        const int a = fixture::mouthKeyAt(m_before, 0.5);
        const QRectF r = m_view->itemRect({ItemKind::Mouth, a});
        const QPoint top(int(r.center().x()), int(std::lround(r.top())) + 1);
        QCOMPARE(m_view->hitAt(top).part, HitPart::Weight);
        drag(viewport(), top, top + QPoint(0, int((r.height() - 4) / 2)));
        QVERIFY(near(m_doc->timeline().mouthKeys()[a].weight, 0.5, 0.05));
        undoAllAndCompare();
    }

    void pinyinEditedInPlace()
    {
        QTest::mouseDClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Syllable, 2}));
        auto *editor = viewport()->findChild<QLineEdit *>(QStringLiteral("pinyinEditor"));
        QVERIFY(editor && editor->isVisible());
        QCOMPARE(editor->text(), QStringLiteral("ma5"));
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("miao4"));
        QTest::keyClick(editor, Qt::Key_Return);
        QCOMPARE(m_doc->syllables()[2].pinyin, QStringLiteral("miao"));
        QCOMPARE(m_doc->syllables()[2].shapes.size(), 4);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        undoAllAndCompare();
    }

    void headAndBlinkActions()
    {
        m_playhead->setTime(1.0);
        m_widget->timelineActions().addShake->trigger();
        QVERIFY(m_doc->timeline().headKeys().size() > m_before.timeline.headKeys().size());
        m_widget->timelineActions().regenerateBlinks->trigger();
        QVERIFY(m_doc->timeline().blinks() != m_before.timeline.blinks());
        QCOMPARE(m_doc->undoStack()->count(), 2);
        const TimelineActions &actions = m_widget->timelineActions();
        for (QAction *action : {actions.zoomIn, actions.zoomOut, actions.zoomToFit, actions.snap, actions.deleteItems,
                 actions.copy, actions.paste, actions.regenerateBlinks, actions.addShake, actions.addNod,
                 actions.applyEmotion[int(Emotion::Smile)]})
            QVERIFY2(!action->icon().pixmap(20, 20).isNull(), qPrintable(action->text()));
        undoAllAndCompare();
    }

    // Issue 26: Head Nod acts at the playhead after a click elsewhere on the ruler, not over the
    // selection made before it.
    void headNodAfterClickingElsewhere()
    {
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, centre({ItemKind::Blink, 0})); // 0.9 s
        QVERIFY(!m_view->selection().isEmpty());
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, at(2.5, RowKind::Ruler));
        QVERIFY(m_view->selection().isEmpty());
        QVERIFY(near(m_playhead->time(), 2.5, 0.021));
        m_widget->timelineActions().addNod->trigger();
        QVector<double> added;
        for (const HeadKey &k : m_doc->timeline().headKeys())
            if (!m_before.timeline.headKeys().contains(k))
                added << k.time;
        QVERIFY(!added.isEmpty());
        QVERIFY2(
            *std::min_element(added.begin(), added.end()) >= 2.5 - 0.021, qPrintable(QString::number(added.first())));
        undoAllAndCompare();
    }

    void rulerScrubs()
    {
        QVERIFY(!m_playhead->isScrubbing());
        const QPoint from = at(0.5, RowKind::Ruler);
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, from);
        QVERIFY(m_playhead->isScrubbing());
        QVERIFY(near(m_playhead->time(), 0.5, 0.021));
        QTest::mouseMove(viewport(), at(1.5, RowKind::Ruler));
        QVERIFY(near(m_playhead->time(), 1.5, 0.021));
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, at(1.5, RowKind::Ruler));
        QVERIFY(!m_playhead->isScrubbing());
        QCOMPARE(m_doc->undoStack()->count(), 0);
    }

    // Issue 26: two recordings as clips on the Audio row. A clip's title strip moves it, with
    // its syllables and mouth keys; its edge trims it; Delete removes it with what it owns; the
    // waveform under the title still scrubs. Each is one undo step.
    void audioClipsMoveTrimAndDelete()
    {
        QTemporaryDir dir;
        const auto tone = [&](const char *name, double seconds) {
            Audio audio;
            audio.samples.resize(qsizetype(seconds * audio.sampleRate));
            for (qsizetype i = 0; i < audio.samples.size(); ++i)
                audio.samples[i] = float(0.5 * std::sin(2 * M_PI * 220 * double(i) / audio.sampleRate));
            QString error;
            const QString path = dir.filePath(QString::fromLatin1(name));
            if (!writeAudio(path, audio, &error))
                qFatal("%s", qPrintable(error));
            return path;
        };
        // The fixture's syllables: 你好吗 over 0.2-1.1 s, 明天 over 1.6-2.4 s.
        Animation a = m_doc->animation();
        a.timeline.setAudioClips(
            {AudioClip {tone("first.wav", 1.2), 0.0, 1.2}, AudioClip {tone("second.wav", 1.0), 1.5, 1.0}});
        m_doc->changeAnimation(a, QStringLiteral("sound"));
        const Animation two = m_doc->animation();
        m_view->setPixelsPerSecond(kPps, TimelineLayout::kLabelWidth); // new sound: it zoomed to fit
        m_view->waveform(1)->waitForFinished();

        const QRectF r = m_view->itemRect({ItemKind::Audio, 1});
        QVERIFY(near(r.left(), m_view->xOf(1.5), 1.0));
        const QPoint title(int(r.center().x()), int(r.top()) + 6);
        QCOMPARE(m_view->hitAt(title).item, (std::optional<ItemRef>(ItemRef {ItemKind::Audio, 1})));
        QCOMPARE(m_view->hitAt(title).part, HitPart::Body);
        QVERIFY(!m_view->hitAt(QPoint(title.x(), int(r.bottom()) - 4)).item); // the waveform scrubs

        // Moved 0.5 s later: its syllables and mouth keys follow, the first clip's stay.
        drag(viewport(), title, title + QPoint(int(0.5 * kPps), 0));
        const QVector<AudioClip> &clips = m_doc->timeline().audioClips();
        QCOMPARE(clips.size(), 2);
        QCOMPARE(clips[0], two.timeline.audioClips()[0]);
        QVERIFY2(near(clips[1].offset, 2.0, 1e-6), qPrintable(QString::number(clips[1].offset)));
        const QVector<LipsyncSyllable> &syllables = m_doc->syllables();
        QCOMPARE(syllables.size(), two.syllables.size());
        for (qsizetype i = 0; i < syllables.size(); ++i) {
            const double shift = two.syllables[i].start >= 1.5 ? 0.5 : 0.0;
            QVERIFY2(near(syllables[i].start, two.syllables[i].start + shift), qPrintable(syllables[i].text));
            QVERIFY(near(syllables[i].end, two.syllables[i].end + shift));
        }
        const QVector<MouthKey> &keys = m_doc->timeline().mouthKeys();
        QCOMPARE(keys.size(), two.timeline.mouthKeys().size());
        for (const MouthKey &k : two.timeline.mouthKeys()) {
            const double shift = k.time >= 1.5 && k.time < 2.5 ? 0.5 : 0.0;
            QVERIFY2(std::any_of(keys.begin(), keys.end(),
                         [&](const MouthKey &m) { return near(m.time, k.time + shift) && m.shape == k.shape; }),
                qPrintable(QString::number(k.time)));
        }
        QCOMPARE(m_doc->undoStack()->undoText(), QStringLiteral("Move on Timeline"));

        // Its start edge trims it: heard from 2.2 s, the file where it was.
        const QRectF moved = m_view->itemRect({ItemKind::Audio, 1});
        const QPoint edge(int(std::lround(moved.left())) + 1, int(moved.center().y()));
        QCOMPARE(m_view->hitAt(edge).part, HitPart::StartEdge);
        drag(viewport(), edge, edge + QPoint(int(0.2 * kPps), 0));
        QVERIFY2(near(m_doc->timeline().audioClips()[1].trimIn, 0.2, 1e-6),
            qPrintable(QString::number(m_doc->timeline().audioClips()[1].trimIn)));
        QVERIFY(near(m_doc->timeline().audioClips()[1].offset, 2.0));

        // The first clip, selected by its title and deleted, goes with its syllables (你好吗).
        const QRectF first = m_view->itemRect({ItemKind::Audio, 0});
        QTest::mouseClick(
            viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(int(first.center().x()), int(first.top()) + 6));
        QCOMPARE(m_view->selection(), (Selection {{ItemKind::Audio, 0}}));
        QTest::keyClick(m_view, Qt::Key_Delete);
        QCOMPARE(m_doc->timeline().audioClips().size(), 1);
        QCOMPARE(m_doc->timeline().audioClips()[0].path, two.timeline.audioClips()[1].path);
        QCOMPARE(m_doc->syllables().size(), 2);
        QCOMPARE(m_doc->syllables()[0].text, QStringLiteral("明"));
        QCOMPARE(m_doc->undoStack()->count(), 4);
        undoAllAndCompare();
    }

    void wheelZoomsAboutTheCursor()
    {
        const QPoint cursor = at(1.0, RowKind::Mouth);
        const double before = m_view->timelineLayout().timeAt(cursor.x());
        QWheelEvent zoom(QPointF(cursor), QPointF(viewport()->mapToGlobal(cursor)), QPoint(), QPoint(0, 240),
            Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport(), &zoom);
        QVERIFY(near(m_view->timelineLayout().pixelsPerSecond(), kPps * 1.25 * 1.25, 1e-6));
        QVERIFY(near(m_view->timelineLayout().timeAt(cursor.x()), before, 1e-9));
        QWheelEvent scroll(QPointF(cursor), QPointF(viewport()->mapToGlobal(cursor)), QPoint(), QPoint(0, -120),
            Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        const double scrolled = m_view->timelineLayout().scrollTime();
        QApplication::sendEvent(viewport(), &scroll);
        QVERIFY(m_view->timelineLayout().scrollTime() > scrolled);
        m_widget->timelineActions().zoomToFit->trigger();
        QCOMPARE(m_view->timelineLayout().scrollTime(), 0.0);
        QVERIFY(m_view->xOf(m_doc->timeline().duration()) <= viewport()->width());
    }

    void playheadMovedByAKeyStaysInSight()
    {
        m_view->setPixelsPerSecond(2000, TimelineLayout::kLabelWidth); // about half a second in sight
        QVERIFY(m_view->xOf(2.5) > viewport()->width());
        m_playhead->setTime(2.5); // what End or the arrows do
        QVERIFY2(m_view->xOf(2.5) >= TimelineLayout::kLabelWidth && m_view->xOf(2.5) <= viewport()->width(),
            qPrintable(QString::number(m_view->xOf(2.5))));
        m_playhead->setTime(0); // Home
        QCOMPARE(m_view->timelineLayout().scrollTime(), 0.0);
    }

    void newSoundIsShownWhole()
    {
        m_view->setPixelsPerSecond(2000, TimelineLayout::kLabelWidth);
        QTemporaryDir dir;
        waveformHeight(0.5, dir);
        QVERIFY2(m_view->xOf(3.0) <= viewport()->width(), qPrintable(QString::number(m_view->xOf(3.0))));
        QCOMPARE(m_view->timelineLayout().scrollTime(), 0.0);
    }

    void emptyProjectShowsSecondsNotMinutes()
    {
        Document empty;
        Playhead playhead;
        TimelineWidget widget(&empty, &playhead);
        widget.resize(60, 300); // laid out narrow first, as a dock is
        widget.show();
        QVERIFY(QTest::qWaitForWindowExposed(&widget));
        widget.resize(1200, 300);
        QTest::qWait(20);
        const double shown = widget.view()->timelineLayout().timeAt(widget.view()->viewport()->width());
        QVERIFY2(shown < 10, qPrintable(QString::number(shown)));
    }

    // The ink in the middle of the pinyin under syllable `index`: the tone-marked vowel of "hǎo".
    int pinyinMiddleInk(int index)
    {
        const QImage image = viewport()->grab().toImage();
        const QRectF inner = m_view->itemRect({ItemKind::Syllable, index}).adjusted(3, 1, -3, -1);
        const int x = int(inner.center().x());
        int ink = 0;
        for (int y = int(inner.top() + inner.height() * 0.6); y < int(inner.bottom()); ++y)
            for (int dx = -2; dx <= 2; ++dx)
                ink += qGray(image.pixel(x + dx, y)) > 110 ? 1 : 0;
        return ink;
    }

    void thirdToneIsDrawnInAChineseLocaleFont()
    {
        // The sans serif fontconfig gives zh_TW here claims ǎ ǒ ǐ ǔ and draws nothing for them.
        const QString family = QStringLiteral("WenQuanYi Micro Hei");
        if (!QFontDatabase::families().contains(family))
            QSKIP("WenQuanYi Micro Hei is not installed");
        const QFont before = QApplication::font();
        QFont chinese(family);
        chinese.setPointSizeF(before.pointSizeF());
        QVERIFY(!drawsToneMarks(chinese));
        QApplication::setFont(chinese);
        ensureToneMarks();
        QVERIFY(drawsToneMarks(QApplication::font()));
        QCOMPARE(QApplication::font().families().value(1), family); // Chinese still drawn in it
        init();
        QCOMPARE(m_doc->animation().syllables[1].tone, 3);
        const int ink = pinyinMiddleInk(1);
        QApplication::setFont(before);
        QVERIFY2(ink >= 3, qPrintable(QString::number(ink)));
    }

    // Sets a sine of `amplitude` (of full scale) as the project's sound and returns how many
    // pixels of the waveform row are lit in the column at 1.5 s.
    // Three seconds of a 220 Hz tone at `amplitude` of full scale.
    static QString toneFile(double amplitude, const QTemporaryDir &dir)
    {
        const QString path = dir.filePath(QStringLiteral("tone%1.wav").arg(amplitude));
        Audio audio;
        audio.samples.resize(3 * audio.sampleRate);
        for (qsizetype i = 0; i < audio.samples.size(); ++i)
            audio.samples[i] = float(amplitude * std::sin(2 * M_PI * 220 * double(i) / audio.sampleRate));
        QString error;
        if (!writeAudio(path, audio, &error))
            qFatal("%s", qPrintable(error));
        return path;
    }

    int waveformHeight(double amplitude, const QTemporaryDir &dir)
    {
        const QString path = toneFile(amplitude, dir);
        Animation a = m_doc->animation();
        a.timeline.setAudioClips({AudioClip {path, 0, 3}});
        m_doc->changeAnimation(a, QStringLiteral("sound"));
        m_view->waveform()->waitForFinished();
        if (m_view->waveform()->peaks().isEmpty())
            qFatal("%s", qPrintable(m_view->waveform()->error()));
        return litHeight();
    }

    // The waveform's lit pixels in the column at `time`.
    int litHeight(double time = 1.5)
    {
        const QImage image = viewport()->grab().toImage();
        const QRect row = m_view->timelineLayout().rowRect(RowKind::Waveform, viewport()->width());
        const int x = int(m_view->xOf(time));
        int lit = 0;
        for (int y = row.top(); y <= row.bottom(); ++y)
            lit += qGreen(image.pixel(x, y)) > 150 ? 1 : 0;
        return lit;
    }

    void waveformIsPainted()
    {
        QTemporaryDir dir;
        const int lit = waveformHeight(0.8, dir);
        // The row is drawn from the peaks: near full height at 0.8 of full scale.
        const int rowHeight = m_view->timelineLayout().rowRect(RowKind::Waveform, viewport()->width()).height();
        QVERIFY2(lit > rowHeight / 2, qPrintable(QString::number(lit)));
    }

    void quietRecordingIsDrawnAtItsLoudness()
    {
        // An ordinary speech recording peaking at -26.5 dBFS is drawn as tall as a loud one.
        QTemporaryDir dir;
        const int loud = waveformHeight(0.8, dir);
        const int quiet = waveformHeight(std::pow(10.0, -26.5 / 20), dir);
        const int rowHeight = m_view->timelineLayout().rowRect(RowKind::Waveform, viewport()->width()).height();
        QVERIFY2(quiet > rowHeight / 2, qPrintable(QStringLiteral("%1 of %2 px").arg(quiet).arg(rowHeight)));
        QVERIFY2(std::abs(quiet - loud) <= 2, qPrintable(QStringLiteral("%1 vs %2 px").arg(quiet).arg(loud)));
        QVERIFY(m_view->waveformGain() > 15);
    }

    // A quiet recording beside a loud clip (a video's sound put after a take): each is drawn at its
    // own loudness, the quiet one not a flat line under the loud one's gain.
    void eachRecordingIsDrawnAtItsOwnLoudness()
    {
        QTemporaryDir dir;
        Animation a = m_doc->animation();
        a.timeline.setAudioClips(
            {AudioClip {toneFile(0.8, dir), 0, 3}, AudioClip {toneFile(std::pow(10.0, -26.5 / 20), dir), 3, 3}});
        m_doc->changeAnimation(a, QStringLiteral("two sounds"));
        for (int clip : {0, 1}) {
            m_view->waveform(clip)->waitForFinished();
            QVERIFY2(!m_view->waveform(clip)->peaks().isEmpty(), qPrintable(m_view->waveform(clip)->error()));
        }
        m_widget->timelineActions().zoomToFit->trigger();
        QVERIFY(m_view->xOf(4.5) < viewport()->width());
        const int rowHeight = m_view->timelineLayout().rowRect(RowKind::Waveform, viewport()->width()).height();
        const int loud = litHeight(1.5), quiet = litHeight(4.5);
        QVERIFY2(quiet > rowHeight / 2, qPrintable(QStringLiteral("%1 of %2 px").arg(quiet).arg(rowHeight)));
        QVERIFY2(std::abs(quiet - loud) <= 2, qPrintable(QStringLiteral("%1 vs %2 px").arg(quiet).arg(loud)));
        QVERIFY(m_view->waveformGain(1) > 15 * m_view->waveformGain(0));
    }

    // The gain under the Audio row's title: "+1 dB" said, "-0 dB" (a clip drawn all but as it
    // is) not.
    void gainIsSaidOnlyWhenItIsOne()
    {
        const auto labelInk = [&] {
            const QImage image = viewport()->grab().toImage();
            const QRect row = m_view->timelineLayout().rowRect(RowKind::Waveform, viewport()->width());
            int ink = 0;
            for (int y = row.top() + row.height() * 7 / 10; y < row.bottom(); ++y)
                for (int x = 0; x < TimelineLayout::kLabelWidth - 2; ++x)
                    ink += qGray(image.pixel(x, y)) > 100 ? 1 : 0;
            return ink;
        };
        QTemporaryDir dir;
        waveformHeight(0.8, dir); // drawn at 0.9 / 0.8: +1 dB
        QVERIFY(labelInk() > 10);
        waveformHeight(0.92, dir); // 0.9 / 0.92: -0.2 dB
        QCOMPARE(labelInk(), 0);
    }

    // A clip over another: its title strip shows its own name only, not the one beneath it.
    void titleOfAClipOverAnotherIsReadable()
    {
        QTemporaryDir dir;
        AudioClip under {toneFile(0.8, dir), 0, 3};
        under.script = QStringLiteral("a long script that runs on under the clip put over it");
        const AudioClip over {toneFile(0.5, dir), 0.5, 2.5};
        const auto titleOfOver = [&](const QVector<AudioClip> &clips) {
            Animation a = m_doc->animation();
            a.timeline.setAudioClips(clips);
            m_doc->changeAnimation(a, QStringLiteral("sounds"));
            m_view->setPixelsPerSecond(300, TimelineLayout::kLabelWidth);
            const QRectF box = m_view->itemRect({ItemKind::Audio, int(clips.indexOf(over))});
            // Past the start of its own name, to its end.
            const QRect strip(int(box.left()) + 90, int(box.top()) + 2, int(box.width()) - 100, 10);
            return viewport()->grab().toImage().copy(strip);
        };
        const QImage alone = titleOfOver({over});
        const QImage overAnother = titleOfOver({under, over});
        QCOMPARE(overAnother, alone);
    }

    void stackInLanes_data()
    {
        QTest::addColumn<QVector<Span>>("spans");
        QTest::addColumn<QVector<int>>("lanes");
        QTest::newRow("apart") << QVector<Span> {{0, 1}, {1.5, 2}} << QVector<int> {0, 0};
        QTest::newRow("touching") << QVector<Span> {{0, 1}, {1, 2}} << QVector<int> {0, 0};
        QTest::newRow("overlapping") << QVector<Span> {{0, 2}, {1, 3}} << QVector<int> {0, 1};
        QTest::newRow("a lane freed") << QVector<Span> {{0, 1}, {0.5, 2}, {1.5, 3}} << QVector<int> {0, 1, 0};
        QTest::newRow("three at once") << QVector<Span> {{0, 3}, {1, 2}, {1.5, 2.5}} << QVector<int> {0, 1, 2};
        QTest::newRow("given out of order") << QVector<Span> {{1, 3}, {0, 2}} << QVector<int> {1, 0};
    }

    void stackInLanes()
    {
        QFETCH(QVector<Span>, spans);
        QFETCH(QVector<int>, lanes);
        QCOMPARE(toonface::stackInLanes(spans), lanes);
    }

    // The rows shrink, all in proportion, from comfortable to compact before they scroll.
    void rowsShrinkToCompactBeforeScrolling()
    {
        TimelineLayout layout;
        const int comfortable = layout.comfortableHeight(), compact = layout.compactHeight();
        QVERIFY(compact < comfortable);
        layout.fitRows(10000);
        QCOMPARE(layout.contentHeight(), comfortable);
        layout.fitRows((compact + comfortable) / 2);
        QVERIFY(layout.contentHeight() <= (compact + comfortable) / 2);
        QVERIFY(layout.contentHeight() > compact);
        for (const int room : {compact, compact / 2}) {
            layout.fitRows(room);
            QCOMPARE(layout.contentHeight(), compact);
            for (const TimelineRow &r : layout.rows())
                QCOMPARE(r.height, r.compact);
        }
        // A second lane adds a compact lane's height (or a comfortable one's, given room).
        layout.setItemLanes(RowKind::Emotion, {0, 1});
        QCOMPARE(layout.compactHeight(), compact + layout.row(RowKind::Emotion).compact);
        QCOMPARE(layout.contentHeight(), compact + layout.row(RowKind::Emotion).compact);
    }

    // Issue 26: overlapping clips of one track stack in lanes (the row grows), so that each
    // one's title and body are seen and taken by the pointer, none hidden under another; apart
    // again, the row shrinks back to one lane.
    void overlappingClipsStackInLanes_data()
    {
        QTest::addColumn<int>("kind");
        QTest::newRow("audio") << int(ItemKind::Audio);
        QTest::newRow("emotion") << int(ItemKind::Emotion);
    }

    void overlappingClipsStackInLanes()
    {
        QFETCH(int, kind);
        const ItemKind item = ItemKind(kind);
        const RowKind row = rowOf(item);
        const auto rowRect = [&](RowKind r) { return m_view->timelineLayout().rowRect(r, viewport()->width()); };
        const TimelineLayout &layout = m_view->timelineLayout();
        QCOMPARE(layout.row(row).lanes, 1);
        QTemporaryDir dir;
        Animation a = m_doc->animation();
        if (item == ItemKind::Audio)
            a.timeline.setAudioClips({AudioClip {toneFile(0.8, dir), 0, 3}, AudioClip {toneFile(0.5, dir), 0.5, 2.5}});
        else
            a.timeline.setEmotionClips({EmotionClip {0.2, 2.6, Emotion::Smile, 1.0, 0.3, 0.3},
                EmotionClip {0.8, 2.2, Emotion::Sad, 1.0, 0.3, 0.3}});
        m_doc->changeAnimation(a, QStringLiteral("overlapping clips"));
        m_view->setPixelsPerSecond(kPps, TimelineLayout::kLabelWidth);

        const QRectF first = m_view->itemRect({item, 0}), second = m_view->itemRect({item, 1});
        QVERIFY2(!first.intersects(second),
            qPrintable(QStringLiteral("(%1, %2) and (%3, %4)")
                           .arg(first.top())
                           .arg(first.bottom())
                           .arg(second.top())
                           .arg(second.bottom())));
        QCOMPARE(layout.row(row).lanes, 2);
        QCOMPARE(rowRect(row).height(), 2 * layout.row(row).laneHeight);
        for (const QRectF &r : {first, second}) {
            QVERIFY(QRectF(rowRect(row)).contains(r));
            QVERIFY(r.bottom() <= rowRect(RowKind(int(row) + 1)).top()); // the next row moved down
        }
        // Over the span both play in, each one's title takes that one.
        const int x = int(m_view->xOf(1.5));
        for (int i : {0, 1}) {
            const QRectF r = m_view->itemRect({item, i});
            const TimelineHit hit = m_view->hitAt(QPoint(x, int(r.top()) + 5));
            QCOMPARE(hit.item, (std::optional<ItemRef>(ItemRef {item, i})));
            QCOMPARE(hit.part, HitPart::Body);
        }
        // A click on the second's title selects it, not the first.
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, int(second.top()) + 5));
        QCOMPARE(m_view->selection(), (Selection {{item, 1}}));

        m_doc->undoStack()->undo();
        QCOMPARE(layout.row(row).lanes, 1);
        QCOMPARE(rowRect(row).height(), layout.row(row).laneHeight);
    }

    void waveformZoomsVertically()
    {
        QTemporaryDir dir;
        const int normal = waveformHeight(std::pow(10.0, -26.5 / 20), dir);
        m_widget->timelineActions().waveformShorter->trigger();
        m_widget->timelineActions().waveformShorter->trigger();
        const int shorter = litHeight();
        QVERIFY2(shorter < normal * 0.6, qPrintable(QStringLiteral("%1 vs %2 px").arg(shorter).arg(normal)));
        // Alt+wheel up over the row brings it back.
        const QPoint pos = at(1.5, RowKind::Waveform);
        for (int i = 0; i < 2; ++i) {
            QWheelEvent wheel(pos, viewport()->mapToGlobal(pos), {}, QPoint(0, 120), Qt::NoButton, Qt::AltModifier,
                Qt::NoScrollPhase, false);
            QApplication::sendEvent(viewport(), &wheel);
        }
        QCOMPARE(m_view->waveformZoom(), 1.0);
        QCOMPARE(litHeight(), normal);
    }
};

TOONFACE_TEST_MAIN(TestTimelineView)
#include "tst_timelineview.moc"
