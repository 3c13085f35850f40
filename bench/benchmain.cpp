#include "benchmark.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QProcess>
#include <QTextStream>
#include <QThread>

#include <algorithm>

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
