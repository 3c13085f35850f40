#include "mainwindowfixture.h"
#include "testmain.h"

using namespace toonface;
using namespace toonface::mainwindowfixture;

// The main window: opening, saving and exporting files, the menus, the tool bar, the window.
class TestMainWindow : public MainWindowTestBase
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { setUpCase(); }
    void init() { setUpTest(); }
    void cleanup() { tearDown(); }

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
        QCOMPARE(action("actionUndo")->text(), QStringLiteral("&Undo Move Upper lip, left peak"));
        action("actionUndo")->trigger();
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(action("actionRedo")->text(), QStringLiteral("&Redo Move Upper lip, left peak"));
    }

    // The title names the document as a desktop editor does: the project, never the photo (which
    // is not written), with the modified mark; before a save it is "Untitled project".
    void titleNamesTheProject()
    {
        makeWindow();
        Document *doc = m_window->document();
        fixture::fill(*doc, m_photoPath); // a photo opened and detected: not saved yet
        const auto shown = [this] { return m_window->windowHandle()->title(); };
        QCOMPARE(m_window->windowTitle(), QStringLiteral("Untitled project[*] — Toonface"));
        QCOMPARE(shown(), QStringLiteral("Untitled project — Toonface"));
        doc->movePoint(pt::idx("8.9"), QPointF(190, 320), true);
        QCOMPARE(shown(), QStringLiteral("Untitled project* — Toonface"));
        QVERIFY(!shown().contains(QStringLiteral("portrait.png")));

        const QTemporaryDir folder; // apart from the suite's folder, whose files others count
        const QString first = folder.filePath(QStringLiteral("talk.toonface"));
        QVERIFY(m_window->saveTo(first));
        QCOMPARE(shown(), QStringLiteral("talk.toonface — Toonface"));
        doc->movePoint(pt::idx("8.9"), QPointF(192, 322), true);
        QCOMPARE(shown(), QStringLiteral("talk.toonface* — Toonface"));

        // Save As: the title follows the new file.
        const QString second = folder.filePath(QStringLiteral("talk take two.toonface"));
        QVERIFY(m_window->saveTo(second));
        QCOMPARE(shown(), QStringLiteral("talk take two.toonface — Toonface"));
        QCOMPARE(m_window->windowFilePath(), second);
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

    // Help ▸ User Manual opens the manual shipped in the program (no web link), in each of the
    // interface's languages, covering the four jobs.
    void helpOpensTheShippedManual()
    {
        makeWindow();
        QAction *manual = action("actionManual");
        QVERIFY(manual);
        QMenu *help = m_window->menuBar()->actions().constLast()->menu();
        QVERIFY(help->actions().contains(manual));
        QString text;
        QTimer::singleShot(0, m_window.get(), [&text] {
            if (auto *shown = qobject_cast<ManualDialog *>(QApplication::activeModalWidget())) {
                text = shown->browser()->toPlainText();
                shown->reject();
            }
        });
        manual->trigger();
        // The dialog ran modally and showed the English manual.
        QVERIFY2(text.contains(QStringLiteral("Lip Sync from Recording")), qPrintable(text.left(200)));

        const QRegularExpression han(QStringLiteral("[\\x{4E00}-\\x{9FFF}]"));
        for (const QString &language : {QStringLiteral("en"), QStringLiteral("zh_TW"), QStringLiteral("zh_CN")}) {
            const QString html = ManualDialog::html(language);
            QVERIFY2(!html.isEmpty(), qPrintable(language));
            for (const char *job : {"id=\"photo\"", "id=\"lipsync\"", "id=\"video\"", "id=\"export\""})
                QVERIFY2(
                    html.contains(QLatin1String(job)), qPrintable(language + QLatin1Char(' ') + QLatin1String(job)));
            QCOMPARE(html.contains(han), language != QLatin1String("en"));
            QVERIFY2(!html.contains(QLatin1String("http")), qPrintable(language));
        }
        // The two Chinese manuals are written in their own characters.
        QVERIFY(ManualDialog::html(QStringLiteral("zh_TW")).contains(QStringLiteral("檔案")));
        QVERIFY(ManualDialog::html(QStringLiteral("zh_CN")).contains(QStringLiteral("文件")));
        QCOMPARE(ManualDialog::resourceFor(QStringLiteral("fr")), ManualDialog::resourceFor(QString()));
    }

    // Animation ▸ Live Mode opens its own window where LiveWindow::placement() puts it, beside
    // the main window (it opened centred over it).
    void liveModeOpensBesideTheWindow()
    {
        makeWindow();
        const QRect available = m_window->screen()->availableGeometry();
        m_window->setGeometry(QRect(available.topLeft(), QSize(available.width() / 3, available.height() / 2)));
        QAction *live = action("actionLiveMode");
        QVERIFY(live);
        live->trigger();
        LiveWindow *window = m_window->studio()->liveWindow();
        QVERIFY(window && window->isWindow() && window->isVisible());
        const QRect expected = LiveWindow::placement(m_window->frameGeometry(), window->size(), available);
        QCOMPARE(window->pos(), expected.topLeft());
        window->close();
    }

    // Live Mode is a top-level window of its own: not the main window's child (which the
    // window manager keeps above the main window), never keeping the editor running alone,
    // closed with the main window, and opened again where it was last closed.
    void liveModeIsAWindowOfItsOwn()
    {
        makeWindow();
        action("actionLiveMode")->trigger();
        QPointer<LiveWindow> live = m_window->studio()->liveWindow();
        QVERIFY(live && live->isVisible());
        QVERIFY(!live->parentWidget());
        QVERIFY(live->isWindow());
        QVERIFY(!live->testAttribute(Qt::WA_QuitOnClose));
        QVERIFY(live->windowHandle() && !live->windowHandle()->transientParent());
        // Moved by the user (away from where it first opened), then closed: remembered.
        const QRect available = m_window->screen()->availableGeometry();
        const QRect placed = live->geometry();
        live->move(available.topLeft() + QPoint(37, 41));
        QTRY_COMPARE(live->pos(), available.topLeft() + QPoint(37, 41));
        const QRect chosen = live->geometry();
        QVERIFY(chosen != placed);
        live->close();
        QVERIFY(!Settings().liveWindowGeometry().isEmpty());

        // A new session of the editor opens it there.
        tearDown();
        QVERIFY(!live); // deleted with the studio, not left behind as a window of its own
        makeWindow();
        action("actionLiveMode")->trigger();
        live = m_window->studio()->liveWindow();
        QVERIFY(live && live->isVisible());
        QTRY_COMPARE(live->geometry(), chosen);

        // Closing the main window closes it too (a recording would be committed first).
        QSignalSpy closed(live.data(), &LiveWindow::closed);
        m_window->document()->undoStack()->setClean();
        QVERIFY(m_window->close());
        QCOMPARE(closed.size(), 1);
        QVERIFY(!live->isVisible());
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

    // View > Transparent Background (Ctrl+Shift+B) draws the cartoon without its background
    // over a checkerboard, as a sticker exports it; the next window starts as this one ended.
    void transparentViewIsRemembered()
    {
        makeWindow();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        openProject();
        PreviewView *preview = m_window->previewView();
        QAction *transparent = preview->transparentAction();
        QMenu *view = nullptr;
        for (QAction *a : m_window->menuBar()->actions()) {
            if (a->text() == QStringLiteral("&View"))
                view = a->menu();
        }
        QVERIFY(view && view->actions().contains(transparent));
        QVERIFY(!transparent->isChecked());
        // Pixels of the checkerboard's grey in the view, and the picture's corner alpha.
        const auto checkerPixels = [&] {
            const QImage shown = preview->image().convertToFormat(QImage::Format_RGB32);
            int n = 0;
            for (int y = 0; y < shown.height(); ++y) {
                const auto *row = reinterpret_cast<const QRgb *>(shown.constScanLine(y));
                for (int x = 0; x < shown.width(); ++x)
                    n += row[x] == qRgb(204, 204, 204);
            }
            return n;
        };
        // The picture shown now, brought up to date.
        const auto cornerAlpha = [&] {
            preview->image();
            return qAlpha(preview->renderer()->current().image.pixel(0, 0));
        };
        const auto centreAlpha = [&] {
            const QImage &image = preview->renderer()->current().image;
            return qAlpha(image.pixel(image.width() / 2, image.height() / 2));
        };
        QVERIFY(!preview->image().isNull() && !preview->renderer()->current().image.isNull());
        QCOMPARE(cornerAlpha(), 255);
        QVERIFY2(checkerPixels() < 50, qPrintable(QString::number(checkerPixels())));

        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QTest::keyClick(m_window.get(), Qt::Key_B, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(transparent->isChecked());
        QVERIFY(preview->renderer()->isTransparent());
        QTRY_COMPARE(cornerAlpha(), 0);
        QCOMPARE(centreAlpha(), 255); // the face stays opaque
        QVERIFY2(checkerPixels() > 1000, qPrintable(QString::number(checkerPixels())));
        QCOMPARE(Settings().transparentPreview(), true);

        tearDown();
        makeWindow();
        QVERIFY(m_window->previewView()->transparentAction()->isChecked());
        QVERIFY(m_window->previewView()->renderer()->isTransparent());
        m_window->previewView()->transparentAction()->trigger();
        QCOMPARE(Settings().transparentPreview(), false);
        QVERIFY(!m_window->previewView()->renderer()->isTransparent());
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
};

TOONFACE_TEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
