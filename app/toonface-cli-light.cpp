// toonface-cli-light: the commands that need no more than Qt Core, espeak-ng and FFmpeg's
// resampler (Command::runsLight: lipsync of a plain WAV recording), started by toonface-cli's
// launcher (app/toonface-cli-launcher.cpp). A command line it cannot run after all (the
// launcher's quick reading of the arguments differs from the command's parser) is handed to
// toonface-cli-full.
#include "cli/command.h"
#include "i18n/translations.h"
#include "programs.h"
#include "speech/stagetimes.h"

#include <QCoreApplication>

using namespace toonface::cli;

int main(int argc, char *argv[])
{
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const Command *command = findCommand(args.value(0));
    if (!command || !command->runsLight || !command->runsLight(args.mid(1)))
        return execProgram("toonface-cli-full", argv);

    // As the full program's main does for a command that never renders.
    toonface::markStage("main");
    installQtMessageFilter();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("toonface-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TOONFACE_VERSION));
    toonface::installTranslations(&app, toonface::translationForLocale(toonface::systemUiLocale()));
    endNow(command->run(*command, args.mid(1)));
}
