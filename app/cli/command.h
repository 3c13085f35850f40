#pragma once

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <vector>

namespace toonface::cli {

// Exit codes of the command-line contract (architecture.md).
enum ExitCode {
    ExitOk = 0,
    ExitUsage = 2, // bad arguments
    ExitBadInput = 3, // unreadable or invalid input
    ExitNoFace = 4, // no face found
    ExitCannotAlign = 5, // audio and script could not be aligned
    ExitFailed = 1, // anything else (e.g. an output that cannot be written)
};

// The CLI's messages and help, translated (context "toonface::cli::Cli" of the .ts files). Its
// machine-readable output (JSON, TSV), option names and value names stay as they are.
struct Cli
{
    Q_DECLARE_TR_FUNCTIONS(toonface::cli::Cli)
};

// One subcommand: its name, a one-line summary, its usage, and the function that runs it
// with the arguments after the subcommand's name.
struct Command
{
    QString name;
    // Marked with QT_TRANSLATE_NOOP("toonface::cli::Cli", ...): the registrars run before the
    // translators are installed; translatedSummary() looks it up when it is printed.
    QString summary;
    QString usage;
    std::function<int(const Command &self, const QStringList &args)> run;
    // The command may detect a face in a photo: detection's one-time work starts in the
    // background at launch (warmUpDetection()), beside the application's own start-up.
    bool detects = false;
    // The command never renders (text, SVG, images): it runs without a GUI application, whose
    // start-up (the platform plugin, the font database) would cost more than its work.
    bool coreOnly = false;
    // Whether the command, with these arguments, runs in the light toonface-cli: without
    // FFmpeg's formats and codecs, OpenCV, dlib or Qt Gui, whose loading alone costs more than
    // a short job (app/CMakeLists.txt). Unset: always in the full program.
    std::function<bool(const QStringList &args)> runsLight = {};

    QString translatedSummary() const { return Cli::tr(summary.toUtf8().constData()); }
};

std::vector<Command> &commands();
const Command *findCommand(const QString &name);

// Qt's own diagnostics (platform plugins, runtime dirs, fonts) would break the contract that
// stderr carries one error line; they are shown only with TOONFACE_DEBUG set.
void installQtMessageFilter();

// Ends the process once a command has run, without tearing the application down: everything
// the command wrote is closed by then (files committed, streams flushed here), the warm-up's
// threads have ended (the caches are written), and the teardown would only cost time:
// QGuiApplication's destructor frees the font database, which starts fontconfig (60-70 ms)
// just to free it when no text was drawn, and freeing the landmark model and the rest
// page by page is slower than the kernel's ending of the whole process.
[[noreturn]] void endNow(int code);

struct CommandRegistrar
{
    explicit CommandRegistrar(Command command) { commands().push_back(std::move(command)); }
};

// Ctrl+C, a hang-up or a kill (SIGINT, SIGHUP, SIGTERM) asks the running job to stop: long jobs
// take interruption() as their cancel flag, so an interrupted export removes its hidden
// temporary files and writes nothing; a second signal ends the process at once.
void installInterruptHandlers();
const std::atomic_bool *interruption();
// The exit code of a job stopped by a signal (the shell's 128 + SIGINT).
constexpr int ExitInterrupted = 130;

// Prints "toonface-cli: error: <message>" on stderr and returns `code`. Control characters in
// the message (a crafted file name) are shown as escapes, never sent to the terminal.
int fail(int code, const QString &message);
// Prints "toonface-cli: warning: <message>" on stderr: the job goes on, differently from what was asked.
void warn(const QString &message);
// Prints "toonface-cli: <message>" on stderr: something the job chose for the user that they may
// want to choose otherwise (always printed, unlike progress lines).
void note(const QString &message);
// Prints a progress line on stderr (only when stderr is a terminal or --progress was given).
void progress(const QString &message);
// A long job's progress as lines "<stage>: N %" (progress()): one when a stage begins, then as
// the whole percent rises, at most one a second (an hour-long job prints a line a second, not
// thousands), and at 100 %.
class StageProgress
{
public:
    void operator()(double fraction, const QString &stage);

private:
    QString m_stage;
    int m_percent = -1;
    QElapsedTimer m_clock;
};

// Parses `args` for `command` with `parser` (options already added). On failure prints the
// error and returns false; the caller returns ExitUsage. `--help` prints help and sets *helped.
bool parseArguments(QCommandLineParser &parser, const Command &command, const QStringList &args, bool *helped);

// Writes `data` atomically to `path` (QSaveFile); on failure sets *error naming the file.
bool writeFileAtomically(const QString &path, const QByteArray &data, QString *error);
// A command's result: written atomically to the file of the `output` option when it is set,
// else to stdout. Returns ExitOk, or prints the error line and returns ExitFailed.
int writeOutput(const QCommandLineParser &parser, const QCommandLineOption &output, const QByteArray &data);

} // namespace toonface::cli
