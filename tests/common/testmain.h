// A suite's entry point in its folder's test program (tests/CMakeLists.txt): the suites of a
// folder link into one program, `tests_FOLDER tst_NAME [QtTest options]` runs one of them, and
// ctest runs each in a process of its own. TOONFACE_TEST_MAIN, TOONFACE_TEST_GUILESS_MAIN and
// TOONFACE_TEST_APPLESS_MAIN stand for QtTest's QTEST_MAIN, QTEST_GUILESS_MAIN and
// QTEST_APPLESS_MAIN, with the same application object; the suite takes its file's name.
#pragma once

#include <QStringList>
#include <QTest>

namespace toonface::test {

using SuiteMain = int (*)(int argc, char *argv[]);

// Registers the suite of the file `sourceFile` (its name without the extension: tst_x) with
// the program's main, which runs the suite named first on the command line, the arguments
// after that name handed to it. Returns a number to initialise a variable with.
int registerSuite(const char *sourceFile, SuiteMain main);

// The arguments that make this program run the running suite again, for a suite that starts
// itself as a child process: its name.
QStringList suiteArguments();

} // namespace toonface::test

#define TOONFACE_TEST_REGISTER(mainFunction)                                                                           \
    namespace {                                                                                                        \
    const int toonfaceSuiteRegistered = toonface::test::registerSuite(__FILE__, &mainFunction);                        \
    }

#define TOONFACE_TEST_MAIN_WRAPPER(TestObject, ...)                                                                    \
    namespace {                                                                                                        \
    int toonfaceSuiteMain(int argc, char *argv[])                                                                      \
    {                                                                                                                  \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                             \
        __VA_ARGS__                                                                                                    \
        TestObject tc;                                                                                                 \
        QTEST_SET_MAIN_SOURCE_PATH                                                                                     \
        return QTest::qExec(&tc, argc, argv);                                                                          \
    }                                                                                                                  \
    }                                                                                                                  \
    TOONFACE_TEST_REGISTER(toonfaceSuiteMain)

#define TOONFACE_TEST_MAIN(TestObject) TOONFACE_TEST_MAIN_WRAPPER(TestObject, QTEST_MAIN_SETUP())
#define TOONFACE_TEST_GUILESS_MAIN(TestObject)                                                                         \
    TOONFACE_TEST_MAIN_WRAPPER(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
#define TOONFACE_TEST_APPLESS_MAIN(TestObject) TOONFACE_TEST_MAIN_WRAPPER(TestObject)
