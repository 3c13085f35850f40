#include "export/smilaudio.h"

#include "anim/timeline.h"
#include "export/smilutil.h"
#include "export/svgnumbers.h"
#include "export/svgxml.h"
#include "i18n/coretext.h"
#include "media/audiomix.h"
#include "media/mediareader.h"
#include "media/soundcheck.h"
#include "media/userfile.h"
#include "speech/audio.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QUrl>

#include <algorithm>

namespace toonface::smil {

namespace {

// The sound of `path` decoded and encoded anew, never the file's own bytes: whatever the file
// holds besides its sound (or instead of it) stays out of the export. AAC in MP4 (at most
// 32 kHz: speech keeps its sound below 16 kHz) when `compress`, 16-bit PCM WAV at the file's own
// rate (at most 48 kHz) otherwise. False with *problem when the file is not a sound FFmpeg
// decodes.
bool decodedSound(const QString &path, bool compress, QByteArray *bytes, QByteArray *mime, QString *problem)
{
    const std::optional<MediaInfo> info = probeMedia(path, problem);
    if (!info)
        return false;
    if (!info->hasAudio) {
        *problem = withProblem(path, SoundText::tr("holds no sound"));
        return false;
    }
    const int native = info->audioSampleRate > 0 ? info->audioSampleRate : 32000;
    const int rate = std::min(native, compress ? 32000 : 48000);
    const std::optional<QVector<float>> samples = readAudio(path, rate, problem);
    if (!samples)
        return false;
    if (samples->isEmpty()) {
        *problem = withProblem(path, SoundText::tr("holds no sound"));
        return false;
    }
    QTemporaryDir dir;
    if (!dir.isValid()) {
        *problem
            = withProblem(path, SoundText::tr("no room for a temporary copy of the sound: %1").arg(dir.errorString()));
        return false;
    }
    const QString encoded = dir.filePath(compress ? QStringLiteral("sound.m4a") : QStringLiteral("sound.wav"));
    if (!writeAudio(encoded, Audio {*samples, rate}, problem))
        return false;
    QFile file(encoded);
    if (!file.open(QIODevice::ReadOnly)) {
        *problem = withProblem(encoded, file.errorString());
        return false;
    }
    *bytes = file.readAll();
    *mime = compress ? "audio/mp4" : "audio/wav";
    return !bytes->isEmpty();
}

} // namespace

bool resolveAudio(
    const Timeline &timeline, double duration, const AnimationExportOptions &options, SmilAudio *out, QString *error)
{
    if (options.audio == ExportAudio::None)
        return true;
    QString path = options.audioPath;
    out->duration = duration;
    // The audio track as one file: a clip's own, or the clips mixed (kept until the sound is
    // encoded into the page, which a reference to a file outside it cannot be).
    QTemporaryDir mixFolder;
    if (path.isEmpty() && !soundingClips(timeline.audioClips()).isEmpty()) {
        QString problem;
        const std::optional<TrackSound> track
            = trackSoundFile(timeline.audioClips(), mixFolder.path(), QStringLiteral("mix.wav"), &problem);
        if (!track) {
            *error = SoundText::tr("the sound cannot be used: %1").arg(problem);
            return false;
        }
        if (track->mixed && options.audio != ExportAudio::Embed) {
            *error = SoundText::tr("the sound of several or trimmed recordings can only be embedded, not referenced");
            return false;
        }
        path = track->path;
        out->offset = track->offset;
        out->duration = track->duration > 0 ? track->duration : duration;
    }
    if (path.isEmpty())
        return true;
    // Only a regular file that decodes as sound reaches an export, embedded or referenced: a
    // shared project naming ~/.ssh/id_rsa as its sound gets an error, not the key in its page.
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty()) {
        *error = withProblem(path, problem);
        return false;
    }
    QString problem;
    if (options.audio == ExportAudio::Embed) {
        QByteArray bytes, mime;
        if (!decodedSound(path, options.compressAudio, &bytes, &mime, &problem)) {
            *error = SoundText::tr("the sound cannot be used: %1").arg(problem);
            return false;
        }
        out->uri = "data:" + mime + ";base64," + bytes.toBase64();
        return true;
    }
    // A referenced sound is checked, not decoded: its header and a few packets (checkSound),
    // then every packet's length without decoding (mediaDamage), so an hour-long recording costs
    // milliseconds and a copy cut short is still refused.
    const SoundCheck check = checkSound(path);
    const QString damage = check.ok() ? mediaDamage(path) : QString();
    if (!check.ok() || !damage.isEmpty()) {
        *error = SoundText::tr("the sound cannot be used: %1").arg(check.ok() ? damage : check.error);
        return false;
    }
    const QFileInfo info(path);
    const QDir base(options.outputDir.isEmpty() ? QDir::currentPath() : options.outputDir);
    out->uri = QUrl::toPercentEncoding(base.relativeFilePath(info.absoluteFilePath()), "/");
    return true;
}

