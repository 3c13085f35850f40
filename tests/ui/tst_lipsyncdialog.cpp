#include "dialogfixture.h"
#include "testmain.h"
#include "uifixture.h"

#include "dialogs/lipsyncdialog.h"
#include "document/document.h"
#include "i18n/translations.h"
#include "speech/tts.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace toonface;
using namespace toonface::dialogfixture;

namespace {

constexpr int kAlignTimeoutMs = 180000;

// An animation with something on every kind of track, some of it far past any recording
// used here, so that a test can tell what a lip sync keeps.
Animation busyAnimation()
{
    Animation a;
    a.timeline.addMouthKey({0.5, MouthShape::A, 1.0, 0.2});
    a.timeline.addMouthKey({100.0, MouthShape::O, 0.7, 0.3});
    a.timeline.addEmotionClip({0.0, 3.0, Emotion::Smile, 0.8, 0.3, 0.3});
    a.timeline.addBlink({1.0, 0.18});
    a.syllables.append({QStringLiteral("好"), QStringLiteral("hao"), 3, 1.0, 1.3, 1.0, {{MouthShape::A, 1.0}}});
    a.syllables.append({QStringLiteral("远"), QStringLiteral("yuan"), 3, 100.0, 100.3, 1.0, {{MouthShape::U, 100.0}}});
    return a;
}

void fillBusy(Document &doc)
{
    fixture::fill(doc);
    doc.changeAnimation(busyAnimation(), QStringLiteral("setup"));
    doc.undoStack()->clear();
}

// Fills in the dialog as a user would.
void fillIn(LipSyncDialog &dialog, const QString &recording, const QString &script)
{
    auto *path = dialog.findChild<QLineEdit *>(QStringLiteral("recording"));
    path->clear();
    QTest::keyClicks(path, recording);
    QVERIFY(typeScript(&dialog, script));
}

} // namespace

