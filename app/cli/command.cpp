#include "cli/command.h"

#include <QSaveFile>
#include <QTextStream>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace toonface::cli {

std::vector<Command> &commands()
{
    static std::vector<Command> list;
    return list;
}

const Command *findCommand(const QString &name)
{
    for (const Command &c : commands()) {
        if (c.name == name)
            return &c;
    }
    return nullptr;
}

namespace {

void qtMessages(QtMsgType type, const QMessageLogContext &, const QString &message)
{
    if (type == QtFatalMsg || type == QtCriticalMsg || qEnvironmentVariableIsSet("TOONFACE_DEBUG"))
        QTextStream(stderr) << "toonface-cli: qt: " << message << Qt::endl;
}

} // namespace

void installQtMessageFilter()
{
    qInstallMessageHandler(qtMessages);
}

void endNow(int code)
{
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(code);
}

namespace {

std::atomic_bool interrupted = false;

void onSignal(int)
{
    if (interrupted.exchange(true))
        std::_Exit(ExitInterrupted); // asked twice: the job did not stop in time
}

// A message as one printable line: control characters (an escape sequence hidden in a file
// name or a project's field) written as \xNN.
QString printable(const QString &message)
{
    QString out;
    out.reserve(message.size());
    for (const QChar c : message) {
        if (c.category() == QChar::Other_Control || c.category() == QChar::Other_Format)
            out += QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out;
}

} // namespace

void installInterruptHandlers()
{
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGHUP, SIGTERM})
        sigaction(signal, &action, nullptr);
}

const std::atomic_bool *interruption()
{
    return &interrupted;
}

int fail(int code, const QString &message)
{
    QTextStream(stderr) << "toonface-cli: error: " << printable(message) << Qt::endl;
    return code;
}

void warn(const QString &message)
{
    QTextStream(stderr) << "toonface-cli: warning: " << printable(message) << Qt::endl;
}

void note(const QString &message)
{
    QTextStream(stderr) << "toonface-cli: " << printable(message) << Qt::endl;
}

void progress(const QString &message)
{
    if (isatty(fileno(stderr)) || qEnvironmentVariableIsSet("TOONFACE_PROGRESS"))
        QTextStream(stderr) << "toonface-cli: " << message << Qt::endl;
}

void StageProgress::operator()(double fraction, const QString &stage)
{
    const int percent = int(std::clamp(fraction, 0.0, 1.0) * 100);
    const bool newStage = stage != m_stage;
    if (!newStage && (percent <= m_percent || (percent < 100 && m_clock.isValid() && m_clock.elapsed() < 1000)))
        return;
    progress(Cli::tr("%1: %2 %").arg(stage).arg(percent));
    m_stage = stage;
    m_percent = percent;
    m_clock.start();
}

bool parseArguments(QCommandLineParser &parser, const Command &command, const QStringList &args, bool *helped)
{
    *helped = false;
    const QCommandLineOption help(
        QStringList {QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help."));
    parser.addOption(help);
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    QStringList full = args;
    full.prepend(QStringLiteral("toonface-cli ") + command.name);
    if (!parser.parse(full)) {
        fail(ExitUsage,
            Cli::tr("%1 (usage: %2)").arg(parser.errorText(), QStringLiteral("toonface-cli ") + command.usage));
        return false;
    }
    if (parser.isSet(help)) {
        QTextStream out(stdout);
        out << Cli::tr("Usage: %1").arg(QStringLiteral("toonface-cli ") + command.usage) << "\n\n"
            << command.translatedSummary() << "\n\n";
        out << parser.helpText().section(QLatin1Char('\n'), 2);
        *helped = true;
    }
    return true;
}

int writeOutput(const QCommandLineParser &parser, const QCommandLineOption &output, const QByteArray &data)
{
    if (!parser.isSet(output)) {
        QTextStream(stdout) << data;
        return ExitOk;
    }
    QString error;
    if (!writeFileAtomically(parser.value(output), data, &error))
        return fail(ExitFailed, error);
    return ExitOk;
}

bool writeFileAtomically(const QString &path, const QByteArray &data, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        *error = Cli::tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace toonface::cli
