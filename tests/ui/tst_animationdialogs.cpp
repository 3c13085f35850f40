#include "dialogfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "dialogs/animationedits.h"
#include "dialogs/blinksdialog.h"
#include "dialogs/emotiondialog.h"
#include "dialogs/posepreview.h"
#include "document/document.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

using namespace toonface;
using namespace toonface::dialogfixture;

namespace {

// A lip-sync result of two syllables over one second.
LipsyncResult twoSyllables()
{
    LipsyncResult r;
    r.duration = 1.0;
    r.syllables.append({QStringLiteral("你"), QStringLiteral("ni"), 3, 0.1, 0.4, 0.9, {{MouthShape::I, 0.1}}});
    r.syllables.append(
        {QStringLiteral("好"), QStringLiteral("hao"), 3, 0.5, 0.9, 0.8, {{MouthShape::A, 0.5}, {MouthShape::U, 0.82}}});
    r.mouthCues = mouthCues(r.syllables, r.duration);
    return r;
}

Animation withTalk()
{
    Animation a;
    a.timeline.addMouthKey({0.5, MouthShape::E, 1.0, 0.1}); // before the new range
    a.timeline.addMouthKey({2.5, MouthShape::O, 1.0, 0.1}); // inside the new range
    a.timeline.addMouthKey({4.0, MouthShape::F, 1.0, 0.1}); // after it
    a.syllables.append({QStringLiteral("一"), QStringLiteral("yi"), 1, 0.4, 0.6, 1, {{MouthShape::I, 0.4}}});
    a.syllables.append({QStringLiteral("二"), QStringLiteral("er"), 4, 2.4, 2.7, 1, {{MouthShape::E, 2.4}}});
    a.syllables.append({QStringLiteral("三"), QStringLiteral("san"), 1, 4.0, 4.3, 1, {{MouthShape::A, 4.0}}});
    return a;
}

} // namespace

