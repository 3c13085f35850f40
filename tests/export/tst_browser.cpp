#include "animationfixture.h"
#include "chromium.h"
#include "imagedifference.h"
#include "testmain.h"

#include "anim/timeline.h"
#include "export/framerenderer.h"
#include "export/htmlplayer.h"
#include "export/smilexport.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "render/svgface.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

#include <optional>

using namespace toonface;
using testing::meanDifference;

namespace {

// Chromium renders each frame at this size, as does Toonface's own renderer.
constexpr int kCell = 256;

// The exported SVG as an element of a page, its ids prefixed so several copies can share
// the page (clip paths refer to ids).
QByteArray inlineCopy(QByteArray svg, const QByteArray &prefix)
{
    svg = svg.mid(svg.indexOf("<svg"));
    svg.replace("id=\"", "id=\"" + prefix);
    svg.replace("url(#", "url(#" + prefix);
    svg.replace("href=\"#", "href=\"#" + prefix);
    return svg;
}

} // namespace

// Headless Chromium plays the exported animation: paused at chosen times, its frames match
// Toonface's own renderer (QSvgRenderer) frame for frame, and the HTML player follows the
// audio element when it seeks.
class TestBrowser : public QObject
{
    Q_OBJECT

private:
    QString m_chromium;
    QTemporaryDir m_dir;
    FaceModel m_face = test::animationFace();
    MouthShapeSet m_shapes;
    Timeline m_timeline;

    // Writes `content` to NAME+suffix in the test's folder and loads it in headless Chromium with
    // `extra` arguments; returns what Chromium printed on stdout (empty with m_startFailure set
    // when it could not start, or with a warning when it did not finish).
    std::optional<QByteArray> runChromium(
        const QByteArray &content, const QString &name, const QString &suffix, const QStringList &extra)
    {
        const QString page = m_dir.filePath(name + suffix);
        QFile f(page);
        if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size())
            return std::nullopt;
        f.close();
        QTemporaryDir profile;
        QProcess chromium;
        QStringList args = {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
            QStringLiteral("--disable-gpu"), QStringLiteral("--disable-quic"), QStringLiteral("--no-first-run"),
            QStringLiteral("--disable-background-networking"), QStringLiteral("--disable-component-update"),
            QStringLiteral("--disable-sync"), QStringLiteral("--user-data-dir=") + profile.path()};
        args << extra << QUrl::fromLocalFile(page).toString();
        QElapsedTimer timer;
        timer.start();
        chromium.start(m_chromium, args);
        if (!chromium.waitForStarted(20000)) {
            m_startFailure = chromium.errorString();
            return std::nullopt;
        }
        if (!chromium.waitForFinished(90000)) {
            chromium.kill();
            chromium.waitForFinished();
            qWarning("Chromium did not finish: %s", chromium.readAllStandardError().right(2000).constData());
            return std::nullopt;
        }
        qInfo("Chromium took %lld ms for %s", qlonglong(timer.elapsed()), qPrintable(name));
        m_lastChromiumErrors = chromium.readAllStandardError();
        return chromium.readAllStandardOutput();
    }
    QByteArray m_lastChromiumErrors;

    // Loads a page (`html`, or an SVG document with suffix .svg) in Chromium and returns its
    // screenshot of the window.
    QImage screenshot(const QByteArray &html, QSize window, const QString &name, const QStringList &extra = {},
        const QString &suffix = QStringLiteral(".html"))
    {
        const QString png = m_dir.filePath(name + QStringLiteral(".png"));
        const QStringList args
            = QStringList {QStringLiteral("--hide-scrollbars"), QStringLiteral("--force-device-scale-factor=1"),
                  QStringLiteral("--screenshot=") + png,
                  QStringLiteral("--window-size=%1,%2").arg(window.width()).arg(window.height())}
            + extra;
        if (!runChromium(html, name, suffix, args))
            return {};
        QImage image(png);
        if (image.isNull())
            qWarning("no screenshot; Chromium said: %s", m_lastChromiumErrors.right(2000).constData());
        if (const QString keep = qEnvironmentVariable("TOONFACE_BROWSER_OUT"); !keep.isEmpty() && !image.isNull())
            image.save(QDir(keep).filePath(name + QStringLiteral(".png")));
        return image;
    }
    QString m_startFailure;

    QRect scaled(const QRectF &r) const { return QRectF(r.topLeft() / 2.0, r.size() / 2.0).toAlignedRect(); }

    // The region the mouth and jaw can reach, in a cell.
    QRect mouthBox() const
    {
        const Fapu f = m_face.fapu();
        const QPointF l = m_face.point("8.4"), r = m_face.point("8.3");
        const double top = m_face.point("8.9").y() - 0.4 * f.mns0;
        const double bottom = m_face.point("8.2").y() + 0.9 * f.mns0;
        return scaled(QRectF(QPointF(l.x() - 0.15 * f.mw0, top), QPointF(r.x() + 0.15 * f.mw0, bottom)));
    }

    QRect faceBox() const { return scaled(m_face.bounds().adjusted(-10, -10, 10, 10)); }

