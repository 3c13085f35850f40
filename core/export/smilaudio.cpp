#include "export/smilaudio.h"

#include "anim/timeline.h"
#include "export/smilutil.h"
#include "export/svgnumbers.h"
#include "export/svgxml.h"
#include "i18n/coretext.h"
#include "media/mediareader.h"
#include "speech/audio.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QMimeDatabase>
#include <QTemporaryDir>
#include <QUrl>

#include <algorithm>

namespace toonface::smil {

namespace {

QByteArray audioMimeType(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    static const QHash<QString, const char *> known = {{QStringLiteral("wav"), "audio/wav"},
        {QStringLiteral("mp3"), "audio/mpeg"}, {QStringLiteral("ogg"), "audio/ogg"},
        {QStringLiteral("oga"), "audio/ogg"}, {QStringLiteral("opus"), "audio/ogg"},
        {QStringLiteral("m4a"), "audio/mp4"}, {QStringLiteral("aac"), "audio/aac"},
        {QStringLiteral("flac"), "audio/flac"}, {QStringLiteral("webm"), "audio/webm"}};
    if (const auto it = known.constFind(suffix); it != known.constEnd())
        return *it;
    return QMimeDatabase().mimeTypeForFile(path).name().toLatin1();
}

// The sound of `path` as AAC in MP4 when it is stored uncompressed or losslessly; false (and
// the file is embedded as it is) for compressed sound or a file FFmpeg cannot read (the
// browser may still play it).
bool compressedAudio(const QString &path, QByteArray *bytes)
{
    QString why;
    const std::optional<MediaInfo> info = probeMedia(path, &why);
    if (!info || !info->hasAudio)
        return false;
    static const QStringList lossless = {QStringLiteral("flac"), QStringLiteral("alac"), QStringLiteral("wavpack"),
        QStringLiteral("ape"), QStringLiteral("tta")};
    if (!info->audioCodec.startsWith(QLatin1StringView("pcm_")) && !lossless.contains(info->audioCodec))
        return false;
    // Speech keeps its sound below 16 kHz: 32 kHz sampling is enough, lower rates stay as they are.
    const int rate = std::min(info->audioSampleRate > 0 ? info->audioSampleRate : 32000, 32000);
    const std::optional<QVector<float>> samples = readAudio(path, rate, &why);
    QTemporaryDir dir;
    if (!samples || !dir.isValid())
        return false;
    const QString m4a = dir.filePath(QStringLiteral("sound.m4a"));
    QFile file(m4a);
    if (!writeAudio(m4a, Audio {*samples, rate}, &why) || !file.open(QIODevice::ReadOnly))
        return false;
    *bytes = file.readAll();
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
    if (timeline.audio()) {
        if (path.isEmpty())
            path = timeline.audio()->path;
        out->offset = timeline.audio()->offset;
        out->duration = timeline.audio()->duration > 0 ? timeline.audio()->duration : duration;
    }
    if (path.isEmpty())
        return true;
    const QFileInfo info(path);
    if (options.audio == ExportAudio::Embed) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            *error = SoundText::tr("cannot read the audio file %1: %2").arg(path, file.errorString());
            return false;
        }
        QByteArray aac;
        if (options.compressAudio && compressedAudio(path, &aac))
            out->uri = "data:audio/mp4;base64," + aac.toBase64();
        else
            out->uri = "data:" + audioMimeType(path) + ";base64," + file.readAll().toBase64();
        return true;
    }
    if (!info.isFile()) {
        *error = SoundText::tr("the audio file %1 does not exist").arg(path);
        return false;
    }
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
