#pragma once

// What the main window's suites share (tst_mainwindow: files, menus and the window;
// tst_detectionflow: detection of the photo): a window made per test with its own recovery
// directory and settings, a portrait and a saved project, and answers to message boxes.

#include "uifixture.h"

#include "capture/livewindow.h"
#include "detect/detector.h"
#include "dialogs/manualdialog.h"
#include "document/autosaver.h"
#include "playback/playhead.h"
#include "timeline/timelinewidget.h"
#include "views/photoview.h"
#include "views/pointhandle.h"
#include "views/previewview.h"
#include "views/stepimagedialog.h"
#include "window/applydetection.h"
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
#include <QPointer>
#include <QRegularExpression>
#include <QScreen>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QTransform>
#include <QUndoStack>
#include <QUrl>
#include <QWidgetAction>
#include <QWindow>
#include <QXmlStreamReader>

#include <csignal>

#include <sys/resource.h>
#include <unistd.h>

namespace toonface::mainwindowfixture {

inline const QString kPortrait = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");

// Answers the next message box by clicking the button whose text contains `button`
// (mnemonic ampersands ignored). Returns a flag that turns true once it has answered.
inline std::shared_ptr<bool> answerNextMessageBox(const QString &button)
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

// The base of the suites: no test slots of its own (each suite calls setUpCase(), setUpTest() and
// tearDown() from its initTestCase(), init() and cleanup()).
class MainWindowTestBase : public QObject
{
protected:
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

    void setUpCase()
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

    void setUpTest()
    {
        QSettings().clear();
        m_recoveryDir = std::make_unique<QTemporaryDir>();
    }

    void tearDown()
    {
        if (m_window)
            m_window->document()->undoStack()->setClean(); // close without asking
        m_window.reset();
    }
};

} // namespace toonface::mainwindowfixture
