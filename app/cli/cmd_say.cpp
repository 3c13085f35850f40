#include "cli/command.h"
#include "speech/lipsync.h"

#include <QJsonDocument>

namespace toonface::cli {

namespace {

int runSay(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption lang(QStringLiteral("lang"),
        Cli::tr("Language of the text: cmn, en, or auto (from the text)."), QStringLiteral("cmn|en|auto"),
        QStringLiteral("auto"));
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("The speech: .wav, .flac, .mp3, .ogg, .opus or .m4a."), QStringLiteral("OUT.wav"));
    const QCommandLineOption timings(QStringLiteral("timings"),
        Cli::tr("Also write the exact syllable timings and mouth shapes (toonface.lipsync/1)."),
        QStringLiteral("OUT.json"));
    const QCommandLineOption voice(QStringLiteral("voice"),
        Cli::tr("An espeak-ng voice, optionally with a variant (cmn-latn-pinyin+f2)."), QStringLiteral("VOICE"));
    const QCommandLineOption rate(
        QStringLiteral("rate"), Cli::tr("Words per minute (80-450)."), QStringLiteral("N"), QStringLiteral("175"));
    const QCommandLineOption pitch(
        QStringLiteral("pitch"), Cli::tr("Pitch, 0-100."), QStringLiteral("N"), QStringLiteral("50"));
    parser.addOptions({lang, output, timings, voice, rate, pitch});
    parser.addPositionalArgument(QStringLiteral("TEXT"), Cli::tr("What to say."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output))
        return fail(ExitUsage, Cli::tr("say takes one TEXT and -o OUT.wav (usage: toonface-cli %1)").arg(self.usage));
    const auto language = languageFromCode(parser.value(lang));
    if (!language)
        return fail(ExitUsage, Cli::tr("unknown --lang '%1' (cmn, en or auto)").arg(parser.value(lang)));
    bool rateOk = false, pitchOk = false;
    TtsOptions options;
    options.rate = parser.value(rate).toInt(&rateOk);
    options.pitch = parser.value(pitch).toInt(&pitchOk);
    options.voice = parser.value(voice);
    if (!rateOk || !pitchOk)
        return fail(ExitUsage, Cli::tr("--rate and --pitch take whole numbers"));

    const ScriptParse script = parseScript(parser.positionalArguments().constFirst(), *language);
    if (!script.ok())
        return fail(ExitBadInput, QStringLiteral("the text: ") + script.error);
    const TtsResult spoken = synthesize(script.script, options);
    if (!spoken.ok())
        return fail(ExitBadInput, spoken.error);
    QString error;
    if (!writeAudio(parser.value(output), spoken.audio, &error))
        return fail(ExitFailed, error);
    if (parser.isSet(timings)) {
        const QByteArray json
            = QJsonDocument(lipsyncToJson(lipsyncResult(script.script, spoken))).toJson(QJsonDocument::Indented);
        if (!writeFileAtomically(parser.value(timings), json, &error))
            return fail(ExitFailed, error);
    }
    return ExitOk;
}

const CommandRegistrar registrar({QStringLiteral("say"),
    QString::fromUtf8(QT_TRANSLATE_NOOP("toonface::cli::Cli",
        "Speak a text with espeak-ng and write the exact syllable timings, so a face can talk without a recording.")),
    QStringLiteral("say TEXT [--lang cmn|en] -o OUT.wav [--timings OUT.json] [--voice V] [--rate N] [--pitch N]"),
    runSay});

} // namespace

} // namespace toonface::cli
