#include "anim/timeline.h"
#include "cli/command.h"
#include "cli/faceinput.h"
#include "cli/speechinput.h"
#include "cli/videotrack.h"
#include "export/animationexport.h"
#include "export/exportpreset.h"
#include "export/framerenderer.h"
#include "export/htmlplayer.h"
#include "export/smilexport.h"
#include "export/videoencoder.h"
#include "face/emotion.h"
#include "io/project.h"
#include "render/svgface.h"
#include "speech/audio.h"
#include "track/retarget.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace toonface::cli {

namespace {

int runAnimate(const Command &self, const QStringList &args)
{
    QCommandLineParser parser;
    const QCommandLineOption audio(QStringLiteral("audio"), Cli::tr("The speech recording."), QStringLiteral("A"));
    const QCommandLineOption script(
        QStringLiteral("script"), Cli::tr("The recording's script (a UTF-8 text file)."), QStringLiteral("S"));
    const QCommandLineOption say(
        QStringLiteral("say"), Cli::tr("Speak this text with the built-in voice."), QStringLiteral("TEXT"));
    const QCommandLineOption video(
        QStringLiteral("video"), Cli::tr("Drive the face by a video of the person."), QStringLiteral("CLIP"));
    const QCommandLineOption lang(QStringLiteral("lang"),
        Cli::tr("Language of the script: cmn or en (default: detected)."), QStringLiteral("cmn|en"));
    const QCommandLineOption emotion(QStringLiteral("emotion"),
        Cli::tr("Expression while speaking: neutral, smile, sad, angry or surprise."), QStringLiteral("NAME"),
        QStringLiteral("neutral"));
    const QCommandLineOption noBlink(QStringLiteral("no-blink"), Cli::tr("Do not blink."));
    const QCommandLineOption fps(
        QStringLiteral("fps"), Cli::tr("Frames per second (default 25)."), QStringLiteral("N"), QStringLiteral("25"));
    const QCommandLineOption style(QStringLiteral("style"),
        Cli::tr("Drawing style: %1.").arg(Style::presetNames().join(QStringLiteral(", "))), QStringLiteral("NAME"));
    const QCommandLineOption projectOut(
        QStringLiteral("project"), Cli::tr("Also save the result as a project."), QStringLiteral("OUT.toonface"));
    const QCommandLineOption output(QStringList {QStringLiteral("o"), QStringLiteral("output")},
        Cli::tr("OUT.svg, OUT.html, OUT.mp4, OUT.gif, OUT.webm, OUT.mov, OUT.apng, OUT.webp, or DIR/ for PNG "
                "frames."),
        QStringLiteral("OUT"));
    const QCommandLineOption background(QStringLiteral("background"),
        Cli::tr("What is behind the face in a video or picture: a colour (white, #rrggbb), transparent, or a "
                "photo (default: transparent for WebM, MOV, APNG, WebP and PNG frames, white for MP4 and GIF)."),
        QStringLiteral("COLOUR|transparent|PHOTO"));
    const QCommandLineOption preset(QStringLiteral("preset"),
        Cli::tr("Export for a place with limits: %1.").arg(exportPresetNames().join(QStringLiteral(", "))),
        QStringLiteral("NAME"));
    const QCommandLineOption start(QStringLiteral("start"),
        Cli::tr("Video and pictures: begin this many seconds into the animation."), QStringLiteral("S"));
    const QCommandLineOption duration(QStringLiteral("duration"),
        Cli::tr("Video and pictures: export this many seconds (default: to the end)."), QStringLiteral("S"));
    const QCommandLineOption frame = frameOption();
    parser.addOptions({audio, script, say, video, lang, emotion, noBlink, fps, style, frame, projectOut, output,
        background, preset, start, duration});
    const VideoTrackOptions trackOptions;
    trackOptions.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("INPUT"),
        Cli::tr("A photo or a project; or a video clip, whose neutral frame's face it animates."));
    bool helped = false;
    if (!parseArguments(parser, self, args, &helped))
        return ExitUsage;
    if (helped)
        return ExitOk;
    if (parser.positionalArguments().size() != 1)
        return fail(ExitUsage, Cli::tr("animate takes one photo or project (usage: toonface-cli %1)").arg(self.usage));
    if (!parser.isSet(output))
        return fail(ExitUsage, Cli::tr("animate needs -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|DIR/ ..."));
    const std::optional<AnimationFormat> format = animationFormatForPath(parser.value(output));
    if (!format)
        return fail(ExitUsage,
            Cli::tr("cannot tell the output type of '%1': use .svg, .html, .mp4, .gif, .webm, .mov, .apng, .webp "
                    "or a folder ending in /")
                .arg(parser.value(output)));
    std::optional<ExportPreset> chosenPreset;
    if (parser.isSet(preset)) {
        chosenPreset = exportPresetNamed(parser.value(preset));
        if (!chosenPreset)
            return fail(ExitUsage,
                Cli::tr("unknown --preset '%1' (%2)")
                    .arg(parser.value(preset), exportPresetNames().join(QStringLiteral(", "))));
        if (*format != chosenPreset->format)
            return fail(ExitUsage,
                Cli::tr("the %1 preset writes %2: name the output .%3, not '%4'")
                    .arg(chosenPreset->name, animationFormatSuffix(chosenPreset->format).toUpper(),
                        animationFormatSuffix(chosenPreset->format), parser.value(output)));
    }
    ExportBackground backdrop;
    if (parser.isSet(background)) {
        QString why;
        const std::optional<ExportBackground> parsed = parseExportBackground(parser.value(background), &why);
        if (!parsed)
            return fail(ExitUsage, QStringLiteral("--background: ") + why);
        backdrop = *parsed;
        if (const QString problem = backgroundProblem(*format, backdrop); !problem.isEmpty())
            return fail(ExitUsage, QStringLiteral("%1: %2").arg(parser.value(output), problem));
    }
    double startS = 0;
    double durationS = 0;
    for (const auto &[option, value] : {std::pair {&start, &startS}, std::pair {&duration, &durationS}}) {
        if (!parser.isSet(*option))
            continue;
        bool ok = false;
        *value = parser.value(*option).toDouble(&ok);
        if (!ok || !std::isfinite(*value) || *value < 0 || (option == &duration && *value == 0))
            return fail(ExitUsage,
                Cli::tr("--%1 takes a number of seconds (more than 0 for --duration), not '%2'")
                    .arg(option->names().constFirst(), parser.value(*option)));
        if (!isRasterFormat(*format))
            return fail(ExitUsage,
                Cli::tr("--%1 needs a video or picture output; SVG and HTML play the whole animation")
                    .arg(option->names().constFirst()));
    }
    const QString inputPath = parser.positionalArguments().constFirst();
    const bool clipInput = looksLikeVideo(inputPath);
    const int sources
        = int(parser.isSet(audio) || parser.isSet(script)) + int(parser.isSet(say)) + int(parser.isSet(video));
    // With none, a project plays its own timeline and a clip drives its own face.
    const bool projectInput
        = QFileInfo(parser.positionalArguments().value(0)).suffix().toLower() == QLatin1StringView("toonface");
    if (sources > 1 || (sources == 0 && !projectInput && !clipInput))
        return fail(ExitUsage,
            Cli::tr("animate needs exactly one of --audio with --script, --say TEXT or --video CLIP (a project "
                    "without them plays its own timeline)"));
    if (parser.isSet(audio) != parser.isSet(script))
        return fail(ExitUsage, Cli::tr("--audio and --script go together"));
    const QString clipPath = parser.isSet(video) ? parser.value(video) : clipInput ? inputPath : QString();
    TrackVideoOptions trackVideoOptions;
    if (const int code = trackOptions.read(parser, &trackVideoOptions); code != ExitOk)
        return code;
    bool fpsOk = false;
    const double frameRate = parser.value(fps).toDouble(&fpsOk);
    if (!fpsOk || !(frameRate >= 1 && frameRate <= 120))
        return fail(ExitUsage, Cli::tr("--fps takes a number from 1 to 120, not '%1'").arg(parser.value(fps)));
    Emotion expression = Emotion::Neutral;
    if (const int code = parseEmotionOption(parser, emotion, &expression); code != ExitOk)
        return code;
    QString language = parser.value(lang);
    if (!language.isEmpty() && language != QLatin1StringView("cmn") && language != QLatin1StringView("en"))
        return fail(ExitUsage, Cli::tr("unknown --lang '%1' (cmn or en)").arg(language));
    std::optional<Style> chosenStyle;
    bool wholePhoto = false;
    if (const int code = parseFrameOption(parser, frame, &wholePhoto); code != ExitOk)
        return code;
    if (const int code = parseStyleOption(parser, style, &chosenStyle); code != ExitOk)
        return code;