QByteArray metadata(const SmilAudio &audio, double duration, double fps)
{
    QByteArray m = "\n<metadata><tf:animation xmlns:tf=\"" + QByteArray(kNamespace) + "\" duration=\"";
    appendFixed(m, quantize(duration, 6), 6);
    m += "\" fps=\"";
    appendFixed(m, quantize(fps, 6), 6);
    m += "\"/>";
    if (!audio.uri.isEmpty()) {
        m += "<tf:audio xmlns:tf=\"" + QByteArray(kNamespace) + "\" href=\"";
        appendEscaped(m, audio.uri, true);
        m += "\" offset=\"";
        appendFixed(m, quantize(audio.offset, 6), 6);
        m += "\" duration=\"";
        appendFixed(m, quantize(audio.duration, 6), 6);
        m += "\"/>";
    }
    m += "</metadata>\n";
    return m;
}

QByteArray playerScript(QRectF canvas)
{
    const double r = 0.08 * std::min(canvas.width(), canvas.height());
    const double cx = canvas.center().x(), cy = canvas.center().y();
    auto n = [](double v) {
        QByteArray s;
        appendFixed(s, quantize(v, 1), 1);
        return s;
    };
    QByteArray out = "<g id=\"tf-play\" visibility=\"hidden\" cursor=\"pointer\"><circle cx=\"" + n(cx) + "\" cy=\""
        + n(cy) + "\" r=\"" + n(r) + "\" fill=\"#000\" fill-opacity=\".55\"/><path d=\"M" + n(cx - 0.35 * r) + ','
        + n(cy - 0.5 * r) + 'L' + n(cx + 0.55 * r) + ',' + n(cy) + 'L' + n(cx - 0.35 * r) + ',' + n(cy + 0.5 * r)
        + "Z\" fill=\"#fff\"/></g>\n";
    out += R"(<script type="text/ecmascript"><![CDATA[
(function () {
  var svg = document.documentElement;
  var ns = 'urn:toonface:animation:1';
  var meta = document.getElementsByTagNameNS(ns, 'audio')[0];
  var info = document.getElementsByTagNameNS(ns, 'animation')[0];
  var button = document.getElementById('tf-play');
  if (!meta || !info || !svg.pauseAnimations) return;
  var audio = new Audio(meta.getAttribute('href'));
  var offset = parseFloat(meta.getAttribute('offset')) || 0;
  var clip = parseFloat(meta.getAttribute('duration')) || 0;
  var length = parseFloat(info.getAttribute('duration')) || 0;
  var playing = false;
  function show(visible) { button.setAttribute('visibility', visible ? 'visible' : 'hidden'); }
  function audible(t) { return t - offset >= 0 && t - offset < Math.min(clip, audio.duration || clip); }
  function startAudio(t) {
    audio.currentTime = Math.max(0, t - offset);
    var p = audio.play();
    return p && p.then ? p : { then: function (ok) { ok(); } };
  }
  function tick() {
    if (!playing) return;
    var t = svg.getCurrentTime();
    if (t >= length) { stop(); return; }
    if (audible(t)) {
      if (audio.paused) startAudio(t);
      // Put the animation back on the audio clock when it drifts more than a frame.
      else if (Math.abs(audio.currentTime + offset - t) > 0.04) svg.setCurrentTime(audio.currentTime + offset);
    }
    requestAnimationFrame(tick);
  }
  function play() {
    if (svg.getCurrentTime() >= length) svg.setCurrentTime(0);
    var t = svg.getCurrentTime();
    var started = audible(t) ? startAudio(t) : { then: function (ok) { ok(); } };
    started.then(function () {
      playing = true; show(false); svg.unpauseAnimations(); requestAnimationFrame(tick);
    }, function () { show(true); });
  }
  function stop() { playing = false; audio.pause(); svg.pauseAnimations(); show(true); }
  svg.pauseAnimations();
  svg.setCurrentTime(0);
  svg.addEventListener('click', function () { if (playing) stop(); else play(); });
  play();
})();
]]></script>
)";
    return out;
}

} // namespace toonface::smil
