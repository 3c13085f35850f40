// The toonface-cli a user runs: a light program that loads only Qt Core, espeak-ng and FFmpeg's
// resampler. It runs the commands that need no more with the arguments given (Command::runsLight:
// lipsync of a plain WAV recording) and hands every other command line to the full program,
// toonface-cli-full, which it replaces with exec (same process, same arguments): loading the
// full program's libraries (FFmpeg's codecs, OpenCV, dlib, Qt Gui) alone takes ~50 ms.
#include "cli/command.h"
#include "i18n/translations.h"
#include "speech/stagetimes.h"

#include <QCoreApplication>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

using namespace toonface::cli;

namespace {

// The folder this program was started from (the build tree's or the installed one).
std::string ownFolder()
{
    char path[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0)
        return {};
    std::string p(path, size_t(n));
    return p.substr(0, p.rfind('/'));
}

// Replaces this process with toonface-cli-full: beside this program in the build tree, in
// TOONFACE_CLI_FULL_RELATIVE from it when installed. Returns only on failure, with the exit code.
int runFullProgram(char *argv[])
{
    const std::string folder = ownFolder();
    const std::string candidates[] = {
        folder + "/toonface-cli-full", folder + "/" + TOONFACE_CLI_FULL_RELATIVE + "/toonface-cli-full"};
    for (const std::string &path : candidates) {
        if (access(path.c_str(), X_OK) == 0) {
            toonface::markStage("handover");
            execv(path.c_str(), argv);
            std::fprintf(stderr, "toonface-cli: error: cannot run %s: %s\n", path.c_str(), std::strerror(errno));
            return ExitFailed;
        }
    }
    std::fprintf(stderr, "toonface-cli: error: cannot find %s (nor %s): the installation is incomplete\n",
        candidates[1].c_str(), candidates[0].c_str());
    return ExitFailed;
}

} // namespace

int main(int argc, char *argv[])
{
    QStringList args;
    for (int i = 1; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    const Command *command = findCommand(args.value(0));
    if (!command || !command->runsLight || !command->runsLight(args.mid(1)))
        return runFullProgram(argv);

    // As the full program's main does for a command that never renders.
    toonface::markStage("main");
    installQtMessageFilter();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("toonface-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TOONFACE_VERSION));
    toonface::installTranslations(&app, toonface::translationForLocale(toonface::systemUiLocale()));
    endNow(command->run(*command, args.mid(1)));
}
