#include "cli/command.h"
#include "cli/faceinput.h"
#include "export/epubbook.h"
#include "face/averageface.h"

#include <QFileInfo>

namespace toonface::cli {

namespace {

int runBook(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption audio(QStringLiteral("audio"),
        Cli::tr("The recording of the whole text, headings included, in reading order."), QStringLiteral("A"));
    const QCommandLineOption say(QStringLiteral("say"), Cli::tr("Read the text with the built-in voice."));
    const QCommandLineOption face(QStringLiteral("face"),
        Cli::tr("The face that reads: a photo or a project (default: an average face)."),
        QStringLiteral("PHOTO|PROJECT"));
    const QCommandLineOption lang(QStringLiteral("lang"),
        Cli::tr("The book's language: %1 (default: Chinese or English, as the text reads).")
            .arg(bookLanguages().join(QStringLiteral(", "))),
        QStringLiteral("LANG"));
    const QCommandLineOption title(QStringLiteral("title"),
        Cli::tr("The book's title (default: its first heading or the file's name)."), QStringLiteral("T"));
    const QCommandLineOption author(QStringLiteral("author"), Cli::tr("The book's author."), QStringLiteral("A"));
    const QCommandLineOption highlight(QStringLiteral("highlight"),
        Cli::tr("What reading systems highlight as it is read: sentence or syllable (a character or word)."),
        QStringLiteral("sentence|syllable"), QStringLiteral("sentence"));
    const QCommandLineOption faceAs(QStringLiteral("face-as"),
        Cli::tr("How the face moves on the pages: svg (an animated drawing) or video (a video of each page read "
                "aloud, for reading systems without read-aloud or SVG animation)."),
        QStringLiteral("svg|video"), QStringLiteral("svg"));
    const QCommandLineOption style(QStringLiteral("style"),
        Cli::tr("Drawing style: %1.").arg(Style::presetNames().join(QStringLiteral(", "))), QStringLiteral("NAME"));
    const QCommandLineOption rate(QStringLiteral("rate"), Cli::tr("With --say: words per minute (80-450)."),
        QStringLiteral("N"), QStringLiteral("175"));
    const QCommandLineOption output(
        QStringList {QStringLiteral("o"), QStringLiteral("output")}, Cli::tr("The book."), QStringLiteral("BOOK.epub"));
    parser.addOptions({audio, say, face, lang, title, author, highlight, faceAs, style, rate, output});
    parser.addPositionalArgument(QStringLiteral("TEXT"),
        Cli::tr("The text: plain UTF-8 (.txt) or Markdown (.md), whose headings make chapters."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(ExitUsage, Cli::tr("book takes one text file (usage: toonface-cli %1)").arg(self.usage));
    if (parser.isSet(audio) == parser.isSet(say))
        return fail(ExitUsage, Cli::tr("book needs either --audio A (a recording of the text) or --say"));
    if (!parser.isSet(output) || QFileInfo(parser.value(output)).suffix().toLower() != QLatin1StringView("epub"))
        return fail(ExitUsage, Cli::tr("book needs -o BOOK.epub"));
    if (parser.isSet(lang) && !bookLanguages().contains(parser.value(lang)))
        return fail(ExitUsage,
            Cli::tr("unknown --lang '%1' (%2)").arg(parser.value(lang), bookLanguages().join(QStringLiteral(", "))));
    const QString highlighted = parser.value(highlight);
    if (highlighted != QLatin1StringView("sentence") && highlighted != QLatin1StringView("syllable"))
        return fail(ExitUsage, Cli::tr("--highlight takes sentence or syllable, not '%1'").arg(highlighted));
    const QString faceMedia = parser.value(faceAs);
    if (faceMedia != QLatin1StringView("svg") && faceMedia != QLatin1StringView("video"))
        return fail(ExitUsage, Cli::tr("--face-as takes svg or video, not '%1'").arg(faceMedia));
    bool rateOk = false;
    const int wordsPerMinute = parser.value(rate).toInt(&rateOk);
    if (!rateOk || wordsPerMinute < 80 || wordsPerMinute > 450)
        return fail(ExitUsage, Cli::tr("--rate takes a whole number from 80 to 450, not '%1'").arg(parser.value(rate)));
    std::optional<Style> chosenStyle;
    if (const int code = parseStyleOption(parser, style, &chosenStyle); code != ExitOk)
        return code;

    FaceInput input;
    if (parser.isSet(face)) {
        if (const int code = loadFaceInput(parser.value(face), DetectOptions {}, &input); code != ExitOk)
            return code;
    } else {
        input.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    }

    BookRequest request;
    request.textPath = parser.positionalArguments().constFirst();
    request.audioPath = parser.value(audio);
    request.voice.rate = wordsPerMinute;
    request.language = parser.value(lang);
    request.title = parser.value(title);
    request.author = parser.value(author);
    request.face = input.face;
    request.style = drawingStyle(input, chosenStyle);
    request.mouthShapes = input.mouthShapes;
    request.layerFiles = input.layerPaths;
    request.highlight
        = highlighted == QLatin1StringView("syllable") ? BookHighlight::Syllable : BookHighlight::Sentence;
    request.faceMedia = faceMedia == QLatin1StringView("video") ? BookFaceMedia::Video : BookFaceMedia::Svg;
    request.outputPath = parser.value(output);

    StageProgress report;
    const BookResult result = exportBook(
        request, [&report](double fraction, const QString &stage) { report(fraction, stage); }, interruption());
    switch (result.status) {
    case BookStatus::Done: break;
    case BookStatus::Cancelled:
        return fail(ExitInterrupted, Cli::tr("%1: interrupted; nothing was written").arg(request.outputPath));
    case BookStatus::BadInput: return fail(ExitBadInput, result.error);
    case BookStatus::CannotAlign: return fail(ExitCannotAlign, result.error);
    case BookStatus::Failed: return fail(ExitFailed, result.error);
    }
    progress(Cli::tr("%1: %2 chapters, %3 pages, %4 s read aloud")
                 .arg(request.outputPath)
                 .arg(result.chapters)
                 .arg(result.pages)
                 .arg(result.duration, 0, 'f', 1));
    return ExitOk;
}

const CommandRegistrar registrar({QStringLiteral("book"),
    QString::fromUtf8(QT_TRANSLATE_NOOP("toonface::cli::Cli",
        "Make a read-aloud EPUB 3 book of a text: each page a paragraph beside the talking face, its sentences "
        "highlighted as the recording or the built-in voice reads them.")),
    QStringLiteral(
        "book TEXT.txt|TEXT.md (--audio A | --say) [--face PHOTO|PROJECT] [--lang zh-Hant|zh-Hans|en] "
        "[--title T] [--author A] [--highlight sentence|syllable] [--face-as svg|video] [--style NAME] [--rate N] "
        "-o BOOK.epub"),
    runBook, true});

} // namespace

} // namespace toonface::cli
