// Export Read-aloud Book…: the dialog makes the book in the background with progress, shows a
// bad text's error and writes nothing then, and stops on Cancel; the main window's File menu
// offers it.

#include "dialogs/bookdialog.h"
#include "dialogs/jobstatus.h"
#include "document/document.h"
#include "face/averageface.h"
#include "testmain.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace toonface;

namespace {

QString writeText(const QTemporaryDir &dir, const QString &name, const QString &text)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text.toUtf8());
    return f.fileName();
}

BookRequest base()
{
    BookRequest r;
    r.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    r.style = Style::preset(QStringLiteral("normal"));
    return r;
}

} // namespace

class TestBookDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void makesTheBook()
    {
        QTemporaryDir dir;
        BookDialog dialog(base());
        dialog.textEdit()->setText(writeText(
            dir, QStringLiteral("t.md"), QStringLiteral("# One\n\nHello there. Good day!\n\n# Two\n\nBye.\n")));
        dialog.sourceBox()->setCurrentIndex(1); // the built-in voice
        const QString out = dir.filePath(QStringLiteral("b.epub"));
        dialog.outputEdit()->setText(out);
        QSignalSpy finished(&dialog, &BookDialog::finished);
        QVERIFY(dialog.start());
        QVERIFY(dialog.isRunning());
        QVERIFY(!dialog.start()); // one at a time
        QVERIFY(finished.wait(120000));
        QVERIFY2(dialog.lastResult().ok(), qPrintable(dialog.lastResult().error));
        QCOMPARE(dialog.lastResult().chapters, 2);
        QCOMPARE(dialog.exportedPath(), out);
        QVERIFY(QFileInfo(out).size() > 0);
        QVERIFY(!dialog.status()->isError());
    }

    void badTextShowsItsError()
    {
        QTemporaryDir dir;
        BookDialog dialog(base());
        const QString text = writeText(dir, QStringLiteral("n.txt"), QStringLiteral("no end to these words\n"));
        dialog.textEdit()->setText(text);
        dialog.sourceBox()->setCurrentIndex(1);
        dialog.outputEdit()->setText(dir.filePath(QStringLiteral("b.epub")));
        QSignalSpy finished(&dialog, &BookDialog::finished);
        QVERIFY(dialog.start());
        QVERIFY(finished.wait(60000));
        QCOMPARE(dialog.lastResult().status, BookStatus::BadInput);
        QVERIFY(dialog.status()->isError());
        QVERIFY(dialog.status()->message().contains(text));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {QStringLiteral("n.txt")});
    }

    // With a recording chosen, Export waits for its file.
    void recordingNeedsAFile()
    {
        BookDialog dialog(base());
        dialog.textEdit()->setText(QStringLiteral("t.txt"));
        dialog.outputEdit()->setText(QStringLiteral("b.epub"));
        dialog.sourceBox()->setCurrentIndex(0);
        QVERIFY(dialog.audioEdit()->isEnabled());
        QVERIFY(!dialog.start());
        dialog.sourceBox()->setCurrentIndex(1);
        QVERIFY(!dialog.audioEdit()->isEnabled());
        QCOMPARE(dialog.request().audioPath, QString());
    }

    void cancelLeavesNothing()
    {
        QTemporaryDir dir;
        BookDialog dialog(base());
        QString text;
        for (int i = 1; i <= 6; ++i)
            text += QStringLiteral("# Part %1\n\nThe quick brown fox jumps over the lazy dog. It runs away fast!\n\n")
                        .arg(i);
        dialog.textEdit()->setText(writeText(dir, QStringLiteral("t.md"), text));
        dialog.sourceBox()->setCurrentIndex(1);
        dialog.outputEdit()->setText(dir.filePath(QStringLiteral("b.epub")));
        QSignalSpy finished(&dialog, &BookDialog::finished);
        QVERIFY(dialog.start());
        dialog.reject(); // while running: cancels
        QVERIFY(finished.wait(60000));
        QCOMPARE(dialog.lastResult().status, BookStatus::Cancelled);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList {QStringLiteral("t.md")});
    }

    void actionOpensForTheDocument()
    {
        QWidget window;
        Document document;
        QAction *action = BookDialog::createAction(&window, &document);
        QCOMPARE(action->objectName(), QStringLiteral("actionExportBook"));
        QVERIFY(action->text().contains(QLatin1StringView("Book")));
    }
};

TOONFACE_TEST_MAIN(TestBookDialog)
#include "tst_bookdialog.moc"
