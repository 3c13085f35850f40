// The main window's arrangement on a laptop's screen, its dock toggles and its keys.
#include "testmain.h"
#include "timelinefixture.h"
#include "uifixture.h"

#include "dialogs/shortcutsdialog.h"
#include "document/document.h"
#include "timeline/timelineview.h"
#include "timeline/timelinewidget.h"
#include "views/photoview.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using namespace toonface;

namespace {

QMenu *menuTitled(const QMainWindow &window, const QString &title)
{
    for (QAction *a : window.menuBar()->actions())
        if (a->menu() && a->text().remove(QLatin1Char('&')) == title)
            return a->menu();
    return nullptr;
}

} // namespace

class TestWindowLayout : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;

private Q_SLOTS:
    void initTestCase()
    {
        fixture::isolateSettings();
        QVERIFY(m_dir.isValid());
    }

    void init()
    {
        MainWindow::Options options;
        options.preloadLandmarkModel = false;
        options.recoveryDirectory = m_dir.path();
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void cleanup() { m_window.reset(); }

    void laptopScreenLeavesThePhotoRoom_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::newRow("1280x720") << QSize(1280, 720 - 60);
        QTest::newRow("1600x1000") << QSize(1600, 1000 - 60);
    }

    void laptopScreenLeavesThePhotoRoom()
    {
        QFETCH(QSize, size);
        m_window->resize(size);
        QTest::qWait(50);
        auto *reset = m_window->findChild<QAction *>(QStringLiteral("actionResetLayout"));
        QVERIFY(reset);
        reset->trigger();
        QTest::qWait(100);
        auto *photo = m_window->findChild<PhotoView *>(QStringLiteral("photoView"));
        auto *timeline = m_window->findChild<QDockWidget *>(QStringLiteral("timelineDock"));
        auto *appearance = m_window->findChild<QDockWidget *>(QStringLiteral("appearanceDock"));
        QVERIFY(photo && timeline && appearance);
        const QString sizes = QStringLiteral("photo %1x%2, timeline %3 high, appearance %4 wide")
                                  .arg(photo->width())
                                  .arg(photo->height())
                                  .arg(timeline->height())
                                  .arg(appearance->width());
        // The photo and the cartoon are the work: at least 40 % of the height, a third of the width.
        QVERIFY2(photo->height() >= size.height() * 0.4, qPrintable(sizes));
        QVERIFY2(photo->width() >= size.width() / 4, qPrintable(sizes));
        // The timeline is never taller than its rows.
        auto *view = timeline->findChild<TimelineWidget *>()->view();
        QVERIFY2(view->height() <= view->sizeHint().height() + 2 * view->frameWidth(), qPrintable(sizes));
        // The Appearance dock scrolls vertically only.
        auto *scroll = appearance->findChild<QScrollArea *>(QStringLiteral("appearanceScroll"));
        QVERIFY(scroll);
        QVERIFY2(!scroll->horizontalScrollBar()->isVisible(), qPrintable(sizes));
        QVERIFY2(scroll->widget()->width() >= scroll->widget()->minimumSizeHint().width(), qPrintable(sizes));
        if (!qEnvironmentVariableIsEmpty("TOONFACE_GRAB_DIR"))
            m_window->grab().save(
                qEnvironmentVariable("TOONFACE_GRAB_DIR") + QStringLiteral("/layout-%1.png").arg(size.width()));
    }

    // Issue 26: on a 1280 x 720 screen, with a photo and a recording open, every row of the
    // timeline shows without scrolling (compact if need be), the photo still the work.
    void everyTimelineRowShowsAt720()
    {
        const QSize size(1280, 720 - 60); // a desktop's panel and the title bar take the rest
        m_window->resize(size);
        Document *doc = m_window->document();
        fixture::fill(*doc);
        Animation a = fixture::talkingAnimation();
        a.timeline.setAudioClips({AudioClip {m_dir.filePath(QStringLiteral("talk.wav")), 0, fixture::kTalkDuration}});
        doc->changeAnimation(a, QStringLiteral("Lip Sync"));
        QTest::qWait(50);
        m_window->findChild<QAction *>(QStringLiteral("actionResetLayout"))->trigger();
        QTest::qWait(100);
        auto *view = m_window->findChild<TimelineWidget *>()->view();
        const QRect viewport = view->viewport()->rect();
        for (const TimelineRow &row : view->timelineLayout().rows()) {
            const QRect r = view->timelineLayout().rowRect(row.kind, viewport.width());
            QVERIFY2(viewport.contains(r),
                qPrintable(QStringLiteral("%1: rows %2-%3, viewport %4 high")
                               .arg(rowTitle(row.kind))
                               .arg(r.top())
                               .arg(r.bottom())
                               .arg(viewport.height())));
        }
        QCOMPARE(view->verticalScrollBar()->maximum(), 0);
        auto *photo = m_window->findChild<PhotoView *>(QStringLiteral("photoView"));
        QVERIFY2(photo->height() >= size.height() * 0.4, qPrintable(QString::number(photo->height())));
        if (!qEnvironmentVariableIsEmpty("TOONFACE_GRAB_DIR"))
            m_window->grab().save(qEnvironmentVariable("TOONFACE_GRAB_DIR") + QStringLiteral("/rows-720.png"));
    }

    void viewTogglesTheDocks()
    {
        QMenu *view = menuTitled(*m_window, QStringLiteral("View"));
        QVERIFY(view);
        for (const char *name : {"appearanceDock", "timelineDock"}) {
            auto *dock = m_window->findChild<QDockWidget *>(QString::fromLatin1(name));
            QVERIFY(dock);
            QVERIFY2(view->actions().contains(dock->toggleViewAction()), name);
            dock->toggleViewAction()->trigger();
            QVERIFY(dock->isHidden());
        }
        m_window->findChild<QAction *>(QStringLiteral("actionResetLayout"))->trigger();
        for (const char *name : {"appearanceDock", "timelineDock"})
            QVERIFY2(m_window->findChild<QDockWidget *>(QString::fromLatin1(name))->isVisible(), name);
    }

    void everyKeyIsBoundOnce()
    {
        // A key bound twice where both act does nothing at all (Qt finds it ambiguous).
        QHash<QKeySequence, QString> seen;
        for (QAction *action : m_window->findChildren<QAction *>()) {
            for (const QKeySequence &key : action->shortcuts()) {
                const QString name = action->text();
                QVERIFY2(!seen.contains(key),
                    qPrintable(QStringLiteral("%1: %2 and %3").arg(key.toString(), seen.value(key), name)));
                seen.insert(key, name);
            }
        }
    }

    void keyboardShortcutsListsTheMenus()
    {
        QMenu *help = menuTitled(*m_window, QStringLiteral("Help"));
        QVERIFY(help);
        auto *shortcuts = m_window->findChild<QAction *>(QStringLiteral("actionShortcuts"));
        QVERIFY(shortcuts);
        QVERIFY2(help->actions().contains(shortcuts), qPrintable(shortcuts->parent()->objectName()));
        ShortcutsDialog dialog(m_window->menuBar());
        auto *tree = dialog.findChild<QTreeWidget *>(QStringLiteral("shortcuts"));
        QVERIFY(tree);
        const QList<QTreeWidgetItem *> open
            = tree->findItems(QStringLiteral("Open Photo or Project"), Qt::MatchRecursive);
        QCOMPARE(open.size(), 1);
        QCOMPARE(open.first()->text(1), QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText));
        QVERIFY(!tree->findItems(QStringLiteral("Lip Sync from Recording"), Qt::MatchRecursive).isEmpty());
    }
};

TOONFACE_TEST_MAIN(TestWindowLayout)
#include "tst_windowlayout.moc"
