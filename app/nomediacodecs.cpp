// The light toonface-cli's stand-ins for core/speech/audioffmpeg.cpp, so that it never links
// (nor loads) FFmpeg's formats and codecs: the linker takes these definitions instead of that
// file's from the core library. The light program runs only with input that needs neither
// (Command::runsLight), so these are never reached there; if a change makes them reachable,
// they fail with a clear message instead of a wrong result.
#include "i18n/coretext.h"
#include "speech/audioconvert.h"

namespace toonface::detail {

namespace {

QString needsFullProgram()
{
    return QStringLiteral("this needs FFmpeg's decoders and encoders, which only toonface-cli-full loads");
}

} // namespace

AudioResult decodeWithFfmpeg(const QString &path, const AudioSink &, const SpeechProgressFn &, const std::atomic_bool *)
{
    AudioResult r;
    r.status = AudioStatus::Unreadable;
    r.error = withProblem(path, needsFullProgram());
    return r;
}

std::unique_ptr<AudioFileWriter> openFfmpegAudioWriter(const QString &path, int, QString *error)
{
    *error = withProblem(path, needsFullProgram());
    return nullptr;
}

} // namespace toonface::detail