    if (QFileInfo(inputPath).suffix().toLower() == QLatin1StringView("json"))
        return fail(ExitUsage, Cli::tr("animate takes a photo or a project, not a face JSON (%1)").arg(inputPath));
    const QFileInfo outInfo(parser.value(output));
    const QString workDir
        = *format == AnimationFormat::PngSequence ? QDir(parser.value(output)).absolutePath() : outInfo.absolutePath();
    const QString outputBase
        = *format == AnimationFormat::PngSequence ? QStringLiteral("speech") : outInfo.completeBaseName();

    FaceInput input;
    TrackResult track;
    if (!clipPath.isEmpty()) {
        if (const int code = trackClip(clipPath, trackVideoOptions, &track); code != ExitOk)
            return code;
    }
    if (clipInput) {
        // The thesis' path: the clip's neutral frame is the face.
        input.face = track.neutral.face;
        input.photo = track.neutralImage;
        input.detection = track.neutral;
        if (parser.isSet(projectOut)) {
            input.photoPath = QFileInfo(parser.value(projectOut)).absolutePath() + QLatin1Char('/')
                + QFileInfo(parser.value(projectOut)).completeBaseName() + QStringLiteral("-neutral.png");
            if (!track.neutralImage.save(input.photoPath))
                return fail(ExitFailed, Cli::tr("%1: cannot write the neutral frame").arg(input.photoPath));
        }
    } else if (const int code = loadFaceInput(inputPath, DetectOptions {}, &input); code != ExitOk) {
        return code;
    }
    const Style drawStyle = drawingStyle(input, chosenStyle);
    const MouthShapeSet shapes = input.mouthShapes;

