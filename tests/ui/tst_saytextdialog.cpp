#include "dialogfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "dialogs/languagebox.h"
#include "dialogs/saytextdialog.h"
#include "dialogs/secondsbox.h"
#include "document/document.h"
#include "speech/tts.h"
#include "timeline/audioclipedits.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>

using namespace toonface;
using namespace toonface::dialogfixture;

namespace {

constexpr int kSpeakTimeoutMs = 60000;

void type(SayTextDialog &dialog, const QString &text)
{
    auto *box = dialog.findChild<QPlainTextEdit *>(QStringLiteral("text"));
    box->clear();
    box->insertPlainText(text);
}

} // namespace

class TestSayTextDialog : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void speaksBesideTheProjectWithExactTimings()
    {
        Document doc;
        fixture::fill(doc);
        QString error;
        const QString project = m_dir.filePath(QStringLiteral("saved/hello.toonface"));
        QVERIFY(QDir().mkpath(QFileInfo(project).absolutePath()));
        QVERIFY2(doc.save(project, &error), qPrintable(error));
        doc.undoStack()->clear();
        Animation busy;
        busy.timeline.addMouthKey({50.0, MouthShape::O, 1.0, 0.2});
        doc.changeAnimation(busy, QStringLiteral("setup"));
        doc.undoStack()->clear();
        const Animation before = doc.animation();

        SayTextDialog dialog(&doc);
        dialog.show();
        QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("soundNote"))->text().contains(QStringLiteral("project")));
        const QString text = QStringLiteral("你好，世界");
        type(dialog, text);
        grab(&dialog, QStringLiteral("saytext"));
        const QString wav = dialog.soundPath();
        QCOMPARE(QFileInfo(wav).absolutePath(), QFileInfo(project).absolutePath());
        QCOMPARE(QFileInfo(wav).suffix(), QStringLiteral("wav"));
        QVERIFY(!QFileInfo::exists(wav));

        QSignalSpy applied(&dialog, &SayTextDialog::applied);
        QSignalSpy failed(&dialog, &SayTextDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY2(applied.wait(kSpeakTimeoutMs) || !failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));

        // The sound is written beside the project and is the timeline's sound.
        QVERIFY(QFileInfo::exists(wav));
        const AudioResult sound = loadAudio(wav);
        QVERIFY2(sound.ok(), qPrintable(sound.error));
        QVERIFY(!doc.timeline().audioClips().isEmpty());
        QCOMPARE(doc.timeline().audioClips().first().path, wav);
        QVERIFY(std::abs(doc.timeline().audioClips().first().duration - sound.sourceDuration) < 0.05);

        // The syllables carry the synthesizer's own timings.
        const Script script = parseScript(text).script;
        const LipsyncResult expected = lipsyncResult(script, synthesize(script));
        QCOMPARE(doc.syllables().size(), expected.syllables.size());
        for (int i = 0; i < expected.syllables.size(); ++i) {
            QCOMPARE(doc.syllables()[i].text, expected.syllables[i].text);
            QVERIFY(std::abs(doc.syllables()[i].start - expected.syllables[i].start) < 1e-6);
            QVERIFY(std::abs(doc.syllables()[i].end - expected.syllables[i].end) < 1e-6);
        }
        QVERIFY(doc.timeline().mouthKeys().size() > expected.syllables.size());
        QVERIFY(doc.timeline().mouthKeys().contains(before.timeline.mouthKeys().first())); // past the speech
        QCOMPARE(doc.timeline().audioClips().first().script, text);
        QCOMPARE(doc.timeline().audioClips().first().language, QStringLiteral("cmn"));

        // One step; undo gives back the exact previous animation.
        QCOMPARE(doc.undoStack()->count(), 1);
        doc.undoStack()->undo();
        QVERIFY(doc.animation() == before);
    }

    // Issue 26: a second recording is a second clip; the first stays unless the user asks.
    void secondRecordingKeepsTheFirst()
    {
        Document doc;
        fixture::fill(doc);
        const QString recording = writeTone(m_dir.filePath(QStringLiteral("recording.wav")), 6.0);
        QVERIFY(!recording.isEmpty());
        Animation a = doc.animation();
        AudioClip first {recording, 0, 6.0};
        first.script = QStringLiteral("你好");
        first.language = QStringLiteral("cmn");
        a.timeline.setAudioClips({first});
        a.syllables = {{QStringLiteral("你"), QStringLiteral("ni"), 3, 1.0, 1.3, 1.0, {{MouthShape::I, 1.0}}}};
        doc.changeAnimation(a, QStringLiteral("setup"));
        doc.undoStack()->clear();

        // Wanted at the playhead (2 s), inside the recording: placed after it.
        SayTextDialog dialog(&doc, nullptr, 2.0);
        dialog.show();
        QCOMPARE(dialog.findChild<SecondsBox *>(QStringLiteral("offset"))->value(), 2.0);
        // The language is read from the new text, not taken from the last script's.
        QCOMPARE(dialog.findChild<LanguageBox *>(QStringLiteral("language"))->language(), Language::Auto);
        type(dialog, QStringLiteral("Hello there"));
        auto *overlap = dialog.findChild<QComboBox *>(QStringLiteral("overlap"));
        QVERIFY(overlap);
        QCOMPARE(ClipOverlap(overlap->currentData().toInt()), ClipOverlap::PlaceAfter);
        QSignalSpy applied(&dialog, &SayTextDialog::applied);
        QSignalSpy failed(&dialog, &SayTextDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY2(applied.wait(kSpeakTimeoutMs) || !failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        const QVector<AudioClip> clips = doc.timeline().audioClips();
        QCOMPARE(clips.size(), 2);
        QCOMPARE(clips[0], first);
        QCOMPARE(clips[1].path, dialog.soundPath());
        QCOMPARE(clips[1].offset, 6.0);
        QCOMPARE(clips[1].language, QStringLiteral("en"));
        QCOMPARE(clips[1].script, QStringLiteral("Hello there"));
        QCOMPARE(doc.syllables().first(), a.syllables.first()); // the first clip's syllable stays
        QVERIFY(doc.syllables().last().start >= 6.0);
        QVERIFY2(dialog.outcome().contains(QStringLiteral("recording.wav")), qPrintable(dialog.outcome()));

        // On request, the new one replaces what it plays over, with its syllables.
        SayTextDialog again(&doc, nullptr, 0.5);
        again.show();
        type(again, QStringLiteral("Hi"));
        auto *replace = again.findChild<QComboBox *>(QStringLiteral("overlap"));
        replace->setCurrentIndex(replace->findData(int(ClipOverlap::Replace)));
        QSignalSpy appliedAgain(&again, &SayTextDialog::applied);
        QVERIFY(click(&again, "start"));
        QVERIFY2(appliedAgain.wait(kSpeakTimeoutMs), qPrintable(again.message()));
        const QVector<AudioClip> after = doc.timeline().audioClips();
        QCOMPARE(after.size(), 2);
        QCOMPARE(after[0].offset, 0.5);
        QCOMPARE(after[1], clips[1]);
        QVERIFY(std::none_of(after.begin(), after.end(), [&](const AudioClip &c) { return c.path == recording; }));
        QVERIFY(!doc.syllables().contains(a.syllables.first()));
    }

    void unsavedProjectSpeaksBesideThePhoto()
    {
        const QString photoDir = m_dir.filePath(QStringLiteral("photos"));
        QVERIFY(QDir().mkpath(photoDir));
        const QString photo = QDir(photoDir).filePath(QStringLiteral("portrait.png"));
        QVERIFY(fixture::photo().save(photo));
        Document doc;
        fixture::fill(doc, photo);
        const QString path = SayTextDialog::defaultSoundPath(doc);
        QCOMPARE(path, QDir(photoDir).filePath(QStringLiteral("portrait-speech.wav")));
        // A name already taken is not overwritten.
        QFile taken(path);
        QVERIFY(taken.open(QIODevice::WriteOnly));
        taken.close();
        QCOMPARE(
            SayTextDialog::defaultSoundPath(doc), QDir(photoDir).filePath(QStringLiteral("portrait-speech-2.wav")));
        SayTextDialog dialog(&doc);
        QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("soundNote"))->text().contains(QStringLiteral("photo")));
        QCOMPARE(dialog.soundPath(), QDir(photoDir).filePath(QStringLiteral("portrait-speech-2.wav")));
    }

    void cancelLeavesNoFileAndNoChange()
    {
        Document doc;
        fixture::fill(doc);
        const Animation before = doc.animation();
        SayTextDialog dialog(&doc);
        dialog.show();
        auto *path = dialog.findChild<QLineEdit *>(QStringLiteral("soundPath"));
        const QString wav = m_dir.filePath(QStringLiteral("cancelled.wav"));
        path->setText(wav);
        QString text;
        for (int i = 0; i < 8; ++i)
            text += QStringLiteral("今天天气很好，我们去公园散步吧。");
        type(dialog, text);
        QSignalSpy cancelled(&dialog, &SayTextDialog::cancelled);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(click(&dialog, "cancel"));
        QVERIFY(cancelled.wait(kSpeakTimeoutMs));
        QVERIFY(!QFileInfo::exists(wav));
        QVERIFY(doc.animation() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(dialog.isVisible());
    }

    void unspeakableTextIsSaid()
    {
        Document doc;
        fixture::fill(doc);
        SayTextDialog dialog(&doc);
        dialog.show();
        dialog.findChild<QLineEdit *>(QStringLiteral("soundPath"))->setText(m_dir.filePath(QStringLiteral("x.wav")));
        type(dialog, QStringLiteral("你好 ⓧ"));
        QSignalSpy failed(&dialog, &SayTextDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QCOMPARE(failed.size(), 1);
        QVERIFY2(dialog.message().contains(QStringLiteral("column")), qPrintable(dialog.message()));
        QCOMPARE(doc.undoStack()->count(), 0);
    }
};

TOONFACE_TEST_MAIN(TestSayTextDialog)
#include "tst_saytextdialog.moc"
