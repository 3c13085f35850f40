#include "benchmark.h"

#include <QDir>
#include <QFileInfo>
#include <QApplication>
#include <QJsonDocument>
#include <QTextStream>
#include <QThread>

#include <algorithm>

namespace toonface::bench {

std::vector<Benchmark> &registry()
{
    static std::vector<Benchmark> r;
    return r;
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
