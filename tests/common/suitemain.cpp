// The main of a folder's test program (testmain.h): runs the suite named first on the command
// line; without a name, or with one it does not know, lists its suites.
#include "testmain.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Suite
{
    std::string name;
    toonface::test::SuiteMain main;
};

std::vector<Suite> &suites()
{
    static std::vector<Suite> all;
    return all;
}

QString running;

int listSuites(const char *program)
{
    std::fprintf(stderr, "usage: %s SUITE [QtTest options]\nsuites:\n", program);
    for (const Suite &suite : suites())
        std::fprintf(stderr, "  %s\n", suite.name.c_str());
    return 2;
}

} // namespace

namespace toonface::test {

int registerSuite(const char *sourceFile, SuiteMain main)
{
    std::string name = sourceFile;
    const std::size_t slash = name.find_last_of("/\\");
    if (slash != std::string::npos)
        name.erase(0, slash + 1);
    const std::size_t dot = name.find('.');
    if (dot != std::string::npos)
        name.erase(dot);
    suites().push_back({name, main});
    return int(suites().size());
}

QStringList suiteArguments()
{
    return {running};
}

} // namespace toonface::test

int main(int argc, char *argv[])
{
    if (argc < 2)
        return listSuites(argv[0]);
    for (const Suite &suite : suites()) {
        if (suite.name != argv[1])
            continue;
        running = QString::fromStdString(suite.name);
        // The suite sees the program's name and the arguments after its own name.
        std::vector<char *> arguments {argv[0]};
        arguments.insert(arguments.end(), argv + 2, argv + argc);
        arguments.push_back(nullptr);
        return suite.main(argc - 1, arguments.data());
    }
    std::fprintf(stderr, "%s: no suite named \"%s\"\n", argv[0], argv[1]);
    return listSuites(argv[0]);
}
