#include "render/htmlplayer.h"

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
          "<title>Toonface animation</title>\n<style>\n"
          "body { margin: 0; background: #eee; font-family: sans-serif; }\n"
          "#tf-stage { display: flex; flex-direction: column; align-items: center; gap: 8px; padding: 8px; }\n"
          "#tf-stage > svg { display: block; width: auto; height: calc(100vh - 80px); max-width: 100%; "
          "background: #fff; }\n"
          "#tf-controls { display: flex; gap: 8px; align-items: center; width: min(100%, 640px); }\n"
          "#tf-controls > audio, #tf-seek { flex: 1; }\n"
          "</style>\n</head>\n<body>\n<div id=\"tf-stage\">\n";
    out += e->svg;
    out += "<div id=\"tf-controls\">";
    if (!e->audioUri.isEmpty()) {
        out += "<audio id=\"tf-audio\" controls preload=\"auto\" src=\"" + escaped(e->audioUri) + "\"></audio>";
    } else {
        out += "<button id=\"tf-toggle\" type=\"button\">Play</button>"
               "<input id=\"tf-seek\" type=\"range\" min=\"0\" step=\"0.01\" value=\"0\" max=\""
            + decimal(e->duration) + "\">";
    }
    out += "</div>\n</div>\n<script>\n(function () {\n  var offset = " + decimal(e->audioOffset)
        + ";\n  var length = " + decimal(e->duration) + ";\n";
    out += R"(  var svg = document.querySelector('#tf-stage > svg');
  var audio = document.getElementById('tf-audio');
  svg.pauseAnimations();
  svg.setCurrentTime(0);
  if (audio) {
    // The audio clock leads: the animation follows it on play, pause and seek, and is put back
    // whenever it drifts more than a frame (lip sync shows from about 45 ms).
    var lock = function () {
      var t = audio.currentTime + offset;
      if (Math.abs(svg.getCurrentTime() - t) > 0.04) svg.setCurrentTime(t);
    };
    var tick = function () {
      if (audio.paused) return;
      lock();
      requestAnimationFrame(tick);
    };
    audio.addEventListener('play', function () { lock(); svg.unpauseAnimations(); requestAnimationFrame(tick); });
    audio.addEventListener('pause', function () { svg.pauseAnimations(); lock(); });
    // An animation longer than its sound plays on to its end.
    audio.addEventListener('ended', function () { if (length > audio.currentTime + offset) svg.unpauseAnimations(); });
    ['seeking', 'seeked', 'timeupdate', 'loadedmetadata'].forEach(function (e) { audio.addEventListener(e, lock); });
    return;
  }
  var toggle = document.getElementById('tf-toggle');
  var seek = document.getElementById('tf-seek');
  var playing = false;
  var show = function () { seek.value = svg.getCurrentTime(); toggle.textContent = playing ? 'Pause' : 'Play'; };
  var tick = function () {
    if (!playing) return;
    if (svg.getCurrentTime() >= length) { playing = false; svg.pauseAnimations(); }
    show();
    requestAnimationFrame(tick);
  };
  toggle.addEventListener('click', function () {
    playing = !playing;
    if (playing) {
      if (svg.getCurrentTime() >= length) svg.setCurrentTime(0);
      svg.unpauseAnimations();
      requestAnimationFrame(tick);
    } else {
      svg.pauseAnimations();
    }
    show();
  });
  seek.addEventListener('input', function () { svg.setCurrentTime(parseFloat(seek.value)); });
})();
</script>
</body>
</html>
)";
    return out;
}

} // namespace toonface
