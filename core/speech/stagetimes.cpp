#include "speech/stagetimes.h"

#include <QtGlobal>

#include <cstdio>
#include <ctime>

namespace toonface {

void markStage(const char *stage)
{
    static const bool wanted = qEnvironmentVariableIsSet("TOONFACE_TIMINGS");
    if (!wanted)
        return;
    timespec now {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    std::fprintf(stderr, "toonface: timing: %s %.3f\n", stage, double(now.tv_sec) * 1e3 + double(now.tv_nsec) / 1e6);
}

} // namespace toonface
