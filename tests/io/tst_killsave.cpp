#include "face/averageface.h"
#include "io/project.h"
#include "testmain.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <csignal>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace toonface;

// A save killed at any moment (SIGKILL: no handler runs, as when the power goes or the system
// kills the editor) leaves the project file whole: the old version or the new one, never a
// mix or a cut-off file.
namespace {

// A large project (a long animation: some megabytes of JSON) whose one syllable says which it is.
Project bigProject(const QString &which)
{
    Project p;
    p.face = averageFace(QRectF(60, 80, 200, 240), QSize(320, 400));
    p.syllables = {{which, QString(), 0, 0.0, 0.5, 1.0, {}}};
    for (int i = 0; i < 30000; ++i)
        p.timeline.addMouthKey({i * 0.04, MouthShape(i % kMouthShapeCount), 1.0, 0.02});
    return p;
}

} // namespace

class TestKillSave : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void killedMidSaveLeavesAWholeFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("talk.toonface"));
        const Project first = bigProject(QStringLiteral("first"));
        const Project second = bigProject(QStringLiteral("second"));
        QString error;
        QVERIFY2(saveProject(first, path, &error), qPrintable(error));
        const qint64 size = QFileInfo(path).size();
        QVERIFY(size > 1000000);

        QElapsedTimer oneSave;
        oneSave.start();
        QVERIFY(saveProject(second, path, &error));
        const int saveMs = std::max(2, int(oneSave.elapsed()));

        int killedWhileSaving = 0;
        for (int round = 0; round < 12; ++round) {
            const pid_t child = fork();
            QVERIFY(child >= 0);
            if (child == 0) {
                // Saves the two versions in turn until killed.
                for (int i = 0;; ++i) {
                    QString e;
                    saveProject(i % 2 ? first : second, path, &e);
                }
            }
            // Somewhere inside a save: from a tenth of one to a few of them.
            QThread::msleep(saveMs / 10 + QRandomGenerator::global()->bounded(3 * saveMs));
            QCOMPARE(kill(child, SIGKILL), 0);
            int status = 0;
            QCOMPARE(waitpid(child, &status, 0), child);
            QVERIFY(WIFSIGNALED(status));
            ++killedWhileSaving;

            const std::optional<Project> loaded = loadProject(path, &error);
            QVERIFY2(loaded, qPrintable(error));
            QVERIFY(loaded->syllables == first.syllables || loaded->syllables == second.syllables);
            QCOMPARE(loaded->timeline.mouthKeys().size(), first.timeline.mouthKeys().size());
        }
        QCOMPARE(killedWhileSaving, 12);
        // Whatever a killed save left beside it is its temporary file, never in the project's name.
        const QStringList files = QDir(dir.path()).entryList(QDir::Files);
        for (const QString &f : files)
            QVERIFY2(
                f == QStringLiteral("talk.toonface") || f.startsWith(QStringLiteral("talk.toonface.")), qPrintable(f));
        // And the next save (by a new process) still works.
        QVERIFY2(saveProject(first, path, &error), qPrintable(error));
        QCOMPARE(loadProject(path, &error)->syllables, first.syllables);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestKillSave)
#include "tst_killsave.moc"