    Timeline timeline;
    SpeechTrack speech;
    if (!clipPath.isEmpty()) {
        // The clip's motion, retargeted through ES0 units, and its own sound when it has one.
        timeline.setFrameRate(frameRate);
        addTrackToTimeline(track.frames, track.fps, &timeline);
        const double period = track.fps > 0 ? 1.0 / track.fps : 1.0 / frameRate;
        speech.duration = track.frames.isEmpty() ? 0.0 : track.frames.last().time + period;
        // The clip's sound is copied a block at a time: an hour-long clip's sound is never held whole.
        const QString soundPath = workDir + QLatin1Char('/') + outputBase + QStringLiteral("-sound.wav");
        if (track.hasAudio && !QDir().mkpath(workDir)) // a frame folder not made yet
            return fail(ExitFailed, Cli::tr("cannot create the folder %1").arg(workDir));
        StageProgress soundLines;
        const AudioResult sound = track.hasAudio
            ? copyAudio(
                clipPath, soundPath, [&](double f, const QString &) { soundLines(f, Cli::tr("copying the sound")); },
                interruption())
            : AudioResult {};
        if (sound.status == AudioStatus::Cancelled)
            return fail(ExitInterrupted, Cli::tr("%1: interrupted; nothing was written").arg(parser.value(output)));
        if (sound.status == AudioStatus::Unwritable)
            return fail(ExitFailed, sound.error);
        if (sound.ok()) {
            speech.audioPath = soundPath;
            const double seconds = double(sound.sampleCount) / kSpeechSampleRate;
            speech.duration = std::max(speech.duration, seconds);
            timeline.setAudioClips({AudioClip {speech.audioPath, 0.0, seconds}});
        } else {
            warn(track.hasAudio ? Cli::tr("%1: the animation is silent").arg(sound.error)
                                : Cli::tr("%1: the clip has no sound; the animation is silent").arg(clipPath));
        }
        if (expression != Emotion::Neutral)
            timeline.addEmotionClip(EmotionClip {0.0, speech.duration, expression, 1.0, 0.4, 0.4});
        if (parser.isSet(noBlink))
            timeline.setBlinks({});
    } else if (sources == 0) {
        if (!input.project)
            return fail(ExitUsage,
                Cli::tr("animate needs one of --audio with --script, --say TEXT or --video CLIP (only a project "
                        "plays its own timeline)"));
        // The project's own animation, as the editor made it: the same frames as its preview.
        timeline = input.project->timeline;
        if (timeline.duration() <= 0)
            return fail(ExitBadInput,
                Cli::tr("%1: the project has no animation to play (its timeline is empty)").arg(inputPath));
        if (parser.isSet(fps))
            timeline.setFrameRate(frameRate);
        if (expression != Emotion::Neutral)
            timeline.addEmotionClip(EmotionClip {0.0, timeline.duration(), expression, 1.0, 0.4, 0.4});
        if (parser.isSet(noBlink))
            timeline.setBlinks({});
        // The sound is the timeline's audio track (its clips mixed), not one file.
        speech.duration = timeline.duration();
        speech.syllables = input.project->syllables;
    } else {
        // Speech: the mouth track and the sound.
        SpeechRequest request;
        request.audioPath = parser.value(audio);
        request.scriptPath = parser.value(script);
        request.sayText = parser.value(say);
        request.language = language;
        request.workDir = workDir;
        request.outputBase = outputBase;
        if (const int code = buildSpeechTrack(request, &speech); code != ExitOk)
            return code;

        timeline.setFrameRate(frameRate);
        timeline.addMouthCues(speech.cues);
        AudioClip clip {speech.audioPath, 0.0, speech.duration};
        clip.script = speech.script;
        clip.language = speech.language;
        timeline.setAudioClips({clip});
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
        QString error;
        if (!saveProject(project, parser.value(projectOut), &error))
            return fail(ExitFailed, error);
    }

