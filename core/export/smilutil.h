#pragma once

#include "export/smilexport.h"

#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <numeric>
#include <vector>

// Helpers shared by the parts of the SMIL export (smilexport.cpp and the files it uses).
namespace toonface::smil {

inline constexpr const char *kNamespace = "urn:toonface:animation:1";

inline bool cancelled(const AnimationExportOptions &options)
{
    return options.cancel && options.cancel->load();
}

inline void report(const AnimationExportOptions &options, double fraction)
{
    if (options.progress)
        options.progress(std::clamp(fraction, 0.0, 1.0));
}

// Runs f(i) for i in [0, n) on the global thread pool (inline for small n).
template<class F>
void forEachParallel(qsizetype n, const F &f)
{
    if (n < 16) {
        for (qsizetype i = 0; i < n; ++i)
            f(i);
        return;
    }
    std::vector<qsizetype> indices(static_cast<size_t>(n));
    std::iota(indices.begin(), indices.end(), qsizetype(0));
    QtConcurrent::blockingMap(indices, [&f](qsizetype &i) { f(i); });
}

} // namespace toonface::smil
