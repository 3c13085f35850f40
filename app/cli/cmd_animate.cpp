#include "anim/timeline.h"
#include "cli/command.h"
#include "cli/faceinput.h"
#include "cli/speechinput.h"
#include "export/framerenderer.h"
#include "export/htmlplayer.h"
#include "export/smilexport.h"
#include "export/videoencoder.h"
#include "face/emotion.h"
#include "io/project.h"
#include "render/svgface.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace toonface::cli {

namespace {

enum class OutputKind { Svg, Html, Mp4, Gif, PngDir };

bool outputKind(const QString &path, OutputKind *kind)
{
    if (path.endsWith(QLatin1Char('/'))) {
        *kind = OutputKind::PngDir;
        return true;
    }
    const QString suffix = QFileInfo(path).suffix().toLower();
    static const std::pair<const char *, OutputKind> kinds[] = {{"svg", OutputKind::Svg}, {"html", OutputKind::Html},
        {"htm", OutputKind::Html}, {"mp4", OutputKind::Mp4}, {"gif", OutputKind::Gif}};
    for (const auto &[name, k] : kinds) {
        if (suffix == QLatin1StringView(name)) {
            *kind = k;
            return true;
        }
    }
    return false;
}

// Exported video frames show the drawing's frame with its longer side at its own size, kept
// within 512-1280 pixels (the drawing is vector: a small head is drawn larger, not blurred) and
// even, as encoders want.
QSize videoSize(QSizeF frame)
{
    const QSizeF base = frame.isEmpty() ? QSizeF(512, 512) : frame;
    const double side = std::clamp(std::max(base.width(), base.height()), 512.0, 1280.0);
    const QSize s = base.scaled(side, side, Qt::KeepAspectRatio).toSize();
    return QSize(std::max(2, s.width() & ~1), std::max(2, s.height() & ~1));
}

int writeVideoOutput(const QString &path, OutputKind kind, const SvgFace &face, const Timeline &timeline,
    const MouthShapeSet &shapes, const QString &audioPath)
{
    const QSize size = videoSize(face.frame().size());
    const FrameRenderer renderer(face, timeline, shapes, size);
    const VideoFormat format = kind == OutputKind::Mp4 ? VideoFormat::Mp4
        : kind == OutputKind::Gif                      ? VideoFormat::Gif
                                                       : VideoFormat::PngSequence;
    QString error;
    VideoWriter writer;
    AudioSource audio;
    if (format == VideoFormat::Mp4 && !audioPath.isEmpty()) {
        audio.path = audioPath;
        audio.offset = timeline.audio() ? timeline.audio()->offset : 0.0;
    }
    VideoOptions options;
    if (format == VideoFormat::Gif) {
        // The palette must know the open mouth and shut eyes, which frame 0 may not show.
        Pose open = mouthPose(face.face(), shapes, MouthShape::A);
        open.leftEyeOpen = open.rightEyeOpen = 0;
        options.paletteSamples << rasterizeSvg(face.svg(open), size);
    }
    if (!writer.open(path, format, size, renderer.frameRate(), audio, &error, options))
        return fail(ExitFailed, error);
    FrameRenderOptions frameOptions;
    int lastPercent = -1;
    frameOptions.progress = [&](int delivered, int total) {
        const int percent = total > 0 ? delivered * 100 / total : 100;
        if (percent / 10 != lastPercent / 10)
            progress(QStringLiteral("rendering frames: %1 %").arg(percent));
        lastPercent = percent;
    };
    const bool ok = renderFrames(
        renderer, [&](int, const QImage &image) { return writer.addFrame(image, &error); }, frameOptions);
    if (!ok)
        return fail(ExitFailed, error.isEmpty() ? QStringLiteral("%1: rendering stopped").arg(path) : error);
    if (!writer.finish(&error))
        return fail(ExitFailed, error);
    return ExitOk;
}

int runAnimate(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption audio(
        QStringLiteral("audio"), QStringLiteral("The speech recording."), QStringLiteral("A"));
    const QCommandLineOption script(
        QStringLiteral("script"), QStringLiteral("The recording's script (a UTF-8 text file)."), QStringLiteral("S"));
    const QCommandLineOption say(
        QStringLiteral("say"), QStringLiteral("Speak this text with the built-in voice."), QStringLiteral("TEXT"));
    const QCommandLineOption video(
        QStringLiteral("video"), QStringLiteral("Drive the face by a video of the person."), QStringLiteral("CLIP"));
    const QCommandLineOption lang(QStringLiteral("lang"),
        QStringLiteral("Language of the script: cmn or en (default: detected)."), QStringLiteral("cmn|en"));
    const QCommandLineOption emotion(QStringLiteral("emotion"),
        QStringLiteral("Expression while speaking: neutral, smile, sad, angry or surprise."), QStringLiteral("NAME"),
        QStringLiteral("neutral"));
    const QCommandLineOption noBlink(QStringLiteral("no-blink"), QStringLiteral("Do not blink."));
    const QCommandLineOption fps(QStringLiteral("fps"), QStringLiteral("Frames per second (default 25)."),
        QStringLiteral("N"), QStringLiteral("25"));
    const QCommandLineOption style(QStringLiteral("style"),
        QStringLiteral("Drawing style: %1.").arg(Style::presetNames().join(QStringLiteral(", "))),
        QStringLiteral("NAME"));
    const QCommandLineOption projectOut(QStringLiteral("project"), QStringLiteral("Also save the result as a project."),
        QStringLiteral("OUT.toonface"));
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("OUT.svg, OUT.html, OUT.mp4, OUT.gif, or DIR/ for PNG frames."), QStringLiteral("OUT"));
    const QCommandLineOption frame = frameOption();
    parser.addOptions({audio, script, say, video, lang, emotion, noBlink, fps, style, frame, projectOut, output});
    parser.addPositionalArgument(QStringLiteral("INPUT"), QStringLiteral("A photo or a project."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(
            ExitUsage, QStringLiteral("animate takes one photo or project (usage: toonface-cli %1)").arg(self.usage));
    if (!parser.isSet(output))
        return fail(ExitUsage, QStringLiteral("animate needs -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|DIR/"));
    OutputKind kind;
    if (!outputKind(parser.value(output), &kind))
        return fail(ExitUsage,
            QStringLiteral("cannot tell the output type of '%1': use .svg, .html, .mp4, .gif or a folder ending in /")
                .arg(parser.value(output)));
    const int sources
        = int(parser.isSet(audio) || parser.isSet(script)) + int(parser.isSet(say)) + int(parser.isSet(video));
    // With none, a project plays its own timeline.
    const bool projectInput
        = QFileInfo(parser.positionalArguments().value(0)).suffix().toLower() == QLatin1StringView("toonface");
    if (sources > 1 || (sources == 0 && !projectInput))
        return fail(ExitUsage,
            QStringLiteral("animate needs exactly one of --audio with --script, --say TEXT or --video CLIP (a project "
                           "without them plays its own timeline)"));
    if (parser.isSet(audio) != parser.isSet(script))
        return fail(ExitUsage, QStringLiteral("--audio and --script go together"));
    if (parser.isSet(video))
        return fail(ExitUsage, QStringLiteral("--video: driving the face by a video is not available in this version"));
    bool fpsOk = false;
    const double frameRate = parser.value(fps).toDouble(&fpsOk);
    if (!fpsOk || !(frameRate >= 1 && frameRate <= 120))
        return fail(ExitUsage, QStringLiteral("--fps takes a number from 1 to 120, not '%1'").arg(parser.value(fps)));
    Emotion expression = Emotion::Neutral;
    if (const int code = parseEmotionOption(parser, emotion, &expression); code != ExitOk)
        return code;
    QString language = parser.value(lang);
    if (!language.isEmpty() && language != QLatin1StringView("cmn") && language != QLatin1StringView("en"))
        return fail(ExitUsage, QStringLiteral("unknown --lang '%1' (cmn or en)").arg(language));
    std::optional<Style> chosenStyle;
    bool wholePhoto = false;
    if (const int code = parseFrameOption(parser, frame, &wholePhoto); code != ExitOk)
        return code;
    if (const int code = parseStyleOption(parser, style, &chosenStyle); code != ExitOk)
        return code;

    const QString inputPath = parser.positionalArguments().constFirst();
    if (QFileInfo(inputPath).suffix().toLower() == QLatin1StringView("json"))
        return fail(
            ExitUsage, QStringLiteral("animate takes a photo or a project, not a face JSON (%1)").arg(inputPath));
    FaceInput input;
    if (const int code = loadFaceInput(inputPath, DetectOptions {}, &input); code != ExitOk)
        return code;
    const Style drawStyle = drawingStyle(input, chosenStyle);
    const MouthShapeSet shapes = input.mouthShapes;

    Timeline timeline;
    SpeechTrack speech;
    if (sources == 0) {
        if (!input.project)
            return fail(ExitUsage,
                QStringLiteral("animate needs one of --audio with --script, --say TEXT or --video CLIP (only a project "
                               "plays its own timeline)"));
        // The project's own animation, as the editor made it: the same frames as its preview.
        timeline = input.project->timeline;
        if (timeline.duration() <= 0)
            return fail(ExitBadInput,
                QStringLiteral("%1: the project has no animation to play (its timeline is empty)").arg(inputPath));
        if (parser.isSet(fps))
            timeline.setFrameRate(frameRate);
        if (expression != Emotion::Neutral)
            timeline.addEmotionClip(EmotionClip {0.0, timeline.duration(), expression, 1.0, 0.4, 0.4});
        if (parser.isSet(noBlink))
            timeline.setBlinks({});
        speech.audioPath = input.project->audioPath();
        speech.duration = timeline.duration();
        speech.syllables = input.project->syllables;
        speech.script = input.project->script;
        speech.language = input.project->scriptLanguage;
    } else {
        // Speech: the mouth track and the sound.
        SpeechRequest request;
        request.audioPath = parser.value(audio);
        request.scriptPath = parser.value(script);
        request.sayText = parser.value(say);
        request.language = language;
        const QFileInfo outInfo(parser.value(output));
        request.workDir
            = kind == OutputKind::PngDir ? QDir(parser.value(output)).absolutePath() : outInfo.absolutePath();
        request.outputBase = kind == OutputKind::PngDir ? QStringLiteral("speech") : outInfo.completeBaseName();
        if (const int code = buildSpeechTrack(request, &speech); code != ExitOk)
            return code;

        timeline.setFrameRate(frameRate);
        timeline.addMouthCues(speech.cues);
        timeline.setAudio(AudioClip {speech.audioPath, 0.0, speech.duration});
        if (expression != Emotion::Neutral)
            timeline.addEmotionClip(EmotionClip {0.0, speech.duration, expression, 1.0, 0.4, 0.4});
        if (!parser.isSet(noBlink))
            timeline.generateBlinks(quint32(qHash(input.photoPath)), speech.duration);
    }

    if (parser.isSet(projectOut)) {
        Project project;
        project.photoPath = input.photoPath;
        project.face = input.face;
        project.style = drawStyle;
        project.mouthShapes = shapes;
        project.layerPaths = input.layerPaths;
        project.timeline = timeline;
        project.syllables = speech.syllables;
        project.script = speech.script;
        project.scriptLanguage = speech.language;
        QString error;
        if (!saveProject(project, parser.value(projectOut), &error))
            return fail(ExitFailed, error);
    }

    SvgFace face(input.face, drawStyle);
    face.setFrame(drawingFrame(input.face, wholePhoto));
    for (const QString &layer : std::as_const(input.layerPaths)) {
        QString error;
        if (!face.addLayerFile(layer, &error))
            return fail(ExitBadInput, error);
    }
    const QString out = parser.value(output);
    progress(QStringLiteral("exporting %1 s of animation to %2").arg(speech.duration, 0, 'f', 1).arg(out));
    if (kind == OutputKind::Svg || kind == OutputKind::Html) {
        AnimationExportOptions options;
        options.audio = ExportAudio::Embed;
        options.audioPath = speech.audioPath;
        options.layerFiles = input.layerPaths;
        options.frame = face.frame();
        QString error;
        const QByteArray data = kind == OutputKind::Svg
            ? exportSmilSvg(input.face, drawStyle, timeline, shapes, options, &error)
            : exportHtmlPlayer(input.face, drawStyle, timeline, shapes, options, &error);
        if (data.isEmpty())
            return fail(ExitFailed, error);
        if (!writeFileAtomically(out, data, &error))
            return fail(ExitFailed, error);
        return ExitOk;
    }
    return writeVideoOutput(out, kind, face, timeline, shapes, speech.audioPath);
}

const CommandRegistrar registrar({QStringLiteral("animate"),
    QStringLiteral(
        "Make the face of a photo or project talk, and export the animation (SVG, HTML, MP4, GIF or PNG frames)."),
    QStringLiteral("animate IMAGE|PROJECT [--audio A --script S | --say TEXT | --video CLIP] [--emotion NAME] "
                   "[--no-blink] [--fps N] [--style NAME] [--frame head|photo] [--project OUT.toonface] -o "
                   "OUT.svg|OUT.html|OUT.mp4|OUT.gif|DIR/"),
    runAnimate});

} // namespace

} // namespace toonface::cli
