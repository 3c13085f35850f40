#pragma once

#include <QElapsedTimer>
#include <QJsonObject>
#include <QString>

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

// Runs `fn` repeatedly for at least `minMs` milliseconds (and at least `minRuns` times);
// returns the median time of one run in milliseconds.
double medianMs(const std::function<void()> &fn, int minRuns = 5, double minMs = 200);

// The research data folder (TOONFACE_DATA_DIR or ../shared/data), or empty when absent.
QString sharedDataDir();

} // namespace toonface::bench

#define TOONFACE_BENCH_CONCAT2(a, b) a##b
#define TOONFACE_BENCH_CONCAT(a, b) TOONFACE_BENCH_CONCAT2(a, b)
#define TOONFACE_BENCHMARK(name, fn)                                                                                   \
    static const toonface::bench::Registrar TOONFACE_BENCH_CONCAT(tfBench_, __LINE__)(name, fn)
