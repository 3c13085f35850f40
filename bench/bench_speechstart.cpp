#include "benchmark.h"

#include "speech/audio.h"
#include "speech/pinyindictionary.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QProcess>
#include <QTemporaryDir>

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>

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

QJsonObject loadAverage()
{
    QJsonObject o;
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) > 0)
        o.insert(QStringLiteral("loadAverage1min"), std::round(load[0] * 100) / 100);
    return o;
}

} // namespace

// The character → pinyin dictionary's start: built from the sources into an empty cache (the
// first run on a machine, or after the sources change), then read from the cache (every later
// start), and the old parse of the sources for comparison.
namespace {

QJsonObject dictionaryStart()
{
    QJsonObject out = loadAverage();
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

// Runs the CLI, returning the wall time in ms and the peak resident memory of the children so
// far in MB (the largest run wins, so the runs go from small to large).
std::pair<double, double> runCli(const QStringList &args, QString *error, const QProcessEnvironment &env)
{
    QProcess p;
    p.setProcessEnvironment(env);
    QElapsedTimer t;
    t.start();
    p.start(QStringLiteral(TOONFACE_CLI_PATH), args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0)
        *error = QString::fromUtf8(p.readAllStandardError()).right(300);
    const double ms = double(t.nsecsElapsed()) / 1e6;
    rusage usage {};
    getrusage(RUSAGE_CHILDREN, &usage);
    return {ms, double(usage.ru_maxrss) / 1024.0};
}

// `toonface-cli lipsync` end to end (process start, dictionary, decoding, alignment, JSON) on
// synthetic Mandarin recordings with a character script, cache warm; and a character script's
// first run with a cold cache.
QJsonObject lipsyncCli()
{
    QJsonObject out = loadAverage();
    QTemporaryDir dir;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("TOONFACE_CACHE_DIR"), dir.filePath(QStringLiteral("cache")));
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
        QFile f(txt);
        if (!writeAudio(wav, audio, &error) || !f.open(QIODevice::WriteOnly)) {
            out.insert(QStringLiteral("error"), error);
            return out;
        }
        f.write(text.toUtf8());
        f.close();
        const QStringList args = {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
            txt, QStringLiteral("-o"), dir.filePath(QStringLiteral("out.json"))};
        QJsonObject o;
        o.insert(QStringLiteral("audioSeconds"), std::round(audio.duration() * 10) / 10);
        if (first) {
            // The first run builds the dictionary cache.
            const auto [ms, mb] = runCli(args, &error, env);
            o.insert(QStringLiteral("coldCacheMs"), std::round(ms));
            first = false;
        }
        std::vector<double> times;
        double peakMb = 0;
        for (int run = 0; run < (seconds > 100 ? 2 : 3); ++run) {
            const auto [ms, mb] = runCli(args, &error, env);
            times.push_back(ms);
            peakMb = mb;
        }
        std::sort(times.begin(), times.end());
        const double ms = times[times.size() / 2];
        o.insert(QStringLiteral("ms"), std::round(ms));
        o.insert(QStringLiteral("timesRealTime"), std::round(audio.duration() * 1000.0 / ms));
        o.insert(QStringLiteral("peakMemoryMbSoFar"), std::round(peakMb));
        if (!error.isEmpty())
            o.insert(QStringLiteral("error"), error);
        runs.append(o);
    }
    out.insert(QStringLiteral("runs"), runs);
    out.insert(QStringLiteral("what"),
        QStringLiteral("toonface-cli lipsync with a character script, wall time (median), dictionary cache warm "
                       "after the first run; peak RSS of the largest child so far"));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("speech.dictionaryStart", dictionaryStart);
TOONFACE_BENCHMARK("speech.lipsyncCli", lipsyncCli);
