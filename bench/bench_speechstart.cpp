#include "benchmark.h"

#include "speech/audio.h"
#include "speech/pinyindictionary.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QSet>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdlib>

using namespace toonface;

namespace {

QString dictionaryRoot()
{
    const QString root = qEnvironmentVariable("TOONFACE_DICT_ROOT");
    return root.isEmpty() ? QStringLiteral("/usr/share") : root;
}

// A recording and its script for toonface-cli lipsync: `audio` as the WAV `wav`, `text` as
// the UTF-8 file `txt`.
bool writeRecording(const QString &wav, const Audio &audio, const QString &txt, const QString &text, QString *error)
{
    if (!writeAudio(wav, audio, error))
        return false;
    QFile f(txt);
    if (!f.open(QIODevice::WriteOnly) || f.write(text.toUtf8()) < 0) {
        *error = txt + QStringLiteral(": ") + f.errorString();
        return false;
    }
    return true;
}

} // namespace

// The character → pinyin dictionary's start: built from the sources into an empty cache (the
// first run on a machine, or after the sources change), then read from the cache (every later
// start), and the old parse of the sources for comparison.
namespace {

QJsonObject dictionaryStart()
{
    QJsonObject out = bench::loadAverage();
    QTemporaryDir cache;
    QString error;
    QElapsedTimer t;
    t.start();
    PinyinDictionary::CacheUse use {};
    if (!PinyinDictionary::loadCached(dictionaryRoot(), cache.path(), &error, &use)) {
        out.insert(QStringLiteral("error"), error);
        return out;
    }
    out.insert(QStringLiteral("buildAndCacheMs"), double(t.nsecsElapsed() / 100000) / 10);
    out.insert(QStringLiteral("cacheBytes"), QFile(cache.filePath(QStringLiteral("pinyin-index.bin"))).size());
    std::shared_ptr<const PinyinDictionary> d;
    out.insert(QStringLiteral("cachedLoadMs"),
        std::round(bench::medianMs(
                       [&] { d = PinyinDictionary::loadCached(dictionaryRoot(), cache.path(), &error, &use); }, 9, 0)
            * 10)
            / 10);
    out.insert(QStringLiteral("cacheReused"), use == PinyinDictionary::CacheUse::Reused);
    const std::u32string sentence
        = QStringLiteral("经广州日报报道后成为了社会热点，你更喜欢老鹰还是鹦鹉").toStdU32String();
    out.insert(QStringLiteral("readSentenceMs"),
        std::round(bench::medianMs([&] { d->readRun(sentence); }, 9, 0) * 1000) / 1000);
    return out;
}

// The stages of one `toonface-cli lipsync` run in ms, from the TOONFACE_TIMINGS marks it
// printed (speech/stagetimes.h): start-up (exec to main), script (the application, the
// dictionary and the script), decode (the recording decoded and its features computed; the
// pace probe renders meanwhile on the other core), reference (the reference rendered at the
// speaker's pace, its features computed on the other core; 0 when the probe was the
// reference), align (warp and segmentation), output (JSON written) and exit.
QJsonObject breakdown(const bench::ChildRun &run)
{
    QHash<QByteArray, double> marks;
    for (const QByteArray &line : run.stderrText.split('\n')) {
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() == 4 && parts[1] == "timing:")
            marks.insert(parts[2], parts[3].toDouble());
    }
    QJsonObject o;
    if (!marks.contains("main") || !marks.contains("written"))
        return o;
    const double decoded = marks.value("decoded");
    const double reference = marks.value("reference", decoded);
    const double end = run.startedMs + run.wallMs;
    const auto put = [&](const char *name, double from, double to) {
        o.insert(QLatin1String(name), std::round((to - from) * 10) / 10);
    };
    put("startUpMs", run.startedMs, marks.value("main"));
    put("scriptMs", marks.value("main"), marks.value("script"));
    put("decodeMs", marks.value("script"), decoded);
    if (marks.contains("probed"))
        put("paceProbeMsOtherCore", marks.value("script"), marks.value("probed"));
    put("referenceMs", decoded, reference);
    put("alignMs", reference, marks.value("aligned"));
    put("outputMs", marks.value("aligned"), marks.value("written"));
    put("exitMs", marks.value("written"), end);
    return o;
}

