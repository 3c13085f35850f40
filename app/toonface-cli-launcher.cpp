// toonface-cli, the program users run: a launcher that loads nothing but the C++ runtime and
// replaces itself (exec: same process, same arguments) with the program that runs the command
// line. lipsync of a plain WAV recording goes to toonface-cli-light (Qt Core, espeak-ng and
// FFmpeg's resampler); every other command line to toonface-cli-full, whose libraries (FFmpeg's
// codecs, OpenCV, dlib, Qt Gui) alone take ~50 ms to load. The choice here is a quick reading of
// the arguments; the light program checks it with the command's own parser and hands anything
// it cannot run to the full program itself.
#include "programs.h"
#include "speech/wavheader.h"

#include <cstring>
#include <string>
#include <sys/stat.h>

namespace {

// Whether lipsync's arguments name a recording the light program reads: the last --audio's
// value (as `--audio X`, `-audio X`, `--audio=X` or `-audio=X`) is a plain PCM WAV file, or no
// file at all (the light program reports that as the full one does).
bool lipsyncRunsLight(int argc, char *argv[])
{
    const char *audio = nullptr;
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i];
        if (a.rfind("--", 0) == 0)
            a.erase(0, 2);
        else if (a.rfind('-', 0) == 0)
            a.erase(0, 1);
        else
            continue;
        if (a == "audio" && i + 1 < argc)
            audio = argv[++i];
        else if (a.rfind("audio=", 0) == 0)
            audio = argv[i] + std::strlen(argv[i]) - (a.size() - 6);
        else if ((a == "script" || a == "lang" || a == "o" || a == "output") && i + 1 < argc)
            ++i; // its value
    }
    if (!audio)
        return true;
    struct stat st
    {
    };
    if (stat(audio, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size == 0)
        return true;
    return toonface::probePlainWav(audio).has_value();
}

} // namespace

int main(int argc, char *argv[])
{
    const bool light = argc > 1 && std::strcmp(argv[1], "lipsync") == 0 && lipsyncRunsLight(argc, argv);
    return toonface::cli::execProgram(light ? "toonface-cli-light" : "toonface-cli-full", argv);
}
