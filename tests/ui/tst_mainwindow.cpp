#include "testmain.h"
#include "uifixture.h"

#include "detect/detector.h"
#include "document/autosaver.h"
#include "playback/playhead.h"
#include "timeline/timelinewidget.h"
#include "views/photoview.h"
#include "views/pointhandle.h"
#include "views/previewview.h"
#include "views/stepimagedialog.h"
#include "window/detectionsteps.h"
#include "window/mainwindow.h"
#include "window/settings.h"
#include "window/studio.h"

#include "testphotos.h"
#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>

#include <QDockWidget>
#include <QFile>
#include <QGraphicsPixmapItem>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QUrl>
#include <QWidgetAction>
#include <QXmlStreamReader>

#include <csignal>

#include <sys/resource.h>
#include <unistd.h>

using namespace toonface;

namespace {

const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

// Answers the next message box by clicking the button whose text contains `button`
// (mnemonic ampersands ignored). Returns a flag that turns true once it has answered.
std::shared_ptr<bool> answerNextMessageBox(const QString &button)
{
    auto answered = std::make_shared<bool>(false);
    auto *timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, button, answered] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        const QList<QAbstractButton *> buttons = box->buttons();
        for (QAbstractButton *b : buttons) {
            if (b->text().remove(QLatin1Char('&')).contains(button)) {
                *answered = true;
                timer->deleteLater();
                b->click();
                return;
            }
        }
    });
    timer->start();
    return answered;
}

// Clicks, for as long as it lives, the first button containing one of `buttons` in any
// message box that comes up (a method that finds no face offers the average face, or warns
// that the points are unchanged).
class MessageBoxAnswerer
{
public:
    explicit MessageBoxAnswerer(const QStringList &answers)
    {
        m_timer.setInterval(20);
        QObject::connect(&m_timer, &QTimer::timeout, [this, answers] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            const QList<QAbstractButton *> buttons = box->buttons();
            for (const QString &answer : answers) {
                for (QAbstractButton *b : buttons) {
                    if (b->text().remove(QLatin1Char('&')).contains(answer)) {
                        ++m_answered;
                        b->click();
                        return;
                    }
                }
            }
        });
        m_timer.start();
    }
    int answered() const { return m_answered; }

