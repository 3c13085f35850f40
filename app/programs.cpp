#include "programs.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string>
#include <unistd.h>

namespace toonface::cli {

namespace {

// The folder of the running program (/proc/self/exe: the real file, through any symlink).
std::string ownFolder()
{
    char path[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0)
        return {};
    const std::string p(path, size_t(n));
    return p.substr(0, p.rfind('/'));
}

} // namespace

int execProgram(const char *name, char *argv[])
{
    const std::string folder = ownFolder();
    const std::string installed = folder + "/" + TOONFACE_CLI_PROGRAMS_RELATIVE + "/" + name;
    const std::string beside = folder + "/" + name;
    for (const std::string &path : {beside, installed}) {
        if (access(path.c_str(), X_OK) == 0) {
            execv(path.c_str(), argv);
            std::fprintf(stderr, "toonface-cli: error: cannot run %s: %s\n", path.c_str(), std::strerror(errno));
            return 1;
        }
    }
    std::fprintf(stderr, "toonface-cli: error: cannot find %s (nor %s): the installation is incomplete\n",
        installed.c_str(), beside.c_str());
    return 1;
}

} // namespace toonface::cli
