#include "i18n/translations.h"
#include "launchtimings.h"
#include "views/tonemarkfont.h"
#include "window/mainwindow.h"
#include "window/settings.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {

// For looking at the window in headless runs: TOONFACE_SCREENSHOT=out.png saves the window
// once it has been idle (nothing opening or detecting) for a moment, then quits;
// TOONFACE_SCREENSHOT_STEP=NAME shows that detection step (e.g. classic-b1) first.
void scheduleScreenshot(toonface::MainWindow &window, const QString &path, const QString &step)
{
    auto *timer = new QTimer(&window);
    timer->setInterval(500);
    auto idleTicks = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, path, step, timer, idleTicks] {
        *idleTicks = window.isBusy() ? 0 : *idleTicks + 1;
        if (*idleTicks < 3)
            return;
        timer->stop();
        if (!step.isEmpty()) {
            window.showDetectionStep(step);
            if (window.overlayStep() != step)
                qWarning("toonface: no detection step %s to show", qPrintable(step));
            QApplication::processEvents();
        }
        window.grab().save(path);
        QApplication::exit(0);
    });
    timer->start();
}

} // namespace

int main(int argc, char *argv[])
{
    QElapsedTimer clock;
    clock.start();
    // Qt takes the first thread that asks for its thread data for the main thread: claim it
    // here, before the warm-up's threads (which use Qt types) can.
    QThread::currentThread();
    // Detection's one-time work (the landmark model, the face detector) goes on in the
    // background while the application and its window start.
    toonface::warmUpDetection();
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Toonface"));
    QApplication::setApplicationName(QStringLiteral("toonface"));
    QApplication::setApplicationDisplayName(QStringLiteral("Toonface"));
    QApplication::setApplicationVersion(QStringLiteral(TOONFACE_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("toonface"));
    // The interface's language: Preferences' choice, else the system's.
    toonface::installTranslations(&app, toonface::translationForSetting(toonface::Settings().language()));
    toonface::ensureToneMarks();

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Toonface: personal cartoon faces from photos."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("file"),
        QApplication::translate("main", "A photo or a .toonface project to open."), QStringLiteral("[file]"));
    const QCommandLineOption methodOption(QStringLiteral("method"),
        QApplication::translate("main", "Detect faces with METHOD in this session: auto, classic or landmarks."),
        QStringLiteral("METHOD"));
    parser.addOption(methodOption);
    parser.process(app);
    toonface::DetectionMethod method = toonface::DetectionMethod::Auto;
    if (parser.isSet(methodOption) && !toonface::detectionMethodFromName(parser.value(methodOption), &method)) {
        std::fprintf(stderr, "toonface: error: %s\n",
            qPrintable(QApplication::translate("main", "unknown detection method \"%1\" (auto, classic or landmarks)")
                           .arg(parser.value(methodOption))));
        return 2;
    }

    toonface::MainWindow window;
    if (parser.isSet(methodOption))
        window.setDetectionMethod(method);
    window.show();
    const QStringList files = parser.positionalArguments();
    const QString file = files.isEmpty() ? QString() : QDir::current().absoluteFilePath(files.first());
    if (toonface::LaunchTimings::wanted()) {
        auto *timings = new toonface::LaunchTimings(&window, clock);
        window.startup({});
        if (!file.isEmpty())
            timings->open(file);
    } else {
        window.startup(file);
    }

    const QString screenshot = qEnvironmentVariable("TOONFACE_SCREENSHOT");
    if (!screenshot.isEmpty())
        scheduleScreenshot(window, screenshot, qEnvironmentVariable("TOONFACE_SCREENSHOT_STEP"));
    return app.exec();
}
