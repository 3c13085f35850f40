#pragma once

// toonface-cli is three programs (app/CMakeLists.txt): the launcher users run, the light
// program and the full one. The launcher and the light program find the others beside
// themselves (the build tree) or in TOONFACE_CLI_PROGRAMS_RELATIVE from their folder (installed),
// and replace themselves with them. Plain C++: the launcher loads no library but the C++ runtime.
namespace toonface::cli {

// Replaces this process with the program `name` (e.g. "toonface-cli-full") given `argv`
// (argv[0] kept). Returns only on failure, after printing the error line naming the file
// looked for; the result is the exit code (1).
int execProgram(const char *name, char *argv[]);

} // namespace toonface::cli
