// Export Read-aloud Book…: the dialog makes the book in the background with progress, shows a
// bad text's error and writes nothing then, and stops on Cancel; the main window's File menu
// offers it.

#include "dialogs/bookdialog.h"
#include "dialogs/jobstatus.h"
#include "document/document.h"
#include "face/averageface.h"
#include "media/mediareader.h"
#include "speech/audio.h"
#include "testmain.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

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

    // "Face: A video of each page", chosen with the keyboard, makes a book whose page shows a
    // video; the dialog shows the stage it is at while it works.
    void videoFaceIsChosenInTheDialog()
    {
        QTemporaryDir dir;
        BookDialog dialog(base());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        dialog.textEdit()->setText(writeText(dir, QStringLiteral("t.txt"), QStringLiteral("Hello there.\n")));
        dialog.sourceBox()->setCurrentIndex(1);
        const QString out = dir.filePath(QStringLiteral("v.epub"));
        dialog.outputEdit()->setText(out);
        QCOMPARE(dialog.request().faceMedia, BookFaceMedia::Svg);
        dialog.faceMediaBox()->setFocus();
        QTest::keyClick(dialog.faceMediaBox(), Qt::Key_Down);
        QCOMPARE(dialog.request().faceMedia, BookFaceMedia::Video);
        QSignalSpy finished(&dialog, &BookDialog::finished);
        QVERIFY(dialog.start());
        auto *bar = dialog.status()->findChild<QProgressBar *>();
        QVERIFY(bar);
        bool shown = false;
        while (finished.isEmpty()) {
            shown = shown || (bar->isVisible() && bar->value() > 0);
            if (!finished.wait(20) && !dialog.isRunning())
                break;
        }
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 120000);
        QVERIFY2(dialog.lastResult().ok(), qPrintable(dialog.lastResult().error));
        QVERIFY2(shown, "no progress shown");
        QFile book(out);
        QVERIFY(book.open(QIODevice::ReadOnly));
        QVERIFY(book.readAll().contains("OEBPS/video/p00001.mp4"));
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

    // A project of several recordings is read by its whole audio track, mixed — not by its first
    // recording alone; one whole recording is offered as before.
    void severalRecordingsAreReadAsTheMixedTrack()
    {
        QTemporaryDir dir;
        Audio tone;
        tone.samples.resize(tone.sampleRate); // 1 s
        for (qsizetype i = 0; i < tone.samples.size(); ++i)
            tone.samples[i] = float(0.3 * std::sin(2 * M_PI * 300 * double(i) / tone.sampleRate));
        const QString a = dir.filePath(QStringLiteral("a.wav"));
        const QString b = dir.filePath(QStringLiteral("b.wav"));
        QString error;
        QVERIFY2(writeAudio(a, tone, &error) && writeAudio(b, tone, &error), qPrintable(error));

        BookRequest first = base();
        first.audioPath = a;
        BookDialog single(first);
        single.setProjectTrack({AudioClip {a, 0.0, 1.0}});
        QCOMPARE(single.sourceBox()->count(), 2);
        QCOMPARE(single.request().audioPath, a);

        BookDialog dialog(first);
        dialog.setProjectTrack({AudioClip {a, 0.0, 1.0}, AudioClip {b, 2.0, 1.0}});
        QCOMPARE(dialog.sourceBox()->count(), 3);
        QCOMPARE(dialog.sourceBox()->currentIndex(), 0);
        QVERIFY2(dialog.sourceBox()->currentText().contains(QLatin1Char('2')),
            qPrintable(dialog.sourceBox()->currentText()));
        QCOMPARE(dialog.request().audioPath, dialog.mixedTrackPath());
        QVERIFY(!dialog.audioEdit()->isEnabled());

        dialog.textEdit()->setText(writeText(dir, QStringLiteral("t.txt"), QStringLiteral("Hello there.\n")));
        dialog.outputEdit()->setText(dir.filePath(QStringLiteral("b.epub")));
        QSignalSpy finished(&dialog, &BookDialog::finished);
        QVERIFY(dialog.start());
        QVERIFY(finished.wait(120000));
        // What the book read: both recordings at their places, 0 .. 3 s (the first alone is 1 s).
        const std::optional<QVector<float>> heard = readAudio(dialog.mixedTrackPath(), tone.sampleRate, &error);
        QVERIFY2(heard, qPrintable(error));
        QVERIFY2(
            std::abs(heard->size() / double(tone.sampleRate) - 3.0) < 0.01, qPrintable(QString::number(heard->size())));
        const auto level = [&heard, &tone](double from, double to) {
            float peak = 0;
            for (qsizetype i = qsizetype(from * tone.sampleRate); i < qsizetype(to * tone.sampleRate); ++i)
                peak = std::max(peak, std::abs(heard->at(i)));
            return peak;
        };
        QVERIFY(level(0.1, 0.9) > 0.25f);
        QVERIFY(level(1.1, 1.9) < 0.01f);
        QVERIFY(level(2.1, 2.9) > 0.25f);
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