class TestAnimationDialogs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void speechReplacesOnlyItsRange()
    {
        const Animation before = withTalk();
        const Animation after = *withSpeech(
            before, twoSyllables(), SpeechPlacement {QStringLiteral("/tmp/a.wav"), 2.0, QStringLiteral("你好")});
        // Keys: the one at 0.5 and at 4.0 kept, the one at 2.5 replaced by the result's, moved by 2 s.
        const QVector<MouthKey> &keys = after.timeline.mouthKeys();
        QVERIFY(keys.contains(before.timeline.mouthKeys()[0]));
        QVERIFY(keys.contains(before.timeline.mouthKeys()[2]));
        QVERIFY(!keys.contains(before.timeline.mouthKeys()[1]));
        for (const MouthCue &cue : twoSyllables().mouthCues) {
            bool found = false;
            for (const MouthKey &k : keys)
                found |= std::abs(k.time - (cue.start + 2.0)) < 1e-9 && k.shape == cue.shape;
            QVERIFY2(found, qPrintable(QStringLiteral("cue at %1").arg(cue.start)));
        }
        // Syllables: 一 and 三 kept, 二 replaced by 你 好 at their times + 2 s, in order.
        QStringList texts;
        for (const LipsyncSyllable &s : after.syllables)
            texts << s.text;
        QCOMPARE(texts,
            (QStringList {QStringLiteral("一"), QStringLiteral("你"), QStringLiteral("好"), QStringLiteral("三")}));
        QCOMPARE(after.syllables[2].start, 2.5);
        QCOMPARE(after.syllables[2].shapes[1].start, 2.82);
        AudioClip clip {QStringLiteral("/tmp/a.wav"), 2.0, 1.0};
        clip.script = QStringLiteral("你好");
        clip.language = QStringLiteral("cmn");
        QCOMPARE(after.timeline.audioClips(), QVector<AudioClip> {clip});
    }

    // Issue 26: a new recording is a new clip; one it would play over is kept (it goes after
    // it) unless replacing is asked for; the same recording again replaces itself.
    void speechIsPlacedBesideOtherClips()
    {
        Animation before = withTalk();
        AudioClip first {QStringLiteral("/tmp/first.wav"), 2.0, 1.5}; // owns 二 and the key at 2.5
        first.script = QStringLiteral("二");
        before.timeline.setAudioClips({first});
        const SpeechPlacement wanted {QStringLiteral("/tmp/new.wav"), 2.2, QStringLiteral("你好")};

        ClipPlace placed;
        const Animation after = *withSpeech(before, twoSyllables(), wanted, &placed);
        QCOMPARE(placed.start, 3.5); // after the first clip
        QCOMPARE(placed.overlapped, QVector<int> {0});
        QVERIFY(placed.replaced.isEmpty());
        QCOMPARE(after.timeline.audioClips().size(), 2);
        QCOMPARE(after.timeline.audioClips()[0], first);
        QCOMPARE(after.timeline.audioClips()[1].offset, 3.5);
        QVERIFY(after.syllables.contains(before.syllables[1])); // 二 kept
        QVERIFY(after.timeline.mouthKeys().contains(before.timeline.mouthKeys()[1]));
        QVERIFY(placementNote(before.timeline, placed, wanted.offset).contains(QStringLiteral("first.wav")));

        SpeechPlacement replace = wanted;
        replace.overlap = ClipOverlap::Replace;
        const Animation replaced = *withSpeech(before, twoSyllables(), replace, &placed);
        QCOMPARE(placed.start, 2.2);
        QCOMPARE(placed.replaced, QVector<int> {0});
        QCOMPARE(replaced.timeline.audioClips().size(), 1);
        QCOMPARE(replaced.timeline.audioClips()[0].path, QStringLiteral("/tmp/new.wav"));
        QVERIFY(!replaced.syllables.contains(before.syllables[1])); // 二 went with its clip
        QVERIFY(replaced.syllables.contains(before.syllables[2])); // 三 (no clip) stays

        // Lip-syncing the first recording again at its place replaces it, whatever the choice.
        const Animation again
            = *withSpeech(before, twoSyllables(), SpeechPlacement {first.path, first.offset, QStringLiteral("你好")});
        QCOMPARE(again.timeline.audioClips().size(), 1);
        QCOMPARE(again.timeline.audioClips()[0].script, QStringLiteral("你好"));

        // Nothing past the timeline's four hours.
        QVERIFY(
            !withSpeech(before, twoSyllables(), SpeechPlacement {wanted.audioPath, Timeline::kMaxSeconds - 0.5, {}}));
    }

    void emotionGivesWay()
    {
        Animation before;
        before.timeline.addEmotionClip({0.0, 10.0, Emotion::Sad, 1.0, 0.5, 0.5}); // holds the new one
        before.timeline.addEmotionClip({11.0, 12.0, Emotion::Angry, 1.0, 0.3, 0.3}); // apart
        const EmotionClip smile {4.0, 6.0, Emotion::Smile, 0.8, 0.2, 0.2};
        const Animation after = withEmotion(before, smile, true);
        const QVector<EmotionClip> &clips = after.timeline.emotionClips();
        QCOMPARE(clips.size(), 4);
        QCOMPARE(clips[0].start, 0.0);
        QCOMPARE(clips[0].end, 4.0);
        QCOMPARE(clips[0].emotion, Emotion::Sad);
        QCOMPARE(clips[1], smile);
        QCOMPARE(clips[2].start, 6.0);
        QCOMPARE(clips[2].end, 10.0);
        QCOMPARE(clips[3], before.timeline.emotionClips()[1]);
        // Without replacing, the clips add up.
        QCOMPARE(withEmotion(before, smile, false).timeline.emotionClips().size(), 3);
    }

    void blinksInARangeKeepTheOthers()
    {
        Animation before;
        before.timeline.addBlink({1.0, 0.2});
        before.timeline.addBlink({5.0, 0.2});
        before.timeline.addBlink({30.0, 0.2});
        const Animation after = withBlinks(before, 7, 2.0, 20.0);
        QVector<BlinkEvent> expected = {before.timeline.blinks()[0], before.timeline.blinks()[2]};
        for (BlinkEvent b : Timeline::randomBlinks(7, 18.0)) {
            b.time += 2.0;
            expected.append(b);
        }
        std::sort(expected.begin(), expected.end(), [](auto &a, auto &b) { return a.time < b.time; });
        QCOMPARE(after.timeline.blinks(), expected);
    }

    void blinksDialogAddsOneStep()
    {
        Document doc;
        fixture::fill(doc);
        Animation a;
        a.timeline.setAudioClips({AudioClip {QStringLiteral("/tmp/x.wav"), 0, 12.0}});
        a.timeline.addBlink({3.0, 0.2});
        doc.changeAnimation(a, QStringLiteral("setup"));
        doc.undoStack()->clear();
        const Animation before = doc.animation();

        BlinksDialog dialog(&doc);
        dialog.show();
        QVERIFY(dialog.findChild<QRadioButton *>(QStringLiteral("whole"))->isChecked());
        auto *seed = dialog.findChild<QSpinBox *>(QStringLiteral("seed"));
        seed->selectAll();
        QTest::keyClicks(seed, QStringLiteral("42"));
        QCOMPARE(dialog.seed(), 42u);
        grab(&dialog, QStringLiteral("blinks"));
        QVERIFY(click(&dialog, "ok"));
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(doc.timeline().blinks(), Timeline::randomBlinks(42, 12.0));
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QVERIFY(doc.animation() == before);

        // A new seed gives other blinks; a range keeps the blinks outside it.
        BlinksDialog ranged(&doc);
        ranged.setSeed(5);
        ranged.setRange(5.0, 12.0);
        ranged.accept();
        QVERIFY(doc.timeline().blinks().contains(before.timeline.blinks().first()));
        QCOMPARE(doc.animation(), withBlinks(before, 5, 5.0, 12.0));
    }

    // The blinks' pattern is a number the user may type or shuffle; the dialog does not speak of
    // the random generator's "seed".
    void blinksDialogSpeaksOfAPattern()
    {
        Document doc;
        fixture::fill(doc);
        BlinksDialog dialog(&doc);
        QStringList texts;
        for (const QLabel *label : dialog.findChildren<QLabel *>())
            texts << label->text();
        for (const QAbstractButton *button : dialog.findChildren<QAbstractButton *>())
            texts << button->text() << button->toolTip();
        QVERIFY(texts.size() > 4);
        for (const QString &text : std::as_const(texts))
            QVERIFY2(!text.contains(QStringLiteral("seed"), Qt::CaseInsensitive), qPrintable(text));
    }

    void emotionDialogAddsOneStepWithItsPreview()
    {
        Document doc;
        fixture::fill(doc);
        Animation a;
        a.timeline.addEmotionClip({0.0, 8.0, Emotion::Sad, 1.0, 0.3, 0.3});
        a.timeline.setAudioClips({AudioClip {QStringLiteral("/tmp/x.wav"), 0, 8.0}});
        doc.changeAnimation(a, QStringLiteral("setup"));
        doc.undoStack()->clear();
        const Animation before = doc.animation();

        EmotionDialog dialog(&doc);
        dialog.resize(dialog.sizeHint());
        dialog.show();
        auto *preview = dialog.findChild<PosePreview *>(QStringLiteral("preview"));
        auto *emotion = dialog.findChild<QComboBox *>(QStringLiteral("emotion"));
        emotion->setCurrentIndex(emotion->findData(int(Emotion::Neutral)));
        const QImage neutral = preview->image();
        emotion->setCurrentIndex(emotion->findData(int(Emotion::Surprise)));
        QVERIFY(preview->image() != neutral); // the preview wears the emotion
        auto *slider = dialog.findChild<QSlider *>(QStringLiteral("intensity"));
        auto *percent = dialog.findChild<QSpinBox *>(QStringLiteral("intensityValue"));
        QCOMPARE(percent->value(), slider->value()); // the two show one value from the start
        slider->setValue(50);
        QCOMPARE(percent->value(), 50);
        auto *start = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("start"));
        auto *end = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("end"));
        start->setValue(2.0);
        end->setValue(5.0);
        grab(&dialog, QStringLiteral("emotion"));
        QVERIFY(click(&dialog, "ok"));
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        const EmotionClip added = dialog.clip();
        QCOMPARE(added.emotion, Emotion::Surprise);
        QCOMPARE(added.intensity, 0.5);
        QVERIFY(doc.timeline().emotionClips().contains(added));
        QCOMPARE(doc.timeline().emotionClips().size(), 3); // the sad clip cut in two around it
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QVERIFY(doc.animation() == before);

        // A range that ends before it starts is refused.
        EmotionDialog bad(&doc);
        EmotionClip c = bad.clip();
        c.start = 3;
        c.end = 1;
        bad.setClip(c);
        bad.accept();
        QVERIFY(bad.result() != QDialog::Accepted);
        QCOMPARE(doc.undoStack()->count(), 1);
    }
};

TOONFACE_TEST_MAIN(TestAnimationDialogs)
#include "tst_animationdialogs.moc"
