#include "benchmark.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QProcess>
#include <QTextStream>
#include <QThread>

#include <QTemporaryFile>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

extern char **environ;

namespace toonface::bench {

std::vector<Benchmark> &registry()
{
    static std::vector<Benchmark> r;
    return r;
}

std::vector<Child> &children()
{
    static std::vector<Child> c;
    return c;
}

QJsonObject runChild(const QString &name, const QStringList &args, const QStringList &env)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const QString &entry : env)
        environment.insert(entry.section(QLatin1Char('='), 0, 0), entry.section(QLatin1Char('='), 1));
    process.setProcessEnvironment(environment);
    process.start(QCoreApplication::applicationFilePath(), QStringList {QStringLiteral("--child"), name} + args);
    if (!process.waitForFinished(300000) || process.exitCode() != 0)
        return {{QStringLiteral("error"), QString::fromLocal8Bit(process.readAllStandardError()).trimmed()}};
    return QJsonDocument::fromJson(process.readAllStandardOutput()).object();
}

ChildRun runMeasured(const QString &program, const QStringList &args, const QStringList &env, bool keepStderr)
{
    std::vector<QByteArray> bytes {QFile::encodeName(program)};
    for (const QString &a : args)
        bytes.push_back(a.toLocal8Bit());
    std::vector<char *> argv;
    for (QByteArray &b : bytes)
        argv.push_back(b.data());
    argv.push_back(nullptr);
    // The extra entries replace those of the same name.
    std::vector<QByteArray> envBytes;
    for (const QString &e : env)
        envBytes.push_back(e.toLocal8Bit());
    const size_t extra = envBytes.size();
    for (char **e = environ; *e; ++e) {
        const QByteArray entry(*e);
        const QByteArray name = entry.left(entry.indexOf('=') + 1);
        if (std::none_of(envBytes.begin(), envBytes.begin() + qsizetype(extra),
                [&](const QByteArray &x) { return x.startsWith(name); }))
            envBytes.push_back(entry);
    }
    std::vector<char *> envp;
    for (QByteArray &e : envBytes)
        envp.push_back(e.data());
    envp.push_back(nullptr);
    ChildRun r;
    QTemporaryFile errors;
    if (keepStderr && !errors.open())
        return r;
    timespec now {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    r.startedMs = double(now.tv_sec) * 1e3 + double(now.tv_nsec) / 1e6;
    QElapsedTimer t;
    t.start();
    const pid_t pid = fork();
    if (pid == 0) {
        const int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, 1);
        dup2(keepStderr ? errors.handle() : devnull, 2);
        execve(argv[0], argv.data(), envp.data());
        _exit(127);
    }
    int status = 0;
    rusage usage {};
    if (pid < 0 || wait4(pid, &status, 0, &usage) != pid)
        return r;
    r.wallMs = double(t.nsecsElapsed()) / 1e6;
    r.cpuMs = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3
        + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e3;
    r.peakMb = double(usage.ru_maxrss) / 1024.0;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.ok = r.exitCode == 0;
    if (keepStderr) {
        errors.seek(0);
        r.stderrText = errors.readAll();
    }
    return r;
}

QJsonObject loadAverage()
{
    QJsonObject o;
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) > 0)
        o.insert(QStringLiteral("loadAverage1min"), std::round(load[0] * 100) / 100);
    return o;
}

double medianMs(const std::function<void()> &fn, int minRuns, double minMs)
{
    std::vector<double> times;
    QElapsedTimer total;
    total.start();
    while (int(times.size()) < minRuns || total.elapsed() < minMs) {
        QElapsedTimer t;
        t.start();
        fn();
        times.push_back(t.nsecsElapsed() / 1e6);
        if (times.size() > 100000)
            break;
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

QString sharedDataDir()
{
    QString dir = qEnvironmentVariable("TOONFACE_DATA_DIR");
    if (dir.isEmpty())
        dir = QStringLiteral(TOONFACE_SHARED_DATA);
    return QFileInfo(dir).isDir() ? QDir(dir).absolutePath() : QString();
}

QStringList gridClips()
{
    if (sharedDataDir().isEmpty())
        return {};
    const QDir dir(sharedDataDir() + QStringLiteral("/video"));
    QStringList paths;
    for (const QString &name : dir.entryList({QStringLiteral("*.mpg")}, QDir::Files, QDir::Name))
        paths << dir.filePath(name);
    return paths;
}

} // namespace toonface::bench

// Usage: toonface-bench [NAME-SUBSTRING ...]; prints one JSON object with each benchmark's
// figures and the machine it ran on.
int main(int argc, char *argv[])
{
    // A child measurement sets up its process itself (before any application object).
    if (argc >= 3 && qstrcmp(argv[1], "--child") == 0) {
        QStringList args;
        for (int i = 3; i < argc; ++i)
            args << QString::fromLocal8Bit(argv[i]);
        for (const auto &c : toonface::bench::children()) {
            if (c.name == QLatin1StringView(argv[2])) {
                QTextStream(stdout) << QJsonDocument(c.run(args)).toJson(QJsonDocument::Compact) << Qt::endl;
                return 0;
            }
        }
        QTextStream(stderr) << "no child measurement " << argv[2] << Qt::endl;
        return 2;
    }
    // The benchmarks paint off screen: with no display they need none (and the measurements
    // are the same).
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY")
        && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv); // the timeline benchmarks paint widgets
    const QStringList filters = app.arguments().mid(1);
    QJsonObject results;
    for (const auto &b : toonface::bench::registry()) {
        if (!filters.isEmpty()
            && std::none_of(filters.begin(), filters.end(), [&](const QString &f) { return b.name.contains(f); }))
            continue;
        QTextStream(stderr) << "running " << b.name << Qt::endl;
        results.insert(b.name, b.run());
    }
    QJsonObject machine;
    machine.insert(QStringLiteral("cores"), QThread::idealThreadCount());
    machine.insert(QStringLiteral("cpu"), QSysInfo::currentCpuArchitecture());
    machine.insert(QStringLiteral("os"), QSysInfo::prettyProductName());
    QJsonObject out;
    out.insert(QStringLiteral("machine"), machine);
    out.insert(QStringLiteral("benchmarks"), results);
    QTextStream(stdout) << QJsonDocument(out).toJson(QJsonDocument::Indented);
    return 0;
}
