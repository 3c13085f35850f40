#include "cli/command.h"
#include "speech/lipsync.h"
#include "speech/stagetimes.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QTextStream>

namespace toonface::cli {

namespace {

int runLipsync(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption audio(QStringLiteral("audio"),
        Cli::tr("The speech recording (WAV, FLAC, MP3, OGG, M4A or a video's sound)."), QStringLiteral("AUDIO"));
    const QCommandLineOption script(QStringLiteral("script"),
        Cli::tr("What is said, as UTF-8 text: Chinese characters, pinyin, zhuyin, or English."),
        QStringLiteral("SCRIPT"));
    const QCommandLineOption lang(QStringLiteral("lang"),
        Cli::tr("Language of the script: cmn, en, or auto (from the script)."), QStringLiteral("cmn|en|auto"),
        QStringLiteral("auto"));
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("Write the result here: .tsv for Rhubarb-style cues, JSON otherwise (default: JSON on stdout)."),
        QStringLiteral("OUT.json|OUT.tsv"));
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
    true});

} // namespace

} // namespace toonface::cli
