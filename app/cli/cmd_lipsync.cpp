#include "cli/command.h"
#include "speech/lipsync.h"
#include "speech/stagetimes.h"
#include "speech/wavfile.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QTextStream>

namespace toonface::cli {

namespace {

struct LipsyncOptions
{
    QCommandLineOption audio {QStringLiteral("audio"),
        Cli::tr("The speech recording (WAV, FLAC, MP3, OGG, M4A or a video's sound)."), QStringLiteral("AUDIO")};
    QCommandLineOption script {QStringLiteral("script"),
        Cli::tr("What is said, as UTF-8 text: Chinese characters, pinyin, zhuyin, or English."),
        QStringLiteral("SCRIPT")};
    QCommandLineOption lang {QStringLiteral("lang"),
        Cli::tr("Language of the script: cmn, en, or auto (from the script)."), QStringLiteral("cmn|en|auto"),
        QStringLiteral("auto")};
    QCommandLineOption output {QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("Write the result here: .tsv for Rhubarb-style cues, JSON otherwise (default: JSON on stdout)."),
        QStringLiteral("OUT.json|OUT.tsv")};
};

// The light toonface-cli runs lipsync unless the recording needs FFmpeg's decoders: a plain
// PCM WAV file (speech/wavfile.h) is read there, and so are the errors of a missing or empty
// file and of bad arguments (the same code prints them in either program).
bool runsLight(const QStringList &args)
{
    QCommandLineParser parser;
    const LipsyncOptions o;
    parser.addOptions({o.audio, o.script, o.lang, o.output});
    parser.addOption(QCommandLineOption(QStringList {QStringLiteral("h"), QStringLiteral("help")}));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    if (!parser.parse(QStringList {QStringLiteral("toonface-cli lipsync")} + args) || !parser.isSet(o.audio))
        return true;
    const QFileInfo file(parser.value(o.audio));
    return !file.isFile() || file.size() == 0 || probePlainWav(file.filePath()).has_value();
}

int runLipsync(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const LipsyncOptions o;
    const QCommandLineOption &audio = o.audio, &script = o.script, &lang = o.lang, &output = o.output;
    parser.addOptions({audio, script, lang, output});
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (!parser.isSet(audio) || !parser.isSet(script) || !parser.positionalArguments().isEmpty())
        return fail(ExitUsage, Cli::tr("lipsync needs --audio and --script (usage: toonface-cli %1)").arg(self.usage));
    const auto language = languageFromCode(parser.value(lang));
    if (!language)
        return fail(ExitUsage, Cli::tr("unknown --lang '%1' (cmn, en or auto)").arg(parser.value(lang)));

    progress(Cli::tr("aligning %1 with %2").arg(parser.value(audio), parser.value(script)));
    const LipsyncOutcome out = lipsyncFiles(parser.value(audio), parser.value(script), *language);
    if (out.status == LipsyncStatus::CannotAlign)
        return fail(ExitCannotAlign, out.error);
    if (!out.ok())
        return fail(ExitBadInput, out.error);

    const bool tsv = parser.isSet(output) && QFileInfo(parser.value(output)).suffix().toLower() == QLatin1String("tsv");
    const QByteArray data
        = tsv ? lipsyncToTsv(out.result) : QJsonDocument(lipsyncToJson(out.result)).toJson(QJsonDocument::Indented);
    const int written = writeOutput(parser, output, data);
    markStage("written");
    return written;
}

const CommandRegistrar registrar({QStringLiteral("lipsync"),
    QString::fromUtf8(QT_TRANSLATE_NOOP("toonface::cli::Cli",
        "Time a recording's syllables against its script and give the mouth shapes (toonface.lipsync/1).")),
    QStringLiteral("lipsync --audio AUDIO --script SCRIPT [--lang cmn|en] [-o OUT.json|OUT.tsv]"), runLipsync, false,
    true, runsLight});

} // namespace

} // namespace toonface::cli
