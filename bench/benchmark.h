#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace toonface::bench {

// One benchmark: a name and a function that measures and returns its figures as JSON.
struct Benchmark
{
    QString name;
    std::function<QJsonObject()> run;
};

std::vector<Benchmark> &registry();

struct Registrar
{
    Registrar(const char *name, std::function<QJsonObject()> run)
    {
        registry().push_back({QString::fromLatin1(name), std::move(run)});
    }
};

// A measurement that needs a process of its own (the first detection is first only once per
// process): `toonface-bench --child NAME ARGS...` runs it and prints its JSON on stdout.
struct Child
{
    QString name;
    std::function<QJsonObject(const QStringList &args)> run;
};

std::vector<Child> &children();

struct ChildRegistrar
{
    ChildRegistrar(const char *name, std::function<QJsonObject(const QStringList &args)> run)
    {
        children().push_back({QString::fromLatin1(name), std::move(run)});
    }
};

// Runs the child measurement `name` in a new process of this executable with `args` and the
// extra environment `env` ("NAME=value" entries); its JSON, or {"error": ...}.
QJsonObject runChild(const QString &name, const QStringList &args, const QStringList &env = {});

// One run of a program in a process of its own, measured alone (wait4): wall and CPU time,
// its own peak memory, and what it wrote on stderr when asked for.
struct ChildRun
{
    double wallMs = 0, cpuMs = 0, peakMb = 0;
    bool ok = false; // exited with 0
    int exitCode = -1; // its exit code, or -1 when a signal ended it
    double startedMs = 0; // CLOCK_MONOTONIC in ms just before the process was started
    QByteArray stderrText; // when keepStderr
};

// Runs `program` with `args` and the extra environment `env` ("NAME=value" entries); its
// stdout is dropped, its stderr too unless `keepStderr`.
ChildRun runMeasured(
    const QString &program, const QStringList &args, const QStringList &env = {}, bool keepStderr = false);

// {"loadAverage1min": the machine's load average now}: CPU times are comparable only with it
// (on a loaded machine a process's CPU time grows as it waits on shared caches and cores).
QJsonObject loadAverage();

// Runs `fn` repeatedly for at least `minMs` milliseconds (and at least `minRuns` times);
// returns the median time of one run in milliseconds.
double medianMs(const std::function<void()> &fn, int minRuns = 5, double minMs = 200);

// The research data folder (TOONFACE_DATA_DIR or ../shared/data), or empty when absent.
QString sharedDataDir();
// The GRID clips of shared/data/video (absolute paths, by name); empty when they are absent.
QStringList gridClips();
inline constexpr const char *kGridClipsAbsent = "the GRID clips of shared/data/video are absent";

} // namespace toonface::bench

#define TOONFACE_BENCH_CONCAT2(a, b) a##b
#define TOONFACE_BENCH_CONCAT(a, b) TOONFACE_BENCH_CONCAT2(a, b)
#define TOONFACE_BENCH_CHILD(name, fn)                                                                                 \
    static const toonface::bench::ChildRegistrar TOONFACE_BENCH_CONCAT(tfChild_, __LINE__)(name, fn)
#define TOONFACE_BENCHMARK(name, fn)                                                                                   \
    static const toonface::bench::Registrar TOONFACE_BENCH_CONCAT(tfBench_, __LINE__)(name, fn)
