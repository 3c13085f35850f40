#include "dialogfixture.h"
#include "testmain.h"
#include "uifixture.h"
#include "videofixture.h"

#include "capture/importvideodialog.h"
#include "dialogs/jobstatus.h"
#include "document/document.h"
#include "media/mediareader.h"
#include "track/retarget.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLayout>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace toonface;
using namespace toonface::videofixture;
using namespace toonface::dialogfixture;

namespace {

constexpr int kTrackTimeoutMs = 240000;

// Something on the tracks an import replaces and on the ones it keeps.
Animation busyAnimation()
{
    Animation a;
    a.timeline.addMouthKey({0.5, MouthShape::A, 1.0, 0.2});
    a.timeline.addMouthKey({2.0, MouthShape::O, 1.0, 0.2}); // where a clip placed at 1.5 s plays
    a.syllables.append({QStringLiteral("好"), QStringLiteral("hao"), 3, 0.4, 0.7, 1.0, {{MouthShape::A, 0.5}}});
    a.syllables.append({QStringLiteral("远"), QStringLiteral("yuan"), 3, 2.0, 2.3, 1.0, {{MouthShape::O, 2.0}}});
    a.timeline.addEmotionClip({0.0, 3.0, Emotion::Smile, 0.8, 0.3, 0.3});
    a.timeline.addBlink({1.0, 0.18});
    a.timeline.addHeadKey({2.0, 5.0, QPointF(0.01, 0), 1.0});
    return a;
}

void fillBusy(Document &doc)
{
    fixture::fill(doc);
    doc.changeAnimation(busyAnimation(), QStringLiteral("setup"));
    doc.undoStack()->clear();
}

template<class T>
T *child(QWidget &parent, const char *name)
{
    return parent.findChild<T *>(QString::fromLatin1(name));
}

// Clicks a check box or radio button on its box, as a user would (the rows are wider than the
// text, so the middle of the widget may be past it).
void clickBox(QAbstractButton *button)
{
    QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(6, button->height() / 2));
}

// Waits until the dialog shows frame `index` large.
bool waitForFrame(ImportVideoDialog &dialog, int index)
{
    return QTest::qWaitFor([&] { return !dialog.shownFrame().isNull() && dialog.shownFrameIndex() == index; }, 20000);
}

} // namespace

