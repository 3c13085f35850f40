#include "cli/command.h"
#include "detect/detector.h"
#include "i18n/translations.h"
#include "speech/stagetimes.h"

#include <QGuiApplication>
#include <QTextStream>
#include <QThread>

#include <algorithm>
#include <memory>

using namespace toonface::cli;

namespace {

void printHelp()
{
    QTextStream out(stdout);
    out << Cli::tr("Usage: %1").arg(QStringLiteral("toonface-cli COMMAND [OPTIONS]")) << "\n\n"
        << Cli::tr("Toonface turns a photo into a personal cartoon face drawn in SVG and makes it talk.\n"
                   "Every job of the editor, with no display.")
        << "\n\n"
        << Cli::tr("Commands:") << "\n";
    auto list = commands();
    std::sort(list.begin(), list.end(), [](const Command &a, const Command &b) { return a.name < b.name; });
    for (const Command &c : list)
        out << "  " << c.usage << "\n      " << c.translatedSummary() << "\n";
    out << "\n  toonface-cli COMMAND --help   " << Cli::tr("options of one command") << "\n"
        << "  toonface-cli --version        " << Cli::tr("the version") << "\n\n"
        << Cli::tr("Exit codes: 0 success, 2 usage, 3 unreadable or invalid input, 4 no face found,\n"
                   "5 the audio and the script could not be aligned, 1 other failures.")
        << "\n";
}

// Whether the arguments of a detecting command may lead to the landmark method: not for
// help, nor with --method classic, nor when the input is a face JSON or a project (their
// points are given). A guess before the command parses its options (an argument right after
// an option is taken for its value, not for the input): a wrong one costs only time.
bool mayUseLandmarks(const QStringList &args)
{
    for (int i = 1; i < args.size(); ++i) {
        const QString &a = args[i];
        if (a == QLatin1StringView("--help") || a == QLatin1StringView("-h")
            || a == QLatin1StringView("--method=classic")
            || (a == QLatin1StringView("--method") && args.value(i + 1) == QLatin1StringView("classic")))
            return false;
        const bool input = !a.startsWith(QLatin1Char('-')) && (i == 1 || !args[i - 1].startsWith(QLatin1Char('-')));
        if (input && (a.endsWith(QLatin1StringView(".json")) || a.endsWith(QLatin1StringView(".toonface"))))
            return false;
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    toonface::markStage("main");
    installQtMessageFilter();
    // Read the arguments before QGuiApplication consumes the ones it knows (--style among them).
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    // A command that will detect a face starts loading detection's models now, on the other
    // core, while the application starts and the photo is read (its detection follows at once
    // and does the rest of the first-time work itself: bench startup.firstVsTenth).
    // Qt takes the first thread that asks for its thread data for the main thread: claim it
    // before the warm-up's threads (which use Qt types) can.
    QThread::currentThread();
    if (const Command *command = findCommand(args.value(0)); command && command->detects && mayUseLandmarks(args))
        toonface::warmUpDetectionModels();
    // Rendering text and SVG needs a GUI application, but never a display.
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const Command *wanted = findCommand(args.value(0));
    std::unique_ptr<QCoreApplication> app;
    if (wanted && wanted->coreOnly)
        app = std::make_unique<QCoreApplication>(argc, argv);
    else
        app = std::make_unique<QGuiApplication>(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("toonface-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TOONFACE_VERSION));
    // Messages and help in the system's language (LANGUAGE, LC_ALL, LC_MESSAGES, LANG).
    toonface::installTranslations(app.get(), toonface::translationForLocale(toonface::systemUiLocale()));

    if (args.isEmpty())
        return fail(ExitUsage, Cli::tr("no command given; try 'toonface-cli --help'"));
    const QString first = args.takeFirst();
    if (first == QLatin1StringView("--help") || first == QLatin1StringView("-h")
        || first == QLatin1StringView("help")) {
        printHelp();
        return ExitOk;
    }
    if (first == QLatin1StringView("--version") || first == QLatin1StringView("-v")) {
        QTextStream(stdout) << "toonface-cli " << TOONFACE_VERSION << Qt::endl;
        return ExitOk;
    }
    if (const Command *command = findCommand(first)) {
        installInterruptHandlers();
        const int code = command->run(*command, args);
        toonface::waitForDetectionWarmUp();
        endNow(code);
    }
    return fail(ExitUsage, Cli::tr("unknown command '%1'; try 'toonface-cli --help'").arg(first));
}
