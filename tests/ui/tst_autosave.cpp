#include "testmain.h"
#include "uifixture.h"

#include "document/autosaver.h"
#include "document/loadedfile.h"
#include "io/project.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

using namespace toonface;

class TestAutosave : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_photoDir;

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_photoDir.isValid());
    }

    void writesOnlyAModifiedDocument()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        Autosaver saver(&doc, dir.path());
        QVERIFY(saver.autosave());
        QVERIFY(!QFile::exists(saver.recoveryPath())); // nothing to save

        doc.movePoint(pt::idx("8.9"), QPointF(190, 320), true);
        QString error;
        QVERIFY2(saver.autosave(&error), qPrintable(error));
        QVERIFY(QFile::exists(saver.recoveryPath()));
        QVERIFY(saver.recoveryPath().startsWith(dir.path()));

        const std::optional<Project> written = loadProject(saver.recoveryPath(), &error);
        QVERIFY2(written, qPrintable(error));
        QCOMPARE(written->face, doc.face());
        // The document itself is still modified: autosave is not a save.
        QVERIFY(doc.isModified());
    }

    void leftoverOnlyOnceTheEditorIsGone()
    {
        QTemporaryDir dir;
        const QString photoPath = m_photoDir.filePath(QStringLiteral("a.png"));
        QVERIFY(fixture::photo().save(photoPath));
        const QString original = m_photoDir.filePath(QStringLiteral("original.toonface"));

        Document doc;
        fixture::fill(doc, photoPath);
        QString error;
        QVERIFY2(doc.save(original, &error), qPrintable(error));
        doc.movePoint(pt::idx("2.1"), QPointF(200, 420), true);

        auto saver = std::make_unique<Autosaver>(&doc, dir.path());
        QVERIFY2(saver->autosave(&error), qPrintable(error));
        QVERIFY(Autosaver::leftovers(dir.path()).isEmpty()); // its editor still runs

        saver.reset(); // as if the editor had crashed: the file stays, the lock goes
        const QList<RecoveryFile> leftovers = Autosaver::leftovers(dir.path());
        QCOMPARE(leftovers.size(), 1);
        QCOMPARE(leftovers.first().originalPath, original);

        const LoadedFile loaded = Autosaver::load(leftovers.first());
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        Document restored;
        Autosaver::restoreInto(&restored, loaded);
        QCOMPARE(restored.face(), doc.face());
        QCOMPARE(restored.project().photoPath, photoPath);
        QCOMPARE(restored.photo().size(), fixture::kPhotoSize);
        QCOMPARE(restored.filePath(), original);
        QVERIFY(restored.isModified());

        Autosaver::remove(leftovers.first());
        QVERIFY(Autosaver::leftovers(dir.path()).isEmpty());
        QVERIFY(QDir(dir.path())
                    .entryList({QStringLiteral("*.toonface"), QStringLiteral("*.json")}, QDir::Files)
                    .isEmpty());
    }

    // The editor killed (SIGKILL: nothing of it runs) after an autosave: its unsaved timeline
    // comes back whole from the recovery file it left, whose lock died with it.
    void unsavedTimelineSurvivesAKill()
    {
        QTemporaryDir dir;
        const QString photoPath = m_photoDir.filePath(QStringLiteral("k.png"));
        QVERIFY(fixture::photo().save(photoPath));
        const QString original = m_photoDir.filePath(QStringLiteral("killed.toonface"));
        Animation edited;
        {
            Document doc;
            fixture::fill(doc, photoPath);
            QString error;
            QVERIFY2(doc.save(original, &error), qPrintable(error));
            edited = doc.animation();
        }
        // What the user did since the save: a lip-synced phrase, a smile, blinks.
        AudioClip clip {QStringLiteral("/tmp/voice.wav"), 0.0, 2.0};
        clip.script = QStringLiteral("ni3 hao3");
        edited.timeline.setAudioClips({clip});
        for (int i = 0; i < 400; ++i)
            edited.timeline.addMouthKey({0.1 * i, MouthShape(i % kMouthShapeCount), 1.0, 0.08});
        edited.timeline.setEmotionClips({EmotionClip {1.0, 3.0, Emotion::Smile, 0.8, 0.3, 0.3}});
        edited.timeline.setBlinks({{0.5, 0.18}, {2.5, 0.2}});

        int ready[2];
        QCOMPARE(pipe(ready), 0);
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            // The editor: opens the project, edits, autosaves, and works on until it is killed.
            close(ready[0]);
            Document doc;
            QString error;
            if (!doc.load(original, &error))
                _exit(2);
            doc.changeAnimation(edited, QStringLiteral("edit"));
            Autosaver saver(&doc, dir.path());
            if (!saver.autosave(&error))
                _exit(3);
            if (write(ready[1], "x", 1) != 1)
                _exit(4);
            for (;;)
                pause();
        }
        close(ready[1]);
        char byte = 0;
        const ssize_t got = read(ready[0], &byte, 1);
        close(ready[0]);
        QCOMPARE(kill(child, SIGKILL), 0);
        int status = 0;
        QCOMPARE(waitpid(child, &status, 0), child);
        QCOMPARE(got, ssize_t(1));
        QVERIFY(WIFSIGNALED(status));

        const QList<RecoveryFile> leftovers = Autosaver::leftovers(dir.path());
        QCOMPARE(leftovers.size(), 1);
        QCOMPARE(leftovers.first().originalPath, original);
        const LoadedFile loaded = Autosaver::load(leftovers.first());
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        Document restored;
        Autosaver::restoreInto(&restored, loaded);
        QCOMPARE(restored.animation().timeline, edited.timeline);
        QCOMPARE(restored.animation().timeline.audioClips(), edited.timeline.audioClips());
        QCOMPARE(restored.filePath(), original);
        QVERIFY(restored.isModified());
    }

    // Editors killed before their first autosave leave only a lock each: once their owners are
    // gone the next look for leftovers removes them (they piled up crash after crash); a
    // running editor's lock stays.
    void locksOfDeadEditorsDoNotPileUp()
    {
        QTemporaryDir dir;
        for (int i = 0; i < 3; ++i) {
            int ready[2];
            QCOMPARE(pipe(ready), 0);
            const pid_t child = fork();
            QVERIFY(child >= 0);
            if (child == 0) {
                close(ready[0]);
                Document doc;
                Autosaver saver(&doc, dir.path());
                if (write(ready[1], "x", 1) != 1)
                    _exit(4);
                for (;;)
                    pause();
            }
            close(ready[1]);
            char byte = 0;
            const ssize_t got = read(ready[0], &byte, 1);
            close(ready[0]);
            QCOMPARE(kill(child, SIGKILL), 0);
            int status = 0;
            QCOMPARE(waitpid(child, &status, 0), child);
            QCOMPARE(got, ssize_t(1));
        }
        const QStringList lockPattern = {QStringLiteral("recovery-*.lock")};
        QCOMPARE(QDir(dir.path()).entryList(lockPattern, QDir::Files).size(), 3);
        Document doc;
        Autosaver running(&doc, dir.path());
        QVERIFY(Autosaver::leftovers(dir.path()).isEmpty());
        const QStringList left = QDir(dir.path()).entryList(lockPattern, QDir::Files);
        QCOMPARE(left.size(), 1); // the running editor's
        QVERIFY(running.recoveryPath().startsWith(dir.filePath(left.first().chopped(5))));
    }

    void savingRemovesTheRecoveryFile()
    {
        QTemporaryDir dir;
        QTemporaryDir projectDir;
        Document doc;
        fixture::fill(doc);
        Autosaver saver(&doc, dir.path());
        doc.movePoint(0, QPointF(50, 60), true);
        QVERIFY(saver.autosave());
        QVERIFY(QFile::exists(saver.recoveryPath()));
        QString error;
        QVERIFY2(doc.save(projectDir.filePath(QStringLiteral("p.toonface")), &error), qPrintable(error));
        QVERIFY(!QFile::exists(saver.recoveryPath()));
    }

    void undoingToCleanRemovesTheRecoveryFile()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        Autosaver saver(&doc, dir.path());
        doc.movePoint(0, QPointF(50, 60), true);
        QVERIFY(saver.autosave());
        QVERIFY(QFile::exists(saver.recoveryPath()));
        doc.undoStack()->undo();
        QVERIFY(!QFile::exists(saver.recoveryPath()));
    }

    void timerWritesOnItsOwn()
    {
        QTemporaryDir dir;
        Document doc;
        fixture::fill(doc);
        Autosaver saver(&doc, dir.path());
        saver.setInterval(1);
        QCOMPARE(saver.interval(), 1);
        doc.movePoint(0, QPointF(50, 60), true);
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(saver.recoveryPath()), 10000);
        saver.setInterval(0);
        QCOMPARE(saver.interval(), 0);
    }

    void unwritableDirectoryReportsTheFile()
    {
        QTemporaryDir dir;
        const QString blocked = dir.filePath(QStringLiteral("blocked"));
        {
            QFile f(blocked); // a file where the directory should be
            QVERIFY(f.open(QIODevice::WriteOnly));
        }
        Document doc;
        fixture::fill(doc);
        Autosaver saver(&doc, blocked);
        doc.movePoint(0, QPointF(50, 60), true);
        QString error;
        QVERIFY(!saver.autosave(&error));
        QVERIFY2(error.contains(QStringLiteral("blocked")), qPrintable(error));
    }
};

TOONFACE_TEST_MAIN(TestAutosave)
#include "tst_autosave.moc"
