#include "cli/speechinput.h"

#include "cli/command.h"
#include "speech/lipsync.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace toonface::cli {

namespace {

std::optional<Language> requestedLanguage(const QString &code)
{
    return code.isEmpty() ? std::optional<Language>(Language::Auto) : languageFromCode(code);
}

} // namespace

int buildSpeechTrack(const SpeechRequest &request, SpeechTrack *out)
{
    const auto language = requestedLanguage(request.language);
    if (!language)
        return fail(ExitUsage, Cli::tr("unknown --lang '%1' (cmn or en)").arg(request.language));

    LipsyncResult result;
    if (!request.sayText.isEmpty()) {
        const ScriptParse script = parseScript(request.sayText, *language);
        if (!script.ok())
            return fail(ExitBadInput, QStringLiteral("--say: ") + script.error);
        const TtsResult spoken = synthesize(script.script);
        if (!spoken.ok())
            return fail(ExitBadInput, spoken.error);
        // The recording is kept beside the output: the animation and the project refer to it.
        if (!QDir().mkpath(request.workDir))
            return fail(ExitFailed, Cli::tr("cannot create the folder %1").arg(request.workDir));
        out->audioPath = QDir(request.workDir).filePath(request.outputBase + QStringLiteral(".wav"));
        QString error;
        if (!writeAudio(out->audioPath, spoken.audio, &error))
            return fail(ExitFailed, error);
        result = lipsyncResult(script.script, spoken);
        out->script = request.sayText;
    } else {
        progress(Cli::tr("aligning %1 with %2").arg(request.audioPath, request.scriptPath));
        // Read once: the script may come through a pipe (--script <(echo ...)).
        const ScriptParse script = readScriptFile(request.scriptPath, *language, &out->script);
        if (!script.ok())
            return fail(ExitBadInput, script.error);
        // A recording of an hour aligns for minutes: it shows how far it is and stops on Ctrl+C.
        StageProgress report;
        const LipsyncOutcome outcome = lipsyncRecording(
            request.audioPath, script.script, request.scriptPath,
            [&report](double fraction, const QString &stage) { report(fraction, stage); }, interruption());
        if (outcome.status == LipsyncStatus::Cancelled)
            return fail(ExitInterrupted, Cli::tr("%1: interrupted; nothing was written").arg(request.audioPath));
        if (!outcome.ok())
            return fail(outcome.status == LipsyncStatus::CannotAlign ? ExitCannotAlign : ExitBadInput, outcome.error);
        result = outcome.result;
        out->audioPath = QFileInfo(request.audioPath).absoluteFilePath();
    }
    out->cues = result.mouthCues;
    out->syllables = result.syllables;
    out->duration = result.duration;
    out->language = languageCode(result.language);
    return ExitOk;
}

} // namespace toonface::cli