private Q_SLOTS:
    void initTestCase()
    {
        m_chromium = test::chromiumPath();
        if (m_chromium.isEmpty())
            QSKIP("Chromium is not installed (Debian package chromium): the browser cannot start");
        QVERIFY(m_dir.isValid());
        const QString wav = m_dir.filePath(QStringLiteral("voice.wav"));
        QVERIFY(test::writeToneWav(wav, 10.0));
        m_timeline = test::animationTimeline(wav);
    }

    // One page holds the animation six times, each paused at its own time: at rest, the open
    // vowel, the silence after a phrase, the middle of an ease, the head shaking while a smile
    // fades, and a blink; and the frame-mode export twice. One launch of Chromium renders all.
    void framesMatchQtRenderer()
    {
        AnimationExportOptions options;
        options.audio = ExportAudio::None;
        QString error;
        const QByteArray svg = exportSmilSvg(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));

        double blink = 5.5;
        for (const BlinkEvent &b : m_timeline.blinks()) {
            if (b.time > 0.5 && b.time < 9.0) {
                blink = b.time + b.duration * (kBlinkPhases.closing + kBlinkPhases.shut / 2);
                break;
            }
        }
        const QVector<double> times = {0.0, test::openVowelTime(), test::silenceTime(), 0.6, 2.3, blink};
        options.mode = AnimationExportOptions::Mode::Frames;
        const QByteArray frameSvg = exportSmilSvg(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!frameSvg.isEmpty(), qPrintable(error));
        // Frame mode shows frame i from i / fps on: times just past two frames' starts.
        const QVector<double> frameTimes = {46 / 25.0 + 0.01, 58 / 25.0 + 0.01};
        const int columns = 3;
        QByteArray page = "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>html,body{margin:0;padding:0;"
                          "background:#fff;overflow:hidden}#grid{display:grid;grid-template-columns:repeat(3,"
            + QByteArray::number(kCell) + "px)}svg{display:block;width:" + QByteArray::number(kCell)
            + "px;height:" + QByteArray::number(kCell) + "px}</style></head><body><div id=\"grid\">";
        for (qsizetype i = 0; i < times.size(); ++i)
            page += inlineCopy(svg, "c" + QByteArray::number(i) + '-');
        for (qsizetype i = 0; i < frameTimes.size(); ++i)
            page += inlineCopy(frameSvg, "f" + QByteArray::number(i) + '-');
        page += "</div><script>window.addEventListener('load', function () {var times = [";
        for (qsizetype i = 0; i < times.size() + frameTimes.size(); ++i)
            page += (i ? "," : "")
                + QByteArray::number(i < times.size() ? times[i] : frameTimes[i - times.size()], 'g', 10);
        page += "]; document.querySelectorAll('svg').forEach(function (s, i) { s.pauseAnimations(); "
                "s.setCurrentTime(times[i]); });});</script></body></html>";

        const qsizetype cells = times.size() + frameTimes.size();
        const QSize window(columns * kCell, int((cells + columns - 1) / columns) * kCell);
        const QImage shot = screenshot(page, window, QStringLiteral("frames"));
        if (shot.isNull() && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        QVERIFY(!shot.isNull());
        QCOMPARE(shot.size(), window);

        const FrameRenderer renderer(SvgFace(m_face, Style()), m_timeline, m_shapes, QSize(kCell, kCell));
        QVector<QImage> browser, qt;
        for (qsizetype i = 0; i < times.size(); ++i) {
            browser.append(shot.copy(int(i % columns) * kCell, int(i / columns) * kCell, kCell, kCell));
            qt.append(renderer.renderAt(times[i]));
            if (const QString keep = qEnvironmentVariable("TOONFACE_BROWSER_OUT"); !keep.isEmpty())
                qt.last().save(QDir(keep).filePath(QStringLiteral("qt-%1.png").arg(i)));
        }

        // Chromium (Skia) and QSvgRenderer antialias edges differently, and Chromium clips the
        // eyeballs where QSvgRenderer covers them with skin: every outline differs by a pixel's
        // worth of blending. Measured, that averages under 1 level of 255 over the face box and
        // up to about 2 over the mouth box (where outlines are densest); the open mouth against
        // the shut one differs by over 30. So 4 leaves room for renderer versions, while a mouth
        // shape or head pose of another time fails (checked below).
        constexpr double kSameFrame = 4.0;
        for (qsizetype i = 0; i < times.size(); ++i) {
            const double face = meanDifference(browser[i], qt[i], faceBox());
            const double mouth = meanDifference(browser[i], qt[i], mouthBox());
            qInfo("t = %.3f s: browser vs Qt, face box %.2f, mouth box %.2f", times[i], face, mouth);
            QVERIFY2(face <= kSameFrame, qPrintable(QStringLiteral("frame at %1 s: %2").arg(times[i]).arg(face)));
            QVERIFY2(mouth <= kSameFrame, qPrintable(QStringLiteral("mouth at %1 s: %2").arg(times[i]).arg(mouth)));
        }

        // The open vowel is not the silence: the mouth region changes far beyond the
        // renderers' disagreement, in the browser as in Qt.
        const double open = meanDifference(browser[1], browser[2], mouthBox());
        const double openQt = meanDifference(qt[1], qt[2], mouthBox());
        qInfo("open vowel vs silence, mouth box: browser %.2f, Qt %.2f", open, openQt);
        QVERIFY(open > 4 * kSameFrame);
        QVERIFY(openQt > 4 * kSameFrame);
        // Frame mode: the frame of its time.
        for (qsizetype i = 0; i < frameTimes.size(); ++i) {
            const qsizetype cell = times.size() + i;
            const QImage shown = shot.copy(int(cell % columns) * kCell, int(cell / columns) * kCell, kCell, kCell);
            const QImage frame = renderer.render(int(frameTimes[i] * 25));
            const double face = meanDifference(shown, frame, faceBox());
            qInfo("frame mode at %.3f s: browser vs Qt's frame %d, face box %.2f", frameTimes[i],
                int(frameTimes[i] * 25), face);
            QVERIFY(face <= kSameFrame);
            if (const QString keep = qEnvironmentVariable("TOONFACE_BROWSER_OUT"); !keep.isEmpty())
                frame.save(QDir(keep).filePath(QStringLiteral("qt-frame-%1.png").arg(i)));
        }
        // And a frame compared with Qt's drawing of another time fails the match: the test
        // can tell times apart.
        QVERIFY(meanDifference(browser[1], qt[2], mouthBox()) > kSameFrame);
        QVERIFY(meanDifference(browser[4], qt[0], faceBox()) > kSameFrame); // the shaking head
    }

    // The SVG with its sound, opened on its own where sound may not start without a click:
    // it waits at time 0 behind its play button.
    void standaloneSvgWaitsForAClick()
    {
        AnimationExportOptions options;
        options.audio = ExportAudio::Embed;
        QString error;
        const QByteArray svg = exportSmilSvg(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));
        const QSize size = m_face.imageSize();
        const QImage shot = screenshot(svg, size, QStringLiteral("standalone"),
            {QStringLiteral("--virtual-time-budget=2000"), QStringLiteral("--autoplay-policy=user-gesture-required")},
            QStringLiteral(".svg"));
        if (shot.isNull() && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        QVERIFY(!shot.isNull());
        const FrameRenderer renderer(SvgFace(m_face, Style()), m_timeline, m_shapes, size);
        const QImage start = renderer.renderAt(0);
        // The button: a dark disc of radius 0.08 of the drawing, in its centre.
        const int r = int(0.08 * std::min(size.width(), size.height()));
        const QRect button(size.width() / 2 - r / 2, size.height() / 2 - r / 2, r, r);
        const double onButton = meanDifference(shot, start, button);
        // Below it, the drawing at time 0.
        const QRect below = QRectF(m_face.bounds())
                                .toAlignedRect()
                                .adjusted(0, r * 2, 0, 0)
                                .intersected(QRect(0, size.height() / 2 + r + 2, size.width(), size.height()));
        const double elsewhere = meanDifference(shot, start, below);
        qInfo("standalone SVG: button region vs the drawing %.2f, below it %.2f", onButton, elsewhere);
        QVERIFY(onButton > 40);
        QVERIFY(elsewhere <= 4.0);
    }

    // The HTML player: dragging its seek bar moves the animation, and the sound with it.
    void htmlPlayerFollowsSeeks()
    {
        AnimationExportOptions options;
        options.audio = ExportAudio::Embed;
        QString error;
        QByteArray html = exportHtmlPlayer(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!html.isEmpty(), qPrintable(error));
        const double seekTo = test::openVowelTime();
        // After the page loads, move the seek bar as a user dragging it would; the player's own
        // listeners must carry the animation there. Only the drawing is shown, at the cell size.
        const QByteArray cell = QByteArray::number(kCell) + "px";
        const QByteArray probe = "<style>#tf-controls{display:none}#tf-stage{display:block;padding:0}"
                                 "html,body{overflow:hidden}#tf-stage>svg{width:"
            + cell + ";height:" + cell + "}</style>" + seekScript(seekTo, false);
        html.replace("</body>", probe + "</body>");
        const QImage shot = screenshot(html, QSize(kCell, kCell), QStringLiteral("player"),
            {QStringLiteral("--virtual-time-budget=3000"),
                QStringLiteral("--autoplay-policy=no-user-gesture-required")});
        if (shot.isNull() && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        QVERIFY(!shot.isNull());

        const FrameRenderer renderer(SvgFace(m_face, Style()), m_timeline, m_shapes, QSize(kCell, kCell));
        const double atSeek = meanDifference(shot, renderer.renderAt(seekTo), mouthBox());
        const double atStart = meanDifference(shot, renderer.renderAt(0), mouthBox());
        qInfo(
            "player after seeking to %.3f s: mouth box vs Qt at that time %.2f, at 0 s %.2f", seekTo, atSeek, atStart);
        QVERIFY2(atSeek <= 4.0, qPrintable(QString::number(atSeek)));
        QVERIFY(atStart > 4.0);
    }

    // A sound that starts after a lead-in: seeking into the lead-in keeps the sound at its start
    // and silent; seeking past it puts the sound at the animation time less the offset. The
    // player's state is read back from the page's DOM.
    void htmlPlayerWithLeadIn_data()
    {
        QTest::addColumn<double>("seekTo");
        QTest::addColumn<double>("audioTime");
        constexpr double offset = 0.8;
        QTest::newRow("lead-in") << 0.4 << 0.0;
        QTest::newRow("speech") << test::openVowelTime() << test::openVowelTime() - offset;
        QTest::newRow("late") << 7.5 << 7.5 - offset;
    }
    void htmlPlayerWithLeadIn()
    {
        QFETCH(double, seekTo);
        QFETCH(double, audioTime);
        Timeline timeline = m_timeline;
        timeline.setAudioClips({AudioClip {m_dir.filePath(QStringLiteral("voice.wav")), 0.8, 9.2}});
        AnimationExportOptions options;
        options.audio = ExportAudio::Embed;
        QString error;
        QByteArray html = exportHtmlPlayer(m_face, Style(), timeline, m_shapes, options, &error);
        QVERIFY2(!html.isEmpty(), qPrintable(error));
        html.replace("</body>", seekScript(seekTo, true) + "</body>");
        const QByteArray dom = dumpDom(html, QStringLiteral("lead-in"));
        if (dom.isEmpty() && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        static const QRegularExpression state(
            QStringLiteral("data-svg-time=\"([^\"]*)\" data-audio-time=\"([^\"]*)\" data-audio-paused=\"([^\"]*)\""));
        const auto m = state.match(QString::fromUtf8(dom));
        QVERIFY2(m.hasMatch(), dom.right(600).constData());
        qInfo("seek to %.3f s: animation at %s s, sound at %s s, paused %s", seekTo, qPrintable(m.captured(1)),
            qPrintable(m.captured(2)), qPrintable(m.captured(3)));
        QVERIFY(std::abs(m.captured(1).toDouble() - seekTo) < 0.02);
        QVERIFY(std::abs(m.captured(2).toDouble() - audioTime) < 0.02);
        QCOMPARE(m.captured(3), QStringLiteral("true"));
    }

private:
    // A script for the page's end: once it has loaded, move the seek bar to `t` as a user would
    // (an input event) and, when `record`, write the player's state to <body>'s attributes a
    // moment later.
    static QByteArray seekScript(double t, bool record)
    {
        QByteArray js = "<script>window.addEventListener('load', function () {"
                        "var seek = document.getElementById('tf-seek'); seek.value = "
            + QByteArray::number(t, 'g', 10) + "; seek.dispatchEvent(new Event('input'));";
        if (record) {
            js += "setTimeout(function () { var a = document.getElementById('tf-audio'); "
                  "var svg = document.querySelector('#tf-stage > svg'); "
                  "document.body.setAttribute('data-svg-time', svg.getCurrentTime()); "
                  "document.body.setAttribute('data-audio-time', a.currentTime); "
                  "document.body.setAttribute('data-audio-paused', a.paused); }, 500);";
        }
        return js + "});</script>";
    }

private Q_SLOTS:
    // What a user hands the export (a sound file's name, a layer's drawing and text) runs
    // nothing in a browser: a name made to close the attribute and add an element, a layer with
    // event handlers, a script and text made to end the player's <script> and CDATA section.
    // Each payload would mark the document's root with data-pwned; Chromium runs both exports
    // and the DOM it ends with has no mark, and still has the texts as text.
    void userTextsExportInert()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString name = QStringLiteral(
            "voice\"'><img src=x onerror=\"document.documentElement.setAttribute('data-pwned',1)\">]]>&amp;.wav");
        const QString wav = dir.filePath(name);
        QVERIFY(test::writeToneWav(wav, 2.0));
        const QString layer = dir.filePath(QStringLiteral("layer.svg"));
        {
            QFile f(layer);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("<svg xmlns=\"http://www.w3.org/2000/svg\" "
                    "onload=\"document.documentElement.setAttribute('data-pwned',2)\">"
                    "<script>document.documentElement.setAttribute('data-pwned',3)</script>"
                    "<text id=\"words\" x=\"10\" y=\"20\">&lt;/script&gt;&lt;script&gt;"
                    "document.documentElement.setAttribute('data-pwned',4)&lt;/script&gt; ]]&gt; &lt;![CDATA[</text>"
                    "</svg>");
        }
        AnimationExportOptions options;
        options.audio = ExportAudio::Reference;
        options.audioPath = wav;
        options.outputDir = dir.path();
        options.layerFiles = {layer};
        QString error;
        const QByteArray svg = exportSmilSvg(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!svg.isEmpty(), qPrintable(error));
        const QByteArray html = exportHtmlPlayer(m_face, Style(), m_timeline, m_shapes, options, &error);
        QVERIFY2(!html.isEmpty(), qPrintable(error));

        const QStringList dumpArgs {QStringLiteral("--virtual-time-budget=3000"), QStringLiteral("--dump-dom")};
        const std::optional<QByteArray> htmlDom
            = runChromium(html, QStringLiteral("inert"), QStringLiteral(".html"), dumpArgs);
        if (!htmlDom && !m_startFailure.isEmpty())
            QSKIP(qPrintable(QStringLiteral("Chromium cannot start: %1").arg(m_startFailure)));
        QVERIFY(htmlDom && htmlDom->contains("tf-stage"));
        const std::optional<QByteArray> svgDom
            = runChromium(svg, QStringLiteral("inert"), QStringLiteral(".svg"), dumpArgs);
        QVERIFY(svgDom && svgDom->contains("tf-play"));
        for (const QByteArray *dom : {&*htmlDom, &*svgDom}) {
            QVERIFY2(!dom->contains("data-pwned=\""), dom->left(400).constData());
            QVERIFY(dom->contains("id=\"layer-1-words\"")); // the layer's text (its ids prefixed), drawn as text
        }
        // The sound is still the file of that name.
        QVERIFY(htmlDom->contains("src=\"" + QUrl::toPercentEncoding(name) + "\""));
    }

private:
    // The page's DOM after it has run for a while (Chromium's --dump-dom).
    QByteArray dumpDom(const QByteArray &html, const QString &name)
    {
        return runChromium(html, name, QStringLiteral(".html"),
            {QStringLiteral("--virtual-time-budget=3000"), QStringLiteral("--dump-dom")})
            .value_or(QByteArray());
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestBrowser)
#include "tst_browser.moc"