    const QString out = parser.value(output);
    progress(Cli::tr("exporting %1 s of animation to %2").arg(speech.duration, 0, 'f', 1).arg(out));
    ExportRequest exportRequest;
    exportRequest.format = *format;
    exportRequest.outputPath = out;
    exportRequest.framing = wholePhoto ? ExportFraming::Photo : ExportFraming::Head;
    exportRequest.face = input.face;
    exportRequest.style = drawStyle;
    exportRequest.timeline = timeline;
    exportRequest.mouthShapes = shapes;
    exportRequest.layerFiles = input.layerPaths;
    exportRequest.audioPath = speech.audioPath;
    exportRequest.background = backdrop;
    exportRequest.start = startS;
    exportRequest.duration = durationS;
    StageProgress lines;
    const auto report = [&lines](double fraction) { lines(fraction, Cli::tr("exporting")); };
    const ExportResult result = chosenPreset ? exportWithPreset(exportRequest, *chosenPreset, report, interruption())
                                             : exportAnimation(exportRequest, report, interruption());
    if (result.status == ExportStatus::Cancelled)
        return fail(ExitInterrupted, Cli::tr("%1: interrupted; nothing was written").arg(out));
    if (result.status == ExportStatus::OverLimit)
        return fail(ExitBadInput,
            Cli::tr("%1; nothing was written (--start and --duration choose a stretch)").arg(result.error));
    if (!result.ok())
        return fail(result.status == ExportStatus::BadInput ? ExitBadInput : ExitFailed, result.error);
    return ExitOk;
}

const CommandRegistrar registrar({QStringLiteral("animate"),
    QString::fromUtf8(QT_TRANSLATE_NOOP("toonface::cli::Cli",
        "Make the face of a photo or project talk, and export the animation (SVG, HTML, MP4, GIF, WebM, MOV, "
        "APNG, WebP or PNG frames).")),
    QStringLiteral(
        "animate IMAGE|PROJECT|CLIP [--audio A --script S | --say TEXT | --video CLIP] [--method "
        "auto|classic|landmarks] [--neutral-frame N|auto] [--snap-mouth] [--emotion NAME] [--no-blink] [--fps N] "
        "[--style NAME] [--frame head|photo] [--background COLOUR|transparent|PHOTO] [--preset NAME] [--start S] "
        "[--duration S] [--project OUT.toonface] -o OUT.svg|OUT.html|OUT.mp4|OUT.gif|OUT.webm|OUT.mov|OUT.apng|"
        "OUT.webp|DIR/"),
    runAnimate, true});

} // namespace

} // namespace toonface::cli