// `toonface-cli lipsync` end to end (process start, dictionary, decoding, alignment, JSON) on
// synthetic Mandarin recordings with a character script, cache warm; and a character script's
// first run with a cold cache.
QJsonObject lipsyncCli()
{
    QJsonObject out = bench::loadAverage();
    QTemporaryDir dir;
    const QStringList env = {QStringLiteral("TOONFACE_CACHE_DIR=") + dir.filePath(QStringLiteral("cache"))};
    const QStringList timedEnv = env + QStringList {QStringLiteral("TOONFACE_TIMINGS=1")};
    const QString sentence = QStringLiteral("今天天气很好，我们去公园散步吧。我爱北京天安门，天安门上太阳升。"
                                            "这个问题很难回答，请你再说一遍。小明每天早上六点起床，然后去学校上课。");
    TtsOptions voice;
    voice.voice = QStringLiteral("cmn-latn-pinyin+f2");
    voice.rate = 160;
    const double perRound = synthesize(parseScript(sentence, Language::Mandarin).script, voice).audio.duration();
    QJsonArray runs;
    bool first = true;
    for (const double seconds : {5.0, 65.0, 600.0}) {
        QString text;
        for (int k = 0; k < std::max(1, int(std::lround(seconds / perRound))); ++k)
            text += sentence;
        const Script script = parseScript(text, Language::Mandarin).script;
        const Audio audio = resampled(synthesize(script, voice).audio, kSpeechSampleRate);
        const QString wav = dir.filePath(QStringLiteral("speech%1.wav").arg(int(seconds)));
        const QString txt = dir.filePath(QStringLiteral("speech%1.txt").arg(int(seconds)));
        QString error;
        if (!writeRecording(wav, audio, txt, text, &error)) {
            out.insert(QStringLiteral("error"), error);
            return out;
        }
        const QStringList args = {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
            txt, QStringLiteral("-o"), dir.filePath(QStringLiteral("out.json"))};
        QJsonObject o;
        o.insert(QStringLiteral("audioSeconds"), std::round(audio.duration() * 10) / 10);
        if (first) {
            // The first run builds the dictionary cache.
            const bench::ChildRun cold = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH), args, env);
            o.insert(QStringLiteral("coldCacheMs"), std::round(cold.wallMs));
            o.insert(QStringLiteral("coldCachePeakMemoryMb"), std::round(cold.peakMb));
            first = false;
        }
        // Each run measured alone; the run of median wall time is reported.
        std::vector<bench::ChildRun> measured;
        for (int run = 0; run < (seconds > 100 ? 3 : 5); ++run)
            measured.push_back(bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH), args, timedEnv, true));
        std::sort(measured.begin(), measured.end(),
            [](const bench::ChildRun &a, const bench::ChildRun &b) { return a.wallMs < b.wallMs; });
        const bench::ChildRun &m = measured[measured.size() / 2];
        o.insert(QStringLiteral("ms"), std::round(m.wallMs));
        o.insert(QStringLiteral("timesRealTime"), std::round(audio.duration() * 1000.0 / m.wallMs));
        o.insert(QStringLiteral("cpuMs"), std::round(m.cpuMs));
        o.insert(QStringLiteral("peakMemoryMb"), std::round(m.peakMb));
        o.insert(QStringLiteral("stages"), breakdown(m));
        if (!m.ok)
            o.insert(QStringLiteral("error"), QString::fromLocal8Bit(m.stderrText).right(300));
        runs.append(o);
    }
    out.insert(QStringLiteral("runs"), runs);
    out.insert(QStringLiteral("what"),
        QStringLiteral("toonface-cli lipsync with a character script, dictionary cache warm after the first run: "
                       "the run of median wall time (of 5, 3 for 10 min), its CPU time, its own peak RSS and its "
                       "stages (TOONFACE_TIMINGS)"));
    return out;
}

