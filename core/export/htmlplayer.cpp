#include "export/htmlplayer.h"

#include <QString>

namespace toonface {

namespace {

QByteArray decimal(double v)
{
    return QByteArray::number(v, 'f', 6);
}

QByteArray escaped(const QByteArray &text)
{
    return QString::fromUtf8(text).toHtmlEscaped().toUtf8();
}

} // namespace

QByteArray exportHtmlPlayer(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    const std::optional<SmilElement> e = exportSmilElement(face, style, timeline, shapes, options, error);
    if (!e)
        return {};
    QByteArray out
        = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
          // Nothing in the page loads from outside it: the drawing and the sound are inside (or,
          // when the sound is referenced, beside it), whatever a user's layer held.
          "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
          "style-src 'unsafe-inline'; img-src data:; media-src 'self' data: blob: file:; base-uri 'none'; "
          "form-action 'none'\">\n"
          "<title>Toonface animation</title>\n<style>\n"
          "body { margin: 0; background: #eee; font-family: sans-serif; }\n"
          "#tf-stage { display: flex; flex-direction: column; align-items: center; gap: 8px; padding: 8px; }\n"
          "#tf-stage > svg { display: block; width: auto; height: calc(100vh - 80px); max-width: 100%; "
          "background: #fff; cursor: pointer; }\n"
          "#tf-controls { display: flex; gap: 8px; align-items: center; width: min(100%, 640px); }\n"
          "#tf-toggle { min-width: 5em; }\n"
          "#tf-seek { flex: 1; }\n"
          "#tf-time { font-variant-numeric: tabular-nums; white-space: nowrap; }\n"
          "</style>\n</head>\n<body>\n<div id=\"tf-stage\">\n";
    out += e->svg;
    out += "<div id=\"tf-controls\"><button id=\"tf-toggle\" type=\"button\">Play</button>"
           "<input id=\"tf-seek\" type=\"range\" min=\"0\" step=\"0.01\" value=\"0\" aria-label=\"Position\" max=\""
        + decimal(e->duration) + "\"><span id=\"tf-time\"></span>";
    if (!e->audioUri.isEmpty())
        out += "<audio id=\"tf-audio\" preload=\"auto\" src=\"" + escaped(e->audioUri) + "\"></audio>";
    out += "</div>\n</div>\n<script>\n(function () {\n  var offset = " + decimal(e->audioOffset)
        + ";\n  var clip = " + decimal(e->audioDuration) + ";\n  var length = " + decimal(e->duration) + ";\n";
    out += R"(  var svg = document.querySelector('#tf-stage > svg');
  var audio = document.getElementById('tf-audio');
  var toggle = document.getElementById('tf-toggle');
  var seek = document.getElementById('tf-seek');
  var clock = document.getElementById('tf-time');
  var playing = false;
  function format(t) {
    var m = Math.floor(t / 60), s = t - 60 * m;
    return m + ':' + (s < 10 ? '0' : '') + s.toFixed(1);
  }
  // Chromium applies setCurrentTime() on a paused document at its next frame: callers that
  // have just set the time pass it on.
  function now(t) { return t === undefined ? svg.getCurrentTime() : t; }
  function show(t) {
    t = Math.min(Math.max(now(t), 0), length);
    seek.value = t;
    clock.textContent = format(t) + ' / ' + format(length);
    toggle.textContent = playing ? 'Pause' : 'Play';
  }
  // The sound covers [offset, offset + clip) of the animation (less if the file is shorter).
  function audible(t) {
    return audio && t >= offset && t - offset < Math.min(clip || Infinity, audio.duration || Infinity);
  }
  // While both play, the audio leads; otherwise the sound waits where the animation is.
  function follow(t) {
    if (!audio) return;
    t = now(t);
    if (playing && audible(t)) {
      if (audio.paused) {
        audio.currentTime = t - offset;
        var started = audio.play();
        if (started && started.catch) started.catch(function () { pause(); });
      } else if (Math.abs(audio.currentTime + offset - t) > 0.04) {
        svg.setCurrentTime(audio.currentTime + offset);
      }
    } else {
      if (!audio.paused) audio.pause();
      var at = Math.max(0, t - offset);
      if (Math.abs(audio.currentTime - at) > 0.01) audio.currentTime = at;
    }
  }
  function tick() {
    if (!playing) return;
    if (svg.getCurrentTime() >= length) {
      svg.setCurrentTime(length);
      pause();
      return;
    }
    follow();
    show();
    requestAnimationFrame(tick);
  }
  function play() {
    var t = svg.getCurrentTime();
    if (t >= length) svg.setCurrentTime(t = 0);
    playing = true;
    svg.unpauseAnimations();
    follow(t);
    show(t);
    requestAnimationFrame(tick);
  }
  function pause() {
    playing = false;
    svg.pauseAnimations();
    follow();
    show();
  }
  function seekTo(t) {
    t = Math.min(Math.max(t, 0), length);
    svg.setCurrentTime(t);
    if (audio && playing && !audio.paused) audio.pause(); // follow() restarts it at the new place
    follow(t);
    show(t);
  }
  svg.pauseAnimations();
  svg.setCurrentTime(0);
  toggle.addEventListener('click', function () { if (playing) pause(); else play(); });
  svg.addEventListener('click', function () { if (playing) pause(); else play(); });
  seek.addEventListener('input', function () { seekTo(parseFloat(seek.value)); });
  document.addEventListener('keydown', function (e) {
    if (e.target === seek && e.key !== ' ') return; // the slider steps on its own
    if (e.key === ' ') { e.preventDefault(); if (playing) pause(); else play(); }
    else if (e.key === 'ArrowLeft') seekTo(svg.getCurrentTime() - 1);
    else if (e.key === 'ArrowRight') seekTo(svg.getCurrentTime() + 1);
  });
  if (audio) audio.addEventListener('loadedmetadata', function () { follow(); show(); });
  window.toonfacePlayer = { play: play, pause: pause, seek: seekTo, time: function () { return svg.getCurrentTime(); } };
  show();
})();
</script>
</body>
</html>
)";
    return out;
}

} // namespace toonface