class TestLipSyncDialog : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    // A Mandarin recording made by the built-in voice in another voice than the aligner's.
    QString spokenRecording(const QString &text, const QString &name)
    {
        TtsOptions o;
        o.voice = QStringLiteral("cmn-latn-pinyin+f2");
        o.rate = 150;
        const TtsResult r = synthesize(parseScript(text).script, o);
        if (!r.ok())
            return QString();
        Audio a = resampled(r.audio, kSpeechSampleRate);
        a.samples = QVector<float>(8000, 0.0f) + a.samples + QVector<float>(8000, 0.0f);
        QString error;
        const QString path = m_dir.filePath(name);
        return writeAudio(path, a, &error) ? path : QString();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // As the editor starts: English with its plural forms ("4 syllables").
        QVERIFY(installTranslations(QCoreApplication::instance(), QString()));
    }

    void realRecordingEndsWithKeysAndSyllablesAsOneStep()
    {
        const QString wav = realRecording();
        if (wav.isEmpty())
            QSKIP("the research recording speech/SSB00050015_16k.wav is absent");
        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();

        LipSyncDialog dialog(&doc);
        dialog.show();
        fillIn(dialog, wav, kRealScript);
        QSignalSpy applied(&dialog, &LipSyncDialog::applied);
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(dialog.isRunning());
        // While it runs the inputs are locked and the progress bar shows.
        QVERIFY(!dialog.findChild<QLineEdit *>(QStringLiteral("recording"))->isEnabled());
        QVERIFY(dialog.findChild<QWidget *>(QStringLiteral("progress"))->isVisible());
        grab(&dialog, QStringLiteral("lipsync-running"));
        QVERIFY2(applied.wait(kAlignTimeoutMs) || !failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        QCOMPARE(dialog.result(), int(QDialog::Accepted));

        // Keys and syllables on the timeline, the recording as its sound.
        const QVector<LipsyncSyllable> &syllables = doc.syllables();
        QString spoken;
        for (const LipsyncSyllable &s : syllables)
            if (s.start < 50)
                spoken += s.text;
        QCOMPARE(spoken, kRealScript);
        QVERIFY(!doc.timeline().audioClips().isEmpty());
        QCOMPARE(doc.timeline().audioClips().first().path, wav);
        const double duration = doc.timeline().audioClips().first().duration;
        QVERIFY(duration > 2.0 && duration < 10.0);
        QCOMPARE(doc.timeline().audioClips().first().script, kRealScript);
        QCOMPARE(doc.timeline().audioClips().first().language, QStringLiteral("cmn"));
        int keysInRange = 0;
        for (const MouthKey &k : doc.timeline().mouthKeys())
            keysInRange += k.time <= duration;
        QVERIFY(keysInRange >= syllables.size() - 1);
        // The old key and syllable inside the recording's range are replaced, those past it kept.
        QVERIFY(!doc.timeline().mouthKeys().contains(before.timeline.mouthKeys().first()));
        QVERIFY(doc.timeline().mouthKeys().contains(before.timeline.mouthKeys().last()));
        QVERIFY(!syllables.contains(before.syllables.first()));
        QCOMPARE(syllables.last(), before.syllables.last());
        // Other tracks untouched.
        QCOMPARE(doc.timeline().emotionClips(), before.timeline.emotionClips());
        QCOMPARE(doc.timeline().blinks(), before.timeline.blinks());
        // The syllables are in time order and inside the recording.
        for (int i = 1; i < syllables.size(); ++i)
            QVERIFY(syllables[i - 1].start <= syllables[i].start);

        // One undo step, which restores the exact previous animation; redo brings it back.
        QCOMPARE(doc.undoStack()->count(), 1);
        const Animation after = doc.animation();
        doc.undoStack()->undo();
        QVERIFY(doc.animation() == before);
        doc.undoStack()->redo();
        QVERIFY(doc.animation() == after);
    }

    void videoSoundInEnglish()
    {
        const QString video = QDir(sharedData()).filePath(QStringLiteral("video/id2_vcd_swwp2s.mpg"));
        if (!QFileInfo::exists(video))
            QSKIP("the research video video/id2_vcd_swwp2s.mpg is absent");
        Document doc;
        fixture::fill(doc);
        LipSyncDialog dialog(&doc);
        dialog.show();
        fillIn(dialog, QFileInfo(video).absoluteFilePath(), QStringLiteral("set white with p two soon"));
        QSignalSpy applied(&dialog, &LipSyncDialog::applied);
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY2(applied.wait(kAlignTimeoutMs) || !failed.isEmpty(), qPrintable(dialog.message()));
        QVERIFY2(failed.isEmpty(), qPrintable(dialog.message()));
        QCOMPARE(doc.syllables().size(), 6);
        QCOMPARE(doc.syllables().first().text, QStringLiteral("set"));
        QCOMPARE(doc.timeline().audioClips().first().language, QStringLiteral("en"));
        QCOMPARE(doc.timeline().audioClips().first().path, QFileInfo(video).absoluteFilePath());
        QVERIFY(std::abs(doc.timeline().audioClips().first().duration - 3.0) < 0.2);
        QVERIFY(!doc.timeline().mouthKeys().isEmpty());
    }

    void startsWithTheClipUnderThePlayhead()
    {
        Document doc;
        fillBusy(doc);
        Animation a = doc.animation();
        AudioClip clip {m_dir.filePath(QStringLiteral("x.wav")), 1.5, 3.0};
        clip.script = QStringLiteral("你好");
        clip.language = QStringLiteral("cmn");
        a.timeline.setAudioClips({clip});
        doc.changeAnimation(a, QStringLiteral("setup"));
        // On the clip: its recording, script and place, to lip-sync it again.
        LipSyncDialog dialog(&doc, nullptr, 2.0);
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("recording"))->text(), clip.path);
        QCOMPARE(dialog.findChild<QPlainTextEdit *>(QStringLiteral("script"))->toPlainText(), clip.script);
        QCOMPARE(dialog.findChild<QDoubleSpinBox *>(QStringLiteral("offset"))->value(), 1.5);
        // Elsewhere: a new recording at the playhead.
        LipSyncDialog elsewhere(&doc, nullptr, 7.0);
        QVERIFY(elsewhere.findChild<QLineEdit *>(QStringLiteral("recording"))->text().isEmpty());
        QCOMPARE(elsewhere.findChild<QDoubleSpinBox *>(QStringLiteral("offset"))->value(), 7.0);
        QVERIFY(elsewhere.findChild<QComboBox *>(QStringLiteral("overlap")));
    }

    void cancelLeavesTheProjectUnchanged()
    {
        const QString text = QStringLiteral("今天天气很好，我们去公园散步吧。");
        const QString wav = spokenRecording(text, QStringLiteral("cancel.wav"));
        QVERIFY(!wav.isEmpty());
        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();
        LipSyncDialog dialog(&doc);
        dialog.show();
        fillIn(dialog, wav, text);
        QSignalSpy cancelled(&dialog, &LipSyncDialog::cancelled);
        QSignalSpy applied(&dialog, &LipSyncDialog::applied);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(dialog.isRunning());
        QVERIFY(click(&dialog, "cancel")); // Cancel while running stops the work, not the dialog
        QVERIFY(cancelled.wait(kAlignTimeoutMs));
        QVERIFY(applied.isEmpty());
        QVERIFY(!dialog.isRunning());
        QVERIFY(dialog.isVisible());
        QVERIFY(dialog.message().contains(QStringLiteral("nothing was changed")));
        QVERIFY(doc.animation() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
        // The inputs work again, and Cancel now closes the dialog.
        QVERIFY(dialog.findChild<QLineEdit *>(QStringLiteral("recording"))->isEnabled());
        QVERIFY(click(&dialog, "cancel"));
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        QVERIFY(!dialog.isVisible());
    }

    void scriptThatCannotFitSaysSoAndChangesNothing()
    {
        const QString tone = writeTone(m_dir.filePath(QStringLiteral("tone.wav")), 0.5);
        QVERIFY(!tone.isEmpty());
        QString longScript;
        for (int i = 0; i < 6; ++i)
            longScript += QStringLiteral("我们明天早上八点在学校门口见面。");
        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();
        LipSyncDialog dialog(&doc);
        dialog.show();
        fillIn(dialog, tone, longScript);
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(failed.wait(kAlignTimeoutMs));
        grab(&dialog, QStringLiteral("lipsync-cannot-fit"));
        // The aligner's own words, naming the recording, and that nothing changed.
        QVERIFY2(dialog.message().contains(QStringLiteral("could not be aligned")), qPrintable(dialog.message()));
        QVERIFY(dialog.message().contains(tone));
        QVERIFY(dialog.message().contains(QStringLiteral("Nothing was changed")));
        QCOMPARE(failed.first().first().toString(), dialog.message());
        QVERIFY(dialog.isVisible());
        QVERIFY(doc.animation() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void unreadableRecordingIsNamed()
    {
        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();
        LipSyncDialog dialog(&doc);
        dialog.show();
        const QString missing = m_dir.filePath(QStringLiteral("missing.wav"));
        fillIn(dialog, missing, QStringLiteral("你好"));
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(failed.wait(kAlignTimeoutMs));
        QVERIFY2(dialog.message().contains(missing), qPrintable(dialog.message()));
        QVERIFY(doc.animation() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void recordingCutShortIsNamed()
    {
        // A 6 s recording copied only in part: its header still promises 6 s.
        const QString whole
            = spokenRecording(QStringLiteral("我们明天早上八点在学校门口见面"), QStringLiteral("whole.wav"));
        QVERIFY(!whole.isEmpty());
        const QString cut = m_dir.filePath(QStringLiteral("cut.wav"));
        QFile in(whole);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray bytes = in.readAll();
        const qsizetype header = bytes.indexOf("data") + 8;
        const double promised = double(bytes.size() - header) / (kSpeechSampleRate * 2);
        const qsizetype kept = header + qsizetype(0.6 * double(bytes.size() - header)) / 2 * 2;
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(kept));
        out.close();

        Document doc;
        fillBusy(doc);
        const Animation before = doc.animation();
        LipSyncDialog dialog(&doc);
        dialog.show();
        fillIn(dialog, cut, QStringLiteral("我们明天早上八点在学校门口见面"));
        QSignalSpy failed(&dialog, &LipSyncDialog::failed);
        QVERIFY(click(&dialog, "start"));
        QVERIFY(failed.wait(kAlignTimeoutMs));
        grab(&dialog, QStringLiteral("lipsync-cut-short"));
        const QString expected = QStringLiteral("cut short (its header promises %1 s, it holds %2 s)")
                                     .arg(promised, 0, 'f', 2)
                                     .arg(double(kept - header) / (kSpeechSampleRate * 2), 0, 'f', 2);
        QVERIFY2(dialog.message().contains(cut), qPrintable(dialog.message()));
        QVERIFY2(dialog.message().contains(expected), qPrintable(dialog.message() + QStringLiteral(" / ") + expected));
        QVERIFY(doc.animation() == before);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void scriptIsCheckedAsItIsTyped()
    {
        Document doc;
        fixture::fill(doc);
        LipSyncDialog dialog(&doc);
        dialog.show();
        auto *state = dialog.findChild<QLabel *>(QStringLiteral("scriptState"));
        auto *start = dialog.findChild<QPushButton *>(QStringLiteral("start"));
        fillIn(dialog, m_dir.filePath(QStringLiteral("any.wav")), QStringLiteral("你好世界"));
        QVERIFY2(state->text().contains(QStringLiteral("4 syllables")), qPrintable(state->text()));
        QVERIFY(start->isEnabled());
        fillIn(dialog, m_dir.filePath(QStringLiteral("any.wav")), QStringLiteral("你好 ⓧ"));
        QVERIFY2(state->text().contains(QStringLiteral("column")), qPrintable(state->text()));
        QVERIFY(!start->isEnabled());
        // No recording: nothing to start.
        fillIn(dialog, QString(), QStringLiteral("你好"));
        QVERIFY(!start->isEnabled());
    }

    void scriptOpensFromAFile()
    {
        Document doc;
        fixture::fill(doc);
        LipSyncDialog dialog(&doc);
        const QString path = m_dir.filePath(QStringLiteral("script.txt"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kRealScript.toUtf8() + "\n");
        file.close();
        QVERIFY(dialog.openScript(path));
        QCOMPARE(dialog.findChild<QPlainTextEdit *>(QStringLiteral("script"))->toPlainText(), kRealScript);
        const QString missing = m_dir.filePath(QStringLiteral("none.txt"));
        QVERIFY(!dialog.openScript(missing));
        QVERIFY(dialog.message().contains(missing));
        QFile binary(m_dir.filePath(QStringLiteral("binary.txt")));
        QVERIFY(binary.open(QIODevice::WriteOnly));
        binary.write(QByteArray("\xff\xfe\x00\x81\xc3", 5));
        binary.close();
        QVERIFY(!dialog.openScript(binary.fileName()));
        QVERIFY(dialog.message().contains(QStringLiteral("UTF-8")));
        // A failed open keeps the script that was there.
        QCOMPARE(dialog.findChild<QPlainTextEdit *>(QStringLiteral("script"))->toPlainText(), kRealScript);
    }
};

TOONFACE_TEST_MAIN(TestLipSyncDialog)
#include "tst_lipsyncdialog.moc"