// The launch of toonface-cli: the ms from the process's start to main and to the point where
// the work starts (lipsync: the script read, aligning begins; animate: main, the command
// starts), medians of 9 runs, and the shared libraries the dynamic loader opened
// (LD_DEBUG=files). lipsync of a WAV runs in the light toonface-cli; animate is handed over
// to toonface-cli-full (its libraries include the light program's, loaded first).
QJsonObject cliStart()
{
    QJsonObject out = bench::loadAverage();
    QTemporaryDir dir;
    const QString sentence = QStringLiteral("今天天气很好，我们去公园散步吧。");
    const Script script = parseScript(sentence, Language::Mandarin).script;
    const Audio audio = resampled(synthesize(script).audio, kSpeechSampleRate);
    const QString wav = dir.filePath(QStringLiteral("speech.wav"));
    const QString txt = dir.filePath(QStringLiteral("speech.txt"));
    QString error;
    if (!writeRecording(wav, audio, txt, sentence, &error)) {
        out.insert(QStringLiteral("error"), error);
        return out;
    }
    const QStringList env = {QStringLiteral("TOONFACE_CACHE_DIR=") + dir.filePath(QStringLiteral("cache"))};
    const QString photo = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
    struct Case
    {
        const char *name;
        QStringList args;
        const char *workStarts; // the mark after which the command's own work runs
    };
    const Case cases[] = {
        {"lipsync",
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"), txt,
                QStringLiteral("-o"), dir.filePath(QStringLiteral("out.json"))},
            "script"},
        {"animate",
            {QStringLiteral("animate"), photo, QStringLiteral("--audio"), wav, QStringLiteral("--script"), txt,
                QStringLiteral("-o"), dir.filePath(QStringLiteral("out.svg"))},
            "main"},
    };
    bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH), cases[0].args, env); // builds the dictionary cache
    for (const Case &c : cases) {
        QJsonObject o;
        std::vector<double> toMain, toWork;
        for (int run = 0; run < 9; ++run) {
            const bench::ChildRun r = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH), c.args,
                env + QStringList {QStringLiteral("TOONFACE_TIMINGS=1")}, true);
            QHash<QByteArray, double> marks;
            for (const QByteArray &line : r.stderrText.split('\n')) {
                const QList<QByteArray> parts = line.split(' ');
                if (parts.size() == 4 && parts[1] == "timing:")
                    marks.insert(parts[2], parts[3].toDouble());
            }
            if (!r.ok || !marks.contains("main") || !marks.contains(c.workStarts)) {
                o.insert(QStringLiteral("error"), QString::fromLocal8Bit(r.stderrText).right(300));
                break;
            }
            toMain.push_back(marks.value("main") - r.startedMs);
            toWork.push_back(marks.value(c.workStarts) - r.startedMs);
        }
        const auto median = [](std::vector<double> v) {
            std::sort(v.begin(), v.end());
            return v.empty() ? 0.0 : std::round(v[v.size() / 2] * 10) / 10;
        };
        o.insert(QStringLiteral("startToMainMs"), median(toMain));
        o.insert(QStringLiteral("startToWorkMs"), median(toWork));
        o.insert(QStringLiteral("workStartsAt"), QLatin1String(c.workStarts));
        const bench::ChildRun traced = bench::runMeasured(
            QStringLiteral(TOONFACE_CLI_PATH), c.args, env + QStringList {QStringLiteral("LD_DEBUG=files")}, true);
        QSet<QByteArray> libraries;
        for (const QByteArray &line : traced.stderrText.split('\n')) {
            const qsizetype at = line.indexOf("file=");
            if (at >= 0 && line.indexOf(" [", at) > at && line.contains("needed by"))
                libraries.insert(line.mid(at + 5, line.indexOf(" [", at) - at - 5));
        }
        o.insert(QStringLiteral("librariesLoaded"), libraries.size());
        for (const char *heavy : {"libavcodec", "libopencv_core", "libdlib", "libQt6Gui"}) {
            bool found = false;
            for (const QByteArray &l : libraries)
                found = found || l.startsWith(heavy);
            o.insert(QLatin1String(heavy), found);
        }
        out.insert(QLatin1String(c.name), o);
    }
    out.insert(QStringLiteral("what"),
        QStringLiteral("toonface-cli's launch: ms from process start to main and to the command's work (lipsync: "
                       "the script read, aligning starts), medians of 9 runs, dictionary cache warm; shared "
                       "libraries opened (LD_DEBUG=files) and whether the heavy ones are among them"));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("speech.cliStart", cliStart);
TOONFACE_BENCHMARK("speech.dictionaryStart", dictionaryStart);
TOONFACE_BENCHMARK("speech.lipsyncCli", lipsyncCli);