class TestImportVideo : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_talking; // the drawn face, with a tone
    QString m_grey; // no face

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_dir.isValid());
        bool skipped = false;
        const QString path = m_dir.filePath(QStringLiteral("talking.mp4"));
        const QString error = writeTalkingClip(path, true, &skipped);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        if (!skipped)
            m_talking = path;
        m_grey = m_dir.filePath(QStringLiteral("grey.mp4"));
        QCOMPARE(writeGreyClip(m_grey, 20), QString());
    }

    // The slider picks the neutral frame and shows it large, decoded as core decodes it.
    void neutralFramePickerShowsTheFrame()
    {
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(!child<QPushButton>(dialog, "start")->isEnabled()); // no clip yet
        QVERIFY(dialog.openClip(m_grey));
        QCOMPARE(child<QSlider>(dialog, "neutralSlider")->maximum(), 19);
        QVERIFY(!child<QCheckBox>(dialog, "useSound")->isChecked()); // the clip has none
        QVERIFY(!child<QCheckBox>(dialog, "useSound")->isEnabled());
        QVERIFY(child<QPushButton>(dialog, "start")->isEnabled());
        QVERIFY(waitForFrame(dialog, 0));

        // Dragging the slider through many frames: the last one asked for is shown.
        auto *slider = child<QSlider>(dialog, "neutralSlider");
        for (int i = 1; i <= 12; ++i)
            slider->setValue(i);
        QCOMPARE(child<QSpinBox>(dialog, "neutralFrame")->value(), 12);
        QVERIFY(waitForFrame(dialog, 12));
        QString error;
        const std::optional<QImage> expected = readVideoFrame(m_grey, 12, &error);
        QVERIFY2(expected, qPrintable(error));
        QVERIFY(meanDifference(dialog.shownFrame(), *expected) < 1.0);
        // Back to an earlier frame (the file is reopened).
        child<QSpinBox>(dialog, "neutralFrame")->setValue(3);
        QVERIFY(waitForFrame(dialog, 3));
        QVERIFY(meanDifference(dialog.shownFrame(), *readVideoFrame(m_grey, 3, &error)) < 1.0);
        QCOMPARE(doc.animation(), busyAnimation()); // looking changes nothing
    }

    // The neutral frame is chosen for the user: not frame 0 when it catches the mouth open,
    // nor a blink, but a frame with the lips closed and the eyes open, shown large.
    void choosesAFrameAtRest()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        const testing::TalkingFace talking {QImage(kPortrait).scaled(320, 320)};
        QVERIFY(talking.isValid());
        // The mouth open over frames 0-5, the eyes shut on 6-7, at rest from 8.
        const QString path = m_dir.filePath(QStringLiteral("opensmidword.mp4"));
        QCOMPARE(writeClip(path, kTalkingFrames, false,
                     [&](int i) { return talking.frame(i < 6 ? 1.0 : 0.0, i == 6 || i == 7 ? 0.0 : 1.0); }),
            QString());
        Document doc;
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QSignalSpy suggested(&dialog, &ImportVideoDialog::neutralSuggested);
        QVERIFY(dialog.openClip(path));
        QVERIFY(suggested.wait(kTrackTimeoutMs));
        const int chosen = suggested.first().first().toInt();
        QVERIFY2(chosen >= 8, qPrintable(QString::number(chosen)));
        QCOMPARE(dialog.neutralFrame(), chosen);
        QVERIFY(waitForFrame(dialog, chosen));
        QVERIFY(!child<QLabel>(dialog, "neutralNote")->text().isEmpty());
        grab(&dialog, QStringLiteral("importvideo-neutral-chosen"));

        // Importing from it: frame 0's open mouth is an opening, not the rest.
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(applied.wait(kTrackTimeoutMs));
        const auto lowerLip
            = [&](int frame) { return doc.timeline().poseKeys()[frame].offsetsEs0.value(QStringLiteral("8.2")).y(); };
        QVERIFY2(lowerLip(0) > lowerLip(12) + 0.05,
            qPrintable(QStringLiteral("%1 vs %2").arg(lowerLip(0)).arg(lowerLip(12))));
    }

    // A frame the user picked before the search ended is kept.
    void keepsTheUsersNeutralFrame()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QSignalSpy suggested(&dialog, &ImportVideoDialog::neutralSuggested);
        QVERIFY(dialog.openClip(m_talking));
        child<QSlider>(dialog, "neutralSlider")->setValue(10);
        QVERIFY(suggested.wait(kTrackTimeoutMs));
        QCOMPARE(dialog.neutralFrame(), 10);
        QVERIFY(waitForFrame(dialog, 10));
        // Opened again, the search chooses anew; on a clip without a face it says so.
        QVERIFY(dialog.openClip(m_grey));
        suggested.clear();
        QVERIFY(suggested.wait(kTrackTimeoutMs));
        QCOMPARE(suggested.first().first().toInt(), -1);
        QCOMPARE(dialog.neutralFrame(), 0);
    }

    // At its smallest (as it opens on a laptop's screen) every row has its own place: the
    // neutral frame's slider was drawn over the bottom of the picture, the dialog narrower than
    // its text was laid out for.
    void rowsDoNotOverlapAtTheSmallestSize()
    {
        Document doc;
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(dialog.openClip(m_grey));
        dialog.resize(dialog.minimumSize());
        QTRY_COMPARE(dialog.size(), dialog.minimumSize());
        QVERIFY2(dialog.width() >= 600, qPrintable(QString::number(dialog.width())));
        const auto *view = dialog.findChild<QWidget *>(QStringLiteral("neutralView"));
        const auto *slider = child<QSlider>(dialog, "neutralSlider");
        const auto *method = dialog.findChild<QWidget *>(QStringLiteral("method"));
        const auto *clip = dialog.findChild<QWidget *>(QStringLiteral("clip"));
        QVERIFY(view && method && clip);
        auto box = [&](const QWidget *w) { return QRect(w->mapTo(&dialog, QPoint(0, 0)), w->size()); };
        QVERIFY(box(clip).bottom() < box(view).top());
        QVERIFY2(box(view).bottom() < box(slider).top(),
            qPrintable(QStringLiteral("picture to %1, slider from %2").arg(box(view).bottom()).arg(box(slider).top())));
        QVERIFY(box(slider).bottom() < box(method).top());
        QVERIFY(view->height() >= view->minimumHeight());
    }

    // A long error (a deep path has no spaces to wrap at) keeps to a few lines under the form
    // at the dialog's smallest size, cut in the middle with "…", and is whole in its tooltip: it pushed the
    // neutral frame's slider over the picture, and a path widened the dialog past the screen.
    void aLongErrorKeepsToItsLinesAtTheSmallestSize()
    {
        Document doc;
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QString deep = m_dir.path();
        for (int i = 0; i < 12; ++i)
            deep += QStringLiteral("/a_folder_with_a_long_name_%1").arg(i);
        const QString missing = deep + QStringLiteral("/clip.mp4");
        QVERIFY(!dialog.openClip(missing));
        const QString error = dialog.message();
        QVERIFY2(error.contains(QStringLiteral("clip.mp4")), qPrintable(error)); // the whole text
        dialog.resize(dialog.minimumSize());
        QTRY_COMPARE(dialog.size(), dialog.minimumSize());
        QVERIFY2(dialog.width() <= 800, qPrintable(QString::number(dialog.width())));
        const auto *view = dialog.findChild<QWidget *>(QStringLiteral("neutralView"));
        const auto *slider = child<QSlider>(dialog, "neutralSlider");
        const auto *method = dialog.findChild<QWidget *>(QStringLiteral("method"));
        const auto *message = dialog.findChild<QLabel *>(QStringLiteral("message"));
        const auto *start = dialog.findChild<QWidget *>(QStringLiteral("start"));
        QVERIFY(view && method && message && start);
        auto box = [&](const QWidget *w) { return QRect(w->mapTo(&dialog, QPoint(0, 0)), w->size()); };
        QVERIFY2(box(view).bottom() < box(slider).top(),
            qPrintable(QStringLiteral("picture to %1, slider from %2").arg(box(view).bottom()).arg(box(slider).top())));
        QVERIFY(box(slider).bottom() < box(method).top());
        QVERIFY(box(method).bottom() < box(message).top());
        QVERIFY(box(message).bottom() < box(start).top());
        QVERIFY(view->height() >= view->minimumHeight());
        // Shown in at most kMessageLines lines that fit the label, the rest in the tooltip.
        const QStringList lines = message->text().split(QLatin1Char('\n'));
        QVERIFY2(lines.size() <= kMessageLines, qPrintable(message->text()));
        QVERIFY(message->height() >= int(lines.size()) * message->fontMetrics().lineSpacing());
        for (const QString &line : lines)
            QVERIFY2(
                message->fontMetrics().horizontalAdvance(line) <= message->contentsRect().width(), qPrintable(line));
        QVERIFY(message->text().contains(QStringLiteral("…")));
        // Cut in the middle: the end, which says the problem, stays.
        QVERIFY2(error.endsWith(lines.last().section(QStringLiteral("…"), -1)), qPrintable(lines.last()));
        QCOMPARE(message->toolTip(), error);
        grab(&dialog, QStringLiteral("importvideo-long-error"));

        // A short one is shown whole, with no tooltip.
        QVERIFY(!dialog.openClip(m_dir.filePath(QStringLiteral("gone.mp4"))));
        QTRY_VERIFY(!message->text().contains(QStringLiteral("…")));
        QCOMPARE(message->text().simplified(), dialog.message().simplified());
        QVERIFY(message->toolTip().isEmpty());
    }

    void importsTheMotionAsOneUndoStep()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();
        ImportVideoDialog dialog(&doc, 1.5);
        dialog.show();
        QVERIFY(dialog.openClip(m_talking));
        QVERIFY(child<QCheckBox>(dialog, "useSound")->isChecked()); // on: the clip has sound
        QVERIFY(child<QRadioButton>(dialog, "atPlayhead")->isChecked());
        QVERIFY(child<QRadioButton>(dialog, "continuousMouth")->isChecked());
        QVERIFY(!child<QCheckBox>(dialog, "usePhoto")->isVisible()); // the project has a face
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(dialog.isRunning());
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(doc.undoStack()->count(), 1);

        // The same keys as the track put onto the timeline by core, at the playhead.
        const Timeline &t = doc.timeline();
        QCOMPARE(t.poseKeys().size(), kTalkingFrames);
        QCOMPARE(t.poseKeys().first().time, 1.5);
        QCOMPARE(t.gazeKeys().size(), kTalkingFrames);
        QCOMPARE(t.headKeys().size(), kTalkingFrames);
        // The mouth opens where the drawing opens it (pose keys carry the lower lip, 8.2).
        const auto lowerLip
            = [&](int frame) { return t.poseKeys()[frame].offsetsEs0.value(QStringLiteral("8.2")).y(); };
        QVERIFY2(lowerLip(11) > lowerLip(3) + 0.05,
            qPrintable(QStringLiteral("%1 vs %2").arg(lowerLip(11)).arg(lowerLip(3))));
        // The blink before the clip (at 1.0 s) stays; the clip's one is where the eyes shut
        // (frames 18-19 from 1.5 s).
        QCOMPARE(t.blinks().size(), 2);
        QCOMPARE(t.blinks()[0], before.timeline.blinks()[0]);
        QVERIFY(std::abs(blinkMiddle(t.blinks()[1]) - (1.5 + 18.5 / kFps)) <= 1.5 / kFps);
        // Continuous mouth: the pose track moves the mouth where the clip plays, so the mouth keys
        // there go and those elsewhere stay; the clip's sound is a new clip on the audio track,
        // which replaces nothing: the syllables stay. The emotions stay.
        QCOMPARE(t.mouthKeys().size(), 1);
        QCOMPARE(t.mouthKeys()[0], before.timeline.mouthKeys()[0]);
        QCOMPARE(doc.syllables(), before.syllables);
        QCOMPARE(t.emotionClips(), before.timeline.emotionClips());
        // The clip is the sound and the video, from the playhead.
        QVERIFY(!t.audioClips().isEmpty());
        QCOMPARE(t.audioClips().first().path, m_talking);
        QCOMPARE(t.audioClips().first().offset, 1.5);
        QVERIFY(std::abs(t.audioClips().first().duration - kTalkingFrames / kFps) < 0.05);
        QVERIFY(t.video());
        QCOMPARE(t.video()->path, m_talking);
        QCOMPARE(t.video()->offset, 1.5);
        QCOMPARE(t.video()->fps, kFps);

        // One undo restores the exact animation before; redo brings the import back.
        const Animation imported = doc.animation();
        doc.undoStack()->undo();
        QCOMPARE(doc.animation(), before);
        doc.undoStack()->redo();
        QCOMPARE(doc.animation(), imported);
    }

    void projectSoundIsKeptUnlessAsked()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        fillBusy(doc);
        Animation a = doc.animation();
        a.timeline.setAudioClips({AudioClip {m_dir.filePath(QStringLiteral("recording.wav")), 0, 6.0}});
        doc.changeAnimation(a, QStringLiteral("sound"));
        const AudioClip recording = doc.timeline().audioClips().first();
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(dialog.openClip(m_talking));
        auto *useSound = child<QCheckBox>(dialog, "useSound");
        auto *replace = child<QCheckBox>(dialog, "replaceOverlap");
        QVERIFY(useSound->isEnabled()); // the clip has sound
        // Off, since the project has a sound; the user ticks it to have both.
        QVERIFY(!useSound->isChecked());
        QVERIFY(!replace->isVisible());
        clickBox(useSound);
        QVERIFY(useSound->isChecked());
        QVERIFY(!child<QLabel>(dialog, "soundNote")->isVisible());
        // It would play over the recording: the dialog says so, and replaces it only on request.
        QVERIFY(replace->isVisible());
        QVERIFY(!replace->isChecked());
        QVERIFY2(replace->text().contains(QStringLiteral("recording.wav")), qPrintable(replace->text()));
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        // Both recordings are on the track, the first as it was.
        const QVector<AudioClip> &clips = doc.timeline().audioClips();
        QCOMPARE(clips.size(), 2);
        QVERIFY(clips.contains(recording));
        QVERIFY(std::any_of(clips.begin(), clips.end(), [&](const AudioClip &c) { return c.path == m_talking; }));
    }

    // The clip's sound is on when the project has none, off (and the dialog says why) when it
    // has one: both would play at once.
    void soundDefaultsToOffWhenTheProjectHasOne_data()
    {
        QTest::addColumn<bool>("projectHasSound");
        QTest::newRow("no sound yet") << false;
        QTest::newRow("a recording") << true;
    }

    void soundDefaultsToOffWhenTheProjectHasOne()
    {
        QFETCH(bool, projectHasSound);
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        fillBusy(doc);
        if (projectHasSound) {
            Animation a = doc.animation();
            a.timeline.setAudioClips({AudioClip {m_dir.filePath(QStringLiteral("take one.wav")), 4.0, 2.0}});
            doc.changeAnimation(a, QStringLiteral("sound"));
        }
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(dialog.openClip(m_talking));
        auto *useSound = child<QCheckBox>(dialog, "useSound");
        auto *note = child<QLabel>(dialog, "soundNote");
        QVERIFY(useSound->isEnabled());
        QCOMPARE(useSound->isChecked(), !projectHasSound);
        QCOMPARE(note->isVisible(), projectHasSound);
        if (projectHasSound) {
            QVERIFY2(note->text().contains(QStringLiteral("take one.wav")), qPrintable(note->text()));
            clickBox(useSound); // the user's choice: the note has said its piece
            QVERIFY(!note->isVisible());
        }
    }

    void snappedMouthGivesMouthKeys()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(dialog.openClip(m_talking));
        clickBox(child<QRadioButton>(dialog, "snapMouth"));
        clickBox(child<QCheckBox>(dialog, "useSound")); // keep the project's sound
        QVERIFY(child<QRadioButton>(dialog, "snapMouth")->isChecked());
        QVERIFY(!child<QCheckBox>(dialog, "useSound")->isChecked());
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        const Timeline &t = doc.timeline();
        QVERIFY(!t.mouthKeys().isEmpty());
        // Shut before, open while the drawing's mouth is open.
        const auto shapeAt = [&](double time) {
            MouthShape shape = MouthShape::M;
            for (const MouthKey &k : t.mouthKeys()) {
                if (k.time <= time + 1e-9)
                    shape = k.shape;
            }
            return shape;
        };
        QCOMPARE(shapeAt(3 / kFps), MouthShape::M);
        QVERIFY(shapeAt(11 / kFps) != MouthShape::M);
        QVERIFY(t.audioClips().isEmpty()); // the sound was not taken, so the script's syllables stay
        QCOMPARE(doc.syllables(), busyAnimation().syllables);
        QVERIFY(t.video());
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void cancelChangesNothing()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(dialog.openClip(m_talking));
        QSignalSpy cancelled(&dialog, &ImportVideoDialog::cancelled);
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(click(&dialog, "cancel"));
        QVERIFY(QTest::qWaitFor([&] { return !cancelled.isEmpty() || !applied.isEmpty(); }, kTrackTimeoutMs));
        QCOMPARE(cancelled.size(), 1);
        QVERIFY(applied.isEmpty());
        QCOMPARE(doc.animation(), busyAnimation());
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(dialog.isVisible()); // still open, ready to try again
        QVERIFY(dialog.message().contains(QStringLiteral("nothing was changed")));
        QVERIFY(child<QPushButton>(dialog, "start")->isEnabled());
    }

    void unreadableFileSaysSoAndChangesNothing()
    {
        Document doc;
        fillBusy(doc);
        const QString broken = m_dir.filePath(QStringLiteral("broken.mp4"));
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(4096, 'x'));
        f.close();
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(!dialog.openClip(broken));
        QVERIFY2(dialog.message().contains(broken), qPrintable(dialog.message()));
        QVERIFY(!child<QPushButton>(dialog, "start")->isEnabled());
        // A sound file has no picture.
        const QString tone = writeTone(m_dir.filePath(QStringLiteral("tone.wav")), 0.5);
        QVERIFY(!tone.isEmpty());
        QVERIFY(!dialog.openClip(tone));
        QVERIFY2(dialog.message().contains(QStringLiteral("video")), qPrintable(dialog.message()));
        QVERIFY(!dialog.openClip(m_dir.filePath(QStringLiteral("missing.mp4"))));
        QVERIFY(dialog.message().contains(QStringLiteral("missing.mp4")));
        QCOMPARE(doc.animation(), busyAnimation());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    // An MP4 cut short whose frames are all past the cut: its header reads, but no frame
    // decodes; the view and the import say so, naming the file, and nothing changes.
    void truncatedMp4SaysSo()
    {
        if (m_talking.isEmpty())
            QSKIP("astronaut.png is not installed (package python3-skimage)");
        QFile whole(m_talking);
        QVERIFY(whole.open(QIODevice::ReadOnly));
        const QString cut = m_dir.filePath(QStringLiteral("cut.mp4"));
        QFile part(cut);
        QVERIFY(part.open(QIODevice::WriteOnly));
        part.write(whole.read(whole.size() * 6 / 10));
        part.close();
        QString error;
        const std::optional<MediaInfo> info = probeMedia(cut, &error);
        if (info && info->frameCount > 0)
            QSKIP("this encoder's MP4 keeps frames before the cut; the GRID row below covers that case");
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        if (dialog.openClip(cut))
            QVERIFY(QTest::qWaitFor([&] { return dialog.frameText().contains(cut); }, 20000));
        QVERIFY2(dialog.message().contains(cut) || dialog.frameText().contains(cut), qPrintable(dialog.message()));
        if (child<QPushButton>(dialog, "start")->isEnabled()) {
            QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
            QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
            QVERIFY(click(&dialog, "start"));
            QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
            QCOMPARE(failed.size(), 1);
            QVERIFY2(dialog.message().contains(cut), qPrintable(dialog.message()));
        }
        QCOMPARE(doc.animation(), busyAnimation());
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    // A clip cut short (a copy that stopped downloading) plays up to the cut: a neutral frame
    // past it says so in the view, and the import tracks the frames there are.
    void truncatedClipImportsWhatIsThere_data()
    {
        QTest::addColumn<QString>("clip");
        QTest::addColumn<int>("frames");
        QTest::newRow("GRID mpg") << QDir(dialogfixture::sharedData()).filePath(QStringLiteral("video/bbaf2n.mpg"))
                                  << 75;
    }

    void truncatedClipImportsWhatIsThere()
    {
        QFETCH(QString, clip);
        QFETCH(int, frames);
        if (clip.isEmpty() || !QFileInfo::exists(clip))
            QSKIP("the clip is absent (astronaut.png from python3-skimage, or the research data's GRID clip)");
        QFile whole(clip);
        QVERIFY(whole.open(QIODevice::ReadOnly));
        const QByteArray bytes = whole.readAll();
        const QString cut = m_dir.filePath(QStringLiteral("cut.") + QFileInfo(clip).suffix());
        QFile part(cut);
        QVERIFY(part.open(QIODevice::WriteOnly));
        part.write(bytes.left(bytes.size() * 6 / 10));
        part.close();
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY2(dialog.openClip(cut), qPrintable(dialog.message()));
        QString error;
        const std::optional<MediaInfo> info = probeMedia(cut, &error);
        QVERIFY2(info, qPrintable(error));
        QVERIFY2(info->frameCount > 0 && info->frameCount < frames, qPrintable(QString::number(info->frameCount)));
        auto *spin = child<QSpinBox>(dialog, "neutralFrame");
        if (spin->maximum() >= info->frameCount) {
            // The header promises more frames than there are: the view says which is missing.
            spin->setValue(spin->maximum());
            QVERIFY(QTest::qWaitFor(
                [&] { return dialog.shownFrame().isNull() && dialog.frameText().contains(cut); }, 20000));
        }
        spin->setValue(0);
        QVERIFY(waitForFrame(dialog, 0));
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY(doc.timeline().poseKeys().size() <= info->frameCount);
        QVERIFY(doc.timeline().poseKeys().size() >= info->frameCount - 3);
    }

    void noFaceOnTheNeutralFrameSaysSo()
    {
        Document doc;
        fillBusy(doc);
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QVERIFY(dialog.openClip(m_grey));
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QCOMPARE(failed.size(), 1);
        QVERIFY2(dialog.message().contains(m_grey), qPrintable(dialog.message()));
        QVERIFY(dialog.message().contains(QStringLiteral("Nothing was changed")));
        QCOMPARE(doc.animation(), busyAnimation());
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(dialog.isVisible());
    }

    // A GRID clip onto a project with no face yet: its neutral frame becomes the photo.
    void gridClipBecomesTheProject()
    {
        const QString grid = QDir(dialogfixture::sharedData()).filePath(QStringLiteral("video/bbaf2n.mpg"));
        if (!QFileInfo::exists(grid))
            QSKIP("the GRID clip video/bbaf2n.mpg of the research data is absent");
        // A copy, so that the neutral frame's PNG is written beside it and not into the data.
        const QString clip = m_dir.filePath(QStringLiteral("bbaf2n.mpg"));
        QVERIFY(QFile::copy(grid, clip));
        Document doc;
        QVERIFY(!doc.hasFace());
        ImportVideoDialog dialog(&doc, 0.0);
        dialog.show();
        QSignalSpy suggested(&dialog, &ImportVideoDialog::neutralSuggested);
        QVERIFY(dialog.openClip(clip));
        QVERIFY(child<QCheckBox>(dialog, "usePhoto")->isVisible());
        QVERIFY(child<QCheckBox>(dialog, "usePhoto")->isChecked());
        QVERIFY(child<QCheckBox>(dialog, "useSound")->isChecked());
        // The frame at rest it finds (in a silence: the lips closed) is the one shown.
        QVERIFY(suggested.wait(kTrackTimeoutMs));
        QCOMPARE(dialog.neutralFrame(), suggested.first().first().toInt());
        QVERIFY(waitForFrame(dialog, dialog.neutralFrame()));
        dialog.adjustSize();
        dialog.layout()->activate();
        QTest::qWait(50);
        dialogfixture::grab(&dialog, QStringLiteral("importvideo"));
        QSignalSpy applied(&dialog, &ImportVideoDialog::applied);
        QSignalSpy failed(&dialog, &ImportVideoDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(QTest::qWaitFor([&] { return !applied.isEmpty() || !failed.isEmpty(); }, kTrackTimeoutMs));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY(doc.hasFace());
        QVERIFY(QFileInfo::exists(doc.project().photoPath));
        QCOMPARE(QFileInfo(doc.project().photoPath).absolutePath(), QFileInfo(clip).absolutePath());
        QCOMPARE(doc.photo().size(), QSize(360, 288));
        const Timeline &t = doc.timeline();
        // 75 frames; a lost frame gives no key, but the speaker faces the camera throughout.
        QVERIFY2(t.poseKeys().size() >= 70, qPrintable(QString::number(t.poseKeys().size())));
        QCOMPARE(t.headKeys().size(), t.poseKeys().size());
        QCOMPARE(t.gazeKeys().size(), t.poseKeys().size());
        QVERIFY(!t.audioClips().isEmpty());
        QCOMPARE(t.audioClips().first().path, clip);
        QVERIFY(t.video());
        QCOMPARE(doc.undoStack()->count(), 1); // the import on the new project
        doc.undoStack()->undo();
        QCOMPARE(doc.animation(), Animation {});
    }
};

TOONFACE_TEST_MAIN(TestImportVideo)
#include "tst_importvideo.moc"