private:
    QTimer m_timer;
    int m_answered = 0;
};

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_photoPath;
    QString m_projectPath;
    std::unique_ptr<QTemporaryDir> m_recoveryDir;
    std::unique_ptr<MainWindow> m_window;

    MainWindow *makeWindow()
    {
        MainWindow::Options options;
        options.preloadLandmarkModel = false;
        options.recoveryDirectory = m_recoveryDir->path();
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        return m_window.get();
    }

    QAction *action(const char *name) const { return m_window->findChild<QAction *>(QLatin1StringView(name)); }
    QAction *action(const QString &name) const { return m_window->findChild<QAction *>(name); }
    QMenu *stepsMenu() const { return m_window->findChild<QMenu *>(QStringLiteral("menuDetectionSteps")); }
    QComboBox *stepsCombo() const { return m_window->findChild<QComboBox *>(QStringLiteral("detectionStepCombo")); }
    QSlider *opacitySlider() const { return m_window->findChild<QSlider *>(QStringLiteral("overlayOpacitySlider")); }

    // Opens the portrait and waits for its detection; false (with a skip or failure recorded)
    // when there is nothing to test with.
    bool openPortrait()
    {
        if (!QFile::exists(kPortrait)) {
            QTest::qSkip("grace_hopper.jpg is not installed (package python-matplotlib-data)", __FILE__, __LINE__);
            return false;
        }
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(kPortrait);
        if (!QTest::qWaitFor([&] { return done.size() == 1; }, 120000)) {
            QTest::qFail("the portrait's detection did not end", __FILE__, __LINE__);
            return false;
        }
        return true;
    }

    bool redetect()
    {
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        action("actionRedetect")->trigger();
        return QTest::qWaitFor([&] { return done.size() == 1; }, 120000);
    }

    // The photo-sized steps listed in the menu, in order, and the close-ups.
    QStringList listedSteps(bool closeUps) const
    {
        QStringList names;
        const QList<QAction *> actions = stepsMenu()->actions();
        for (const QAction *a : actions) {
            const QString name = a->data().toString();
            if (!a->isSeparator() && !name.isEmpty() && DetectionSteps::isCloseUp(name) == closeUps)
                names << name;
        }
        return names;
    }

    void openProject()
    {
        QSignalSpy opened(m_window.get(), &MainWindow::fileOpened);
        m_window->openFile(m_projectPath);
        QTRY_COMPARE(opened.size(), 1);
        QCOMPARE(m_window->document()->filePath(), m_projectPath);
    }

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_dir.isValid());
        m_photoPath = m_dir.filePath(QStringLiteral("portrait.png"));
        QVERIFY(fixture::photo().save(m_photoPath));
        m_projectPath = m_dir.filePath(QStringLiteral("portrait.toonface"));
        Document doc;
        fixture::fill(doc, m_photoPath);
        QString error;
        QVERIFY2(doc.save(m_projectPath, &error), qPrintable(error));
    }

    void init()
    {
        QSettings().clear();
        m_recoveryDir = std::make_unique<QTemporaryDir>();
    }

    void cleanup()
    {
        if (m_window)
            m_window->document()->undoStack()->setClean(); // close without asking
        m_window.reset();
    }

    void openProjectShowsItsNameAndModifiedMark()
    {
        makeWindow();
        openProject();
        Document *doc = m_window->document();
        QVERIFY(doc->hasFace());
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("portrait.toonface")));
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(Settings().recentFiles().value(0), m_projectPath);
        QVERIFY(action("actionSave")->isEnabled());

        doc->movePoint(pt::idx("8.9"), QPointF(190, 320), true);
        QVERIFY(m_window->isWindowModified());
        QCOMPARE(action("actionUndo")->text(), QStringLiteral("&Undo Move point 8.9"));
        action("actionUndo")->trigger();
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(action("actionRedo")->text(), QStringLiteral("&Redo Move point 8.9"));
    }

    void openRecentListsAndOpensPersistedFiles()
    {
        Settings().addRecentFile(m_projectPath);
        makeWindow();
        auto *menu = m_window->findChild<QMenu *>(QStringLiteral("menuRecent"));
        QVERIFY(menu);
        Q_EMIT menu->aboutToShow();
        const QList<QAction *> actions = menu->actions();
        QVERIFY(actions.size() >= 2); // the file, a separator, "Clear Menu"
        QCOMPARE(actions.first()->text(), QStringLiteral("portrait.toonface"));
        actions.first()->trigger();
        QTRY_COMPARE(m_window->document()->filePath(), m_projectPath);
    }

    // Every tool bar button has an icon (the theme's, else the project's own): no text-only
    // buttons, whatever the desktop's icon theme.
    void toolBarButtonsHaveIcons()
    {
        makeWindow();
        const QList<QToolBar *> bars = m_window->findChildren<QToolBar *>();
        int buttons = 0;
        for (QToolBar *bar : bars) {
            const QList<QAction *> actions = bar->actions();
            for (QAction *a : actions) {
                if (a->isSeparator() || qobject_cast<QWidgetAction *>(a))
                    continue;
                ++buttons;
                QVERIFY2(!a->icon().isNull(), qPrintable(a->text()));
                QVERIFY2(!a->icon().pixmap(16, 16).isNull(), qPrintable(a->text()));
            }
        }
        QVERIFY(buttons >= 15);
    }

    // The animation studio is wired in: its menus, the timeline dock, the transport, and the
    // preview following the studio's playhead.
    void studioIsWiredIn()
    {
        makeWindow();
        QStringList menus;
        for (QAction *a : m_window->menuBar()->actions())
            menus << a->text();
        QVERIFY2(menus.indexOf(QStringLiteral("&Animation")) > 0, qPrintable(menus.join(u',')));
        QVERIFY(menus.indexOf(QStringLiteral("&Playback")) > menus.indexOf(QStringLiteral("&Animation")));
        QCOMPARE(menus.constLast(), QStringLiteral("&Help"));
        Studio *studio = m_window->studio();
        QVERIFY(studio->timelineDock());
        QCOMPARE(m_window->dockWidgetArea(studio->timelineDock()), Qt::BottomDockWidgetArea);
        QMenu *file = m_window->menuBar()->actions().constFirst()->menu();
        QVERIFY(file->actions().contains(studio->exportAnimationAction()));
        QVERIFY(studio->animationMenu()->actions().contains(m_window->previewView()->editPoseAction()));
        // Without a face there is nothing to animate.
        QVERIFY(!studio->exportAnimationAction()->isEnabled());
        // The preview draws the pose at the studio's playhead.
        if (!openPortrait())
            return;
        QVERIFY(studio->exportAnimationAction()->isEnabled());
        Animation a = m_window->document()->animation();
        a.timeline.addMouthKey(MouthKey {1.0, MouthShape::A, 1.0, 0.5});
        m_window->document()->changeAnimation(a, QStringLiteral("Open the mouth"));
        const QByteArray shut = m_window->previewView()->svg();
        studio->playhead()->setTime(1.2);
        QTRY_VERIFY(m_window->previewView()->svg() != shut);
    }

    void windowGeometryPersists()
    {
        makeWindow();
        m_window->resize(900, 640);
        QVERIFY(m_window->close());
        QVERIFY(!Settings().windowGeometry().isEmpty());
        m_window.reset();
        makeWindow();
        QCOMPARE(m_window->size(), QSize(900, 640));
    }

    void openFailureSaysWhichFile()
    {
        makeWindow();
        QSignalSpy failed(m_window.get(), &MainWindow::openFailed);
        const auto answered = answerNextMessageBox(QStringLiteral("OK"));
        m_window->openFile(m_dir.filePath(QStringLiteral("missing.toonface")));
        QTRY_COMPARE(failed.size(), 1);
        QVERIFY(*answered);
        QVERIFY(failed.first().first().toString().contains(QStringLiteral("missing.toonface")));
        QVERIFY(!m_window->document()->hasFace());
    }

    void dropOpensTheFile()
    {
        makeWindow();
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(m_projectPath)});
        const QPoint at = m_window->rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &drop);
        QTRY_COMPARE(m_window->document()->filePath(), m_projectPath);

        QMimeData text;
        text.setUrls({QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("notes.txt")))});
        QDragEnterEvent refused(at, Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
        refused.setAccepted(false);
        QApplication::sendEvent(m_window.get(), &refused);
        QVERIFY(!refused.isAccepted());
    }

    void closingWithUnsavedChangesAsks()
    {
        makeWindow();
        openProject();
        m_window->document()->movePoint(0, QPointF(10, 10), true);

        // The question names the project, not the photo (which is never written).
        auto question = std::make_shared<QString>();
        QTimer reader;
        reader.setInterval(10);
        connect(&reader, &QTimer::timeout, this, [question] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget()))
                *question = box->text();
        });
        reader.start();
        auto answered = answerNextMessageBox(QStringLiteral("Cancel"));
        QVERIFY(!m_window->close());
        QVERIFY(*answered);
        reader.stop();
        QVERIFY2(question->contains(QStringLiteral("project %1").arg(QFileInfo(m_projectPath).fileName())),
            qPrintable(*question));
        QVERIFY(m_window->isVisible());

        answered = answerNextMessageBox(QStringLiteral("Discard"));
        QVERIFY(m_window->close());
        QVERIFY(*answered);
        // The project on disk is untouched.
        Document onDisk;
        QString error;
        QVERIFY2(onDisk.load(m_projectPath, &error), qPrintable(error));
        QCOMPARE(onDisk.face(), fixture::face());
    }

    // A save that cannot be written (the disk full, a folder that cannot be written to) says
    // which file and why, keeps the document modified, and leaves the old file as it was.
    void failedSaveSaysSoAndKeepsTheWork_data()
    {
        QTest::addColumn<bool>("diskFull");
        QTest::newRow("disk full") << true;
        QTest::newRow("read-only folder") << false;
    }

    void failedSaveSaysSoAndKeepsTheWork()
    {
        QFETCH(bool, diskFull);
        if (!diskFull && geteuid() == 0)
            QSKIP("running as root: a folder's permissions do not stop root from writing");
        makeWindow();
        openProject();
        Document *doc = m_window->document();
        const FaceModel before = doc->face();
        doc->movePoint(pt::idx("2.1"), QPointF(200, 410), true);
        QVERIFY(m_window->isWindowModified());

        auto text = std::make_shared<QString>();
        QTimer watcher;
        watcher.setInterval(20);
        connect(&watcher, &QTimer::timeout, this, [text] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
                *text = box->windowTitle() + QLatin1Char('\n') + box->text();
                box->accept();
            }
        });
        watcher.start();
        bool saved = true;
        const QString folder = QFileInfo(m_projectPath).absolutePath();
        if (diskFull) {
            // Writing past a file size limit fails with EFBIG, as a full disk fails with ENOSPC.
            struct rlimit old;
            QCOMPARE(getrlimit(RLIMIT_FSIZE, &old), 0);
            const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
            struct rlimit small = old;
            small.rlim_cur = 2048;
            QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
            saved = m_window->saveTo(m_projectPath);
            setrlimit(RLIMIT_FSIZE, &old);
            std::signal(SIGXFSZ, oldHandler);
        } else {
            QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner);
            saved = m_window->saveTo(m_projectPath);
            QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        }
        QVERIFY(!saved);
        QTRY_VERIFY(!text->isEmpty());
        qInfo("the editor said: %s", qPrintable(*text));
        QVERIFY2(text->contains(QStringLiteral("portrait.toonface")), qPrintable(*text));
        QVERIFY(m_window->isWindowModified());
        QVERIFY(doc->isModified());
        QVERIFY(doc->face() != before); // the work is still there
        Document onDisk;
        QString error;
        QVERIFY2(onDisk.load(m_projectPath, &error), qPrintable(error));
        QCOMPARE(onDisk.face(), before);
        // Nothing half-written is left beside it.
        QCOMPARE(QDir(folder).entryList({QStringLiteral("*.toonface*")}, QDir::Files | QDir::Hidden),
            QStringList {QStringLiteral("portrait.toonface")});
    }

    void saveWritesTheProject()
    {
        makeWindow();
        openProject();
        const QString copy = m_dir.filePath(QStringLiteral("copy.toonface"));
        m_window->document()->movePoint(pt::idx("2.1"), QPointF(200, 410), true);
        QVERIFY(m_window->saveTo(copy));
        QVERIFY(!m_window->isWindowModified());
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("copy.toonface")));
        Document saved;
        QString error;
        QVERIFY2(saved.load(copy, &error), qPrintable(error));
        QCOMPARE(saved.face(), m_window->document()->face());
        QCOMPARE(Settings().recentFiles().value(0), copy);
    }

    void styleSelectorChangesTheStyleUndoably()
    {
        makeWindow();
        openProject();
        auto *combo = m_window->findChild<QComboBox *>(QStringLiteral("styleCombo"));
        QVERIFY(combo);
        if (combo->count() < 2)
            QSKIP("only one style preset");
        const QString before = m_window->document()->style().name;
        QCOMPARE(combo->currentData().toString(), before);
        const int other = combo->currentIndex() == 0 ? 1 : 0;
        combo->setCurrentIndex(other);
        Q_EMIT combo->activated(other);
        QCOMPARE(m_window->document()->style().name, combo->itemData(other).toString());
        QCOMPARE(m_window->document()->undoStack()->count(), 1);
        m_window->document()->undoStack()->undo();
        QCOMPARE(m_window->document()->style().name, before);
        QCOMPARE(combo->currentData().toString(), before);
    }

    void startupOffersToRestoreALeftover()
    {
        const QString original = m_dir.filePath(QStringLiteral("crashed.toonface"));
        {
            Document doc;
            fixture::fill(doc, m_photoPath);
            QString error;
            QVERIFY2(doc.save(original, &error), qPrintable(error));
            doc.movePoint(pt::idx("3.5"), QPointF(240, 235), true);
            Autosaver crashed(&doc, m_recoveryDir->path());
            QVERIFY(crashed.autosave());
        }
        QCOMPARE(Autosaver::leftovers(m_recoveryDir->path()).size(), 1);

        makeWindow();
        const auto answered = answerNextMessageBox(QStringLiteral("Restore"));
        m_window->startup(QString());
        QVERIFY(*answered);
        QTRY_VERIFY(m_window->document()->hasFace());
        Document *doc = m_window->document();
        QCOMPARE(doc->filePath(), original);
        QVERIFY(doc->isModified());
        QVERIFY(m_window->isWindowModified());
        QCOMPARE(doc->face().point("3.5"), QPointF(240, 235));
        QVERIFY(Autosaver::leftovers(m_recoveryDir->path()).isEmpty());
    }

    void startupDiscardDeletesTheLeftoverAndOpensTheFile()
    {
        {
            Document doc;
            fixture::fill(doc, m_photoPath);
            doc.movePoint(0, QPointF(5, 5), true);
            Autosaver crashed(&doc, m_recoveryDir->path());
            QVERIFY(crashed.autosave());
        }
        makeWindow();
        const auto answered = answerNextMessageBox(QStringLiteral("Discard"));
        QSignalSpy opened(m_window.get(), &MainWindow::fileOpened);
        m_window->startup(m_projectPath);
        QVERIFY(*answered);
        QTRY_COMPARE(opened.size(), 1);
        QCOMPARE(m_window->document()->filePath(), m_projectPath);
        QVERIFY(Autosaver::leftovers(m_recoveryDir->path()).isEmpty());
    }

    void exportWritesSvgAndPng_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("svg") << QStringLiteral("cartoon.svg");
        QTest::newRow("png") << QStringLiteral("cartoon.png");
    }

    void exportWritesSvgAndPng()
    {
        QFETCH(QString, name);
        makeWindow();
        openProject();
        const QString path = m_dir.filePath(name);
        QSignalSpy exported(m_window.get(), &MainWindow::exported);
        m_window->exportTo(path);
        QTRY_COMPARE(exported.size(), 1);
        QVERIFY2(exported.first().at(1).toString().isEmpty(), qPrintable(exported.first().at(1).toString()));
        if (name.endsWith(QLatin1StringView(".svg"))) {
            QFile file(path);
            QVERIFY(file.open(QIODevice::ReadOnly));
            QXmlStreamReader xml(&file);
            QVERIFY(xml.readNextStartElement());
            QCOMPARE(xml.name(), QLatin1StringView("svg"));
        } else {
            const QImage image(path);
            QCOMPARE(image.size(), fixture::kPhotoSize);
        }
    }

    // Without the landmark model, auto's fallback to the thesis' pipeline is said in the status
    // bar, which keeps it up.
    void fallbackToClassicIsShown()
    {
        const QByteArray saved = qgetenv("TOONFACE_LANDMARK_MODEL");
        const bool had = qEnvironmentVariableIsSet("TOONFACE_LANDMARK_MODEL");
        qputenv("TOONFACE_LANDMARK_MODEL", "/nonexistent/toonface-ui-test/landmarks.dat");
        makeWindow();
        const bool ok = openPortrait();
        const QString message = m_window->statusBar()->currentMessage();
        if (had)
            qputenv("TOONFACE_LANDMARK_MODEL", saved);
        else
            qunsetenv("TOONFACE_LANDMARK_MODEL");
        if (!ok)
            return;
        QVERIFY(m_window->document()->hasFace());
        QVERIFY2(message.contains(QStringLiteral("classic")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("/nonexistent/toonface-ui-test/landmarks.dat")), qPrintable(message));
    }

    // A photo of two people: the status bar says how many faces there were and which was used.
    void severalFacesAreCounted()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        const QImage one(kPortrait);
        const QImage both = testing::twoPeople(one);
        const QString photo = m_dir.filePath(QStringLiteral("two people.png"));
        QVERIFY(both.save(photo));
        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(photo);
        QVERIFY(QTest::qWaitFor([&] { return done.size() == 1; }, 120000));
        QVERIFY(m_window->document()->hasFace());
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("2 faces found: using the largest, most central one")),
            qPrintable(message));
        // The whole photo is shown, so that the other face can be seen and chosen.
        QCOMPARE(m_window->photoView()->fitMode(), PhotoView::Fit::Photo);
        QVERIFY(m_window->document()->face().point("2.1").x() < one.width());

        // The other face's box is on the photo; a click in it detects that face, one undo step.
        PhotoView *view = m_window->photoView();
        QCOMPARE(view->otherFaces().size(), 1);
        const QRect other = view->otherFaces().constFirst();
        QVERIFY(other.left() >= one.width() - 5);
        const int undoBefore = m_window->document()->undoStack()->count();
        done.clear();
        const QPoint click = view->mapFromScene(QPointF(other.center()));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, click);
        QVERIFY(QTest::qWaitFor([&] { return done.size() == 1; }, 120000));
        QVERIFY(other.contains(m_window->document()->face().point("2.1").toPoint()));
        QCOMPARE(m_window->document()->undoStack()->count(), undoBefore + 1);
        QCOMPARE(m_window->document()->undoStack()->undoText(), QStringLiteral("Use another face"));
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("using the one you chose")),
            qPrintable(m_window->statusBar()->currentMessage()));
        // Now the first portrait's face is the other one.
        QCOMPARE(view->otherFaces().size(), 1);
        QVERIFY(view->otherFaces().constFirst().right() < one.width() + 5);
        m_window->document()->undoStack()->undo();
        QVERIFY(m_window->document()->face().point("2.1").x() < one.width());
    }

    void cancelledDetectionLeavesNoFace()
    {
        makeWindow();
        QSignalSpy opened(m_window.get(), &MainWindow::fileOpened);
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(m_photoPath);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY(m_window->isBusy()); // detecting
        auto *cancel = m_window->findChild<QAbstractButton *>(QStringLiteral("cancelButton"));
        QVERIFY(cancel && cancel->isVisible());
        cancel->click();
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 60000);
        QVERIFY(!m_window->isBusy());
        QVERIFY(!cancel->isVisible());
        QVERIFY(!m_window->document()->hasFace());
        QCOMPARE(m_window->document()->undoStack()->count(), 0);
    }

    void photoWithoutFaceOffersTheAverageFace()
    {
        QImage blank(320, 240, QImage::Format_RGB32);
        blank.fill(QColor(128, 128, 128));
        const QString blankPath = m_dir.filePath(QStringLiteral("blank.png"));
        QVERIFY(blank.save(blankPath));

        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        const auto answered = answerNextMessageBox(QStringLiteral("Place Average Face"));
        m_window->openFile(blankPath);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 60000);
        QVERIFY(*answered);
        Document *doc = m_window->document();
        QVERIFY(doc->hasFace());
        QVERIFY(doc->filePath().isEmpty());
        QCOMPARE(doc->displayName(), QStringLiteral("blank.png"));
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Place average face"));
        QVERIFY(QRectF(0, 0, 320, 240).contains(doc->face().bounds(PointGroup::Mouth)));
    }

    // The points are placed as soon as they are found, before the detection's steps (drawn
    // after, in the background); the face then stays as it was placed, in one undo step.
    void pointsComeBeforeTheSteps()
    {
        makeWindow();
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        QStringList order;
        FaceModel placed;
        int stepsWhenPlaced = -1;
        connect(m_window.get(), &MainWindow::pointsPlaced, this, [&] {
            order << QStringLiteral("points");
            placed = m_window->document()->face();
            stepsWhenPlaced = int(m_window->detectionSteps()->names().size());
        });
        connect(m_window.get(), &MainWindow::detectionDone, this, [&] { order << QStringLiteral("done"); });
        m_window->openFile(kPortrait);
        QVERIFY(QTest::qWaitFor([&] { return order.contains(QStringLiteral("done")); }, 120000));
        QCOMPARE(order, QStringList({QStringLiteral("points"), QStringLiteral("done")}));
        QCOMPARE(stepsWhenPlaced, 0);
        QVERIFY(!m_window->detectionSteps()->names().isEmpty());
        const FaceModel &final = m_window->document()->face();
        for (int i = 0; i < kPointCount; ++i)
            QCOMPARE(final.point(i), placed.point(i));
        QCOMPARE(m_window->document()->undoStack()->count(), 1);
    }

    void detectionStepsNeedADetection()
    {
        makeWindow();
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QVERIFY(stepsMenu()->menuAction()->toolTip().contains(QStringLiteral("Open a photo")));
        openProject();
        // A project keeps no steps: the menu says so and how to get them.
        QVERIFY(m_window->detectionSteps()->isEmpty());
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QVERIFY(!stepsCombo()->isEnabled());
        QVERIFY(stepsMenu()->menuAction()->toolTip().contains(QStringLiteral("Re-detect")));
        QCOMPARE(stepsCombo()->toolTip(), stepsMenu()->menuAction()->toolTip());
        QVERIFY(!m_window->photoView()->hasOverlay());
    }

    void detectionStepsOfThePortraitShowOverThePhoto()
    {
        makeWindow();
        // The photo at the size this check was made for: the docks closed, so that the view does
        // not shrink the photo (a shrunk photo shows only some of its pixels).
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
            dock->close();
        if (!openPortrait())
            return;
        Document *doc = m_window->document();
        QVERIFY(doc->hasFace());
        DetectionSteps *steps = m_window->detectionSteps();
        QVERIFY(!steps->isEmpty());

        // The menu and the combo list every step by its name for people, None first and checked.
        QVERIFY(stepsMenu()->menuAction()->isEnabled());
        QVERIFY(stepsCombo()->isEnabled());
        QStringList overlays;
        QStringList closeUps;
        for (const QString &name : steps->names())
            (DetectionSteps::isCloseUp(name) ? closeUps : overlays) << name;
        QVERIFY(!overlays.isEmpty());
        QCOMPARE(listedSteps(false), overlays);
        QCOMPARE(listedSteps(true), closeUps);
        QVERIFY(action("actionStepNone")->isChecked());
        QCOMPARE(stepsCombo()->count(), overlays.size() + 1);
        QCOMPARE(stepsCombo()->currentIndex(), 0);
        for (int i = 0; i < overlays.size(); ++i) {
            QCOMPARE(
                action(QStringLiteral("actionStep-") + overlays[i])->text(), DetectionSteps::displayName(overlays[i]));
            QCOMPARE(stepsCombo()->itemText(i + 1), DetectionSteps::displayName(overlays[i]));
        }
        QVERIFY(!m_window->photoView()->hasOverlay());

        // Choosing one lays it over the whole photo, with the slider's opacity.
        PhotoView *view = m_window->photoView();
        view->fitToWindow();
        opacitySlider()->setValue(100);
        QCoreApplication::processEvents();
        const QImage plain = view->viewport()->grab().toImage();
        // Photo pixels (on a grid) where a step's picture is opaque and clearly not the photo.
        const QRectF photoRect(QPointF(), QSizeF(doc->photo().size()));
        auto differing = [&](const QString &name) {
            const QImage picture = steps->image(name).scaled(doc->photo().size());
            QList<QPoint> points;
            for (int y = 4; y < photoRect.height() - 4; y += 7) {
                for (int x = 4; x < photoRect.width() - 4; x += 7) {
                    const QRgb over = picture.pixel(x, y);
                    const QRgb under = doc->photo().pixel(x, y);
                    const int contrast = std::abs(qRed(over) - qRed(under)) + std::abs(qGreen(over) - qGreen(under))
                        + std::abs(qBlue(over) - qBlue(under));
                    if (qAlpha(over) == 255 && contrast >= 60)
                        points.append(QPoint(x, y));
                }
            }
            return points;
        };
        QString step = overlays.first(); // the step that differs most from the photo
        QList<QPoint> stepDiffers = differing(step);
        for (const QString &name : std::as_const(overlays)) {
            const QList<QPoint> points = differing(name);
            if (points.size() > stepDiffers.size()) {
                step = name;
                stepDiffers = points;
            }
        }
        action(QStringLiteral("actionStep-") + step)->trigger();
        QCOMPARE(m_window->overlayStep(), step);
        QVERIFY(view->hasOverlay());
        QCOMPARE(stepsCombo()->currentData().toString(), step);
        QVERIFY(action(QStringLiteral("actionStep-") + step)->isChecked());
        QCOMPARE(view->overlayItem()->sceneBoundingRect(), photoRect);
        QCOMPARE(view->overlayItem()->opacity(), 1.0);

        // Where the step's picture is opaque and differs from the photo, the view shows it.
        QCoreApplication::processEvents();
        const QImage covered = view->viewport()->grab().toImage();
        int opaque = 0;
        int changed = 0;
        for (const QPoint &p : std::as_const(stepDiffers)) {
            const QPoint v = view->mapFromScene(QPointF(p) + QPointF(0.5, 0.5));
            if (!view->viewport()->rect().contains(v))
                continue;
            ++opaque;
            changed += covered.pixel(v) != plain.pixel(v);
        }
        QVERIFY2(opaque > 100, qPrintable(QString::number(opaque)));
        QVERIFY2(changed >= opaque * 0.95, qPrintable(QStringLiteral("%1 of %2").arg(changed).arg(opaque)));

        opacitySlider()->setValue(35);
        QCOMPARE(view->overlayItem()->opacity(), 0.35);
        QCOMPARE(Settings().overlayOpacity(), 0.35);

        // The combo chooses too, and None takes the overlay away.
        if (overlays.size() > 1) {
            stepsCombo()->setCurrentIndex(2);
            Q_EMIT stepsCombo()->activated(2);
            QCOMPARE(m_window->overlayStep(), overlays[1]);
            QVERIFY(action(QStringLiteral("actionStep-") + overlays[1])->isChecked());
        }
        action("actionStepNone")->trigger();
        QVERIFY(!view->hasOverlay());
        QVERIFY(m_window->overlayStep().isEmpty());
        QVERIFY(!opacitySlider()->isEnabled());
        m_window->showDetectionStep(step);
        QVERIFY(opacitySlider()->isEnabled());

        // Points still drag with the overlay shown, one undo step each.
        const int i = pt::idx("8.4");
        const QPointF before = doc->face().point(i);
        const int undoCount = doc->undoStack()->count();
        const QPoint from = view->mapFromScene(before);
        QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, from);
        for (int s = 1; s <= 6; ++s)
            QTest::mouseMove(view->viewport(), from + QPoint(2 * s, 3 * s));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, from + QPoint(12, 18));
        QVERIFY(QLineF(doc->face().point(i), before + QPointF(12, 18) / view->zoom()).length() < 1.5 / view->zoom());
        QCOMPARE(doc->undoStack()->count(), undoCount + 1);
        QVERIFY(view->hasOverlay());

        // A close-up opens in a window of its own and leaves the overlay as it was.
        if (!closeUps.isEmpty()) {
            action(QStringLiteral("actionStep-") + closeUps.first())->trigger();
            auto *dialog = m_window->findChild<StepImageDialog *>(QStringLiteral("closeUp-") + closeUps.first());
            QVERIFY(dialog);
            QVERIFY(dialog->isVisible());
            QCOMPARE(dialog->windowTitle(), DetectionSteps::displayName(closeUps.first()));
            QVERIFY(!dialog->shownPixmap().isNull());
            QCOMPARE(m_window->overlayStep(), step);
        }

        // Undoing the drag and the detection keeps the steps (they belong to the photo, not the points).
        while (doc->undoStack()->canUndo())
            doc->undoStack()->undo();
        QVERIFY(!doc->hasFace());
        QVERIFY(!steps->isEmpty());
        QVERIFY(view->hasOverlay());
        doc->undoStack()->setClean();

        // Another photo (here a project's) drops them, the close-ups with them.
        openProject();
        QVERIFY(steps->isEmpty());
        QVERIFY(!view->hasOverlay());
        QVERIFY(m_window->overlayStep().isEmpty());
        QVERIFY(!stepsMenu()->menuAction()->isEnabled());
        QCOMPARE(listedSteps(false), QStringList());
        QCOMPARE(stepsCombo()->count(), 1);
        QTRY_VERIFY(m_window->findChildren<StepImageDialog *>().isEmpty());
    }

    void detectionMethodComesFromTheSettings()
    {
        Settings().setDetectionMethod(QStringLiteral("landmarks"));
        makeWindow();
        QVERIFY(action("actionMethodLandmarks")->isChecked());
        QVERIFY(!action("actionMethodAuto")->isChecked());
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Landmarks);
        action("actionMethodClassic")->trigger();
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("classic"));
    }

    void detectionMethodChoosesTheSteps()
    {
        makeWindow();
        QVERIFY(action("actionMethodAuto")->isChecked());
        m_window->setDetectionMethod(DetectionMethod::Classic);
        QVERIFY(action("actionMethodClassic")->isChecked());
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Classic);
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("auto")); // this session only
        const MessageBoxAnswerer answerer({QStringLiteral("OK"), QStringLiteral("Cancel")});
        if (!openPortrait())
            return;
        // The thesis pipeline may or may not place a face on this photo; its steps show how far it got.
        const QStringList classic = m_window->detectionSteps()->names();
        QVERIFY(!classic.isEmpty());
        for (const QString &name : classic)
            QVERIFY2(name.startsWith(QStringLiteral("classic-")), qPrintable(name));
        QVERIFY(classic.contains(QStringLiteral("classic-b1")));
        m_window->showDetectionStep(QStringLiteral("classic-b1"));
        QCOMPARE(m_window->overlayStep(), QStringLiteral("classic-b1"));

        // The menu switches the method; re-detection replaces the steps and keeps the chosen
        // one when the new run has it too.
        action("actionMethodLandmarks")->trigger();
        QCOMPARE(m_window->detectionMethod(), DetectionMethod::Landmarks);
        QCOMPARE(Settings().detectionMethod(), QStringLiteral("landmarks"));
        QVERIFY(action("actionRedetect")->isEnabled()); // with or without a face from the classic run
        QVERIFY(redetect());
        const QStringList landmarks = m_window->detectionSteps()->names();
        QVERIFY(!landmarks.isEmpty());
        for (const QString &name : landmarks)
            QVERIFY2(!name.startsWith(QStringLiteral("classic-")), qPrintable(name));
        QVERIFY(m_window->overlayStep().isEmpty()); // B1 is not a landmark step

        m_window->showDetectionStep(landmarks.first());
        const QString shown = m_window->overlayStep();
        QVERIFY(!shown.isEmpty());
        QVERIFY(redetect());
        QCOMPARE(m_window->overlayStep(), shown);
    }

    void photoIsDetectedInTheBackground()
    {
        if (!QFile::exists(kPortrait))
            QSKIP("grace_hopper.jpg is not installed (package python-matplotlib-data)");
        makeWindow();
        QSignalSpy done(m_window.get(), &MainWindow::detectionDone);
        m_window->openFile(kPortrait);
        QTRY_VERIFY(m_window->isBusy() || done.size() == 1);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 1, 120000);
        QVERIFY(!m_window->isBusy());
        Document *doc = m_window->document();
        if (!doc->hasFace())
            QFAIL("no face found on the portrait");
        // Points and sampled colours arrive as one undoable step.
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->undoStack()->undoText(), QStringLiteral("Detect face"));
        QVERIFY(doc->isModified());
        doc->undoStack()->undo();
        QVERIFY(!doc->hasFace());

        // Re-detection keeping a hand-placed point.
        doc->undoStack()->redo();
        const int i = pt::idx("9.15");
        const QPointF placed = doc->face().point(i) + QPointF(7, 0);
        doc->movePoint(i, placed, true);
        action("actionRedetectKeep")->trigger();
        QVERIFY(m_window->isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 2, 120000);
        QCOMPARE(doc->undoStack()->count(), 3);
        QCOMPARE(doc->face().point(i), placed);

        // Re-detect Points over a point moved by hand asks first: Cancel does nothing,
        // Keep My Points keeps it.
        auto answered = answerNextMessageBox(QStringLiteral("Cancel"));
        action("actionRedetect")->trigger();
        QVERIFY(*answered);
        QVERIFY(!m_window->isBusy());
        QCOMPARE(doc->undoStack()->count(), 3);
        answered = answerNextMessageBox(QStringLiteral("Keep My Points"));
        action("actionRedetect")->trigger();
        QVERIFY(*answered);
        QTRY_VERIFY_WITH_TIMEOUT(done.size() == 3, 120000);
        QCOMPARE(doc->face().point(i), placed);
    }
};

TOONFACE_TEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
