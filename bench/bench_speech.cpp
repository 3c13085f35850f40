#include "benchmark.h"
#include "speechdata.h"

#include "io/textgrid.h"
#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/features.h"
#include "speech/lipsync.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QFont>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QPainter>
#include <QPainterPath>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <fcntl.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

using namespace toonface;

using namespace toonface::speechbench;

TOONFACE_BENCHMARK("speech.alignSynthetic", [] {
    Errors all;
    QJsonArray perVoice;
    quint32 seed = 1;
    for (const Voice &v : kVoices) {
        Errors e;
        double shortest = 1e9;
        QJsonArray slips; // onsets more than 60 ms off: "sentence:syllable pinyin signed ms"
        for (int i = 0; i < sentences().size(); ++i) {
            const Script s = mandarin(sentences()[i]);
            std::vector<double> truth;
            const Audio rec = syntheticRecording(s, v, seed++, &truth);
            const AlignResult r = alignScript(rec, s);
            if (!r.ok())
                continue;
            for (const AlignedSyllable &a : r.syllables)
                shortest = std::min(shortest, (a.end - a.start) * 1000);
            for (int k = 0; k < r.syllables.size(); ++k) {
                e.add(r.syllables[k].start, truth[size_t(k)]);
                all.add(r.syllables[k].start, truth[size_t(k)]);
                const double err = (r.syllables[k].start - truth[size_t(k)]) * 1000;
                if (std::abs(err) > 60)
                    slips.append(
                        QStringLiteral("%1:%2 %3 %4").arg(i).arg(k).arg(s.syllables[k].pinyin).arg(std::round(err)));
            }
        }
        QJsonObject o = e.json();
        o.insert(QStringLiteral("slips"), slips);
        o.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
        o.insert(QStringLiteral("voice"), QString::fromLatin1(v.voice));
        o.insert(QStringLiteral("rate"), v.rate);
        o.insert(QStringLiteral("pitch"), v.pitch);
        perVoice.append(o);
    }
    QJsonObject out = all.json();
    out.insert(QStringLiteral("what"),
        QStringLiteral("espeak-ng voices other than the reference's, 20 dB white noise, "
                       "leading/trailing silence and one unmarked pause"));
    out.insert(QStringLiteral("voices"), perVoice);
    return out;
});

namespace {

// A picture of one alignment: the waveform, the mid-band loudness (black) and voicing (green)
// of the aligner's features, each aligned syllable's onset (blue, labelled with its text and
// pinyin) and end (light blue), and the reference onsets when known (red, dashed, below).
QImage alignmentPlot(const Audio &audio, const LipsyncResult &r, const std::vector<double> &truth, const QString &title)
{
    const SpeechFeatures f = computeSpeechFeatures(audio);
    const int width = 1800, height = 620, left = 50, right = 20;
    // The time shown: the syllables with 0.3 s either side (the whole file when none).
    double t0 = 0, t1 = audio.duration();
    if (!r.syllables.isEmpty()) {
        t0 = std::max(0.0, std::floor((r.syllables.front().start - 0.3) * 10) / 10);
        t1 = std::min(t1, r.syllables.back().end + 0.3);
    }
    const double pxPerS = (width - left - right) / std::max(t1 - t0, 0.01);
    auto x = [&](double t) { return left + (t - t0) * pxPerS; };
    QImage img(width, height, QImage::Format_RGB32);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font(QStringLiteral("WenQuanYi Micro Hei"));
    font.setPixelSize(15);
    p.setFont(font);
    p.drawText(QPointF(left, 20), title);
    // Waveform: min/max per pixel column.
    const int waveTop = 70, waveBottom = 290, waveMid = (waveTop + waveBottom) / 2;
    float peak = 1e-6f;
    for (float s : audio.samples)
        peak = std::max(peak, std::abs(s));
    p.setPen(QColor(90, 90, 90));
    for (int px = left; px < width - right; ++px) {
        const qsizetype a = qsizetype((t0 + (px - left) / pxPerS) * audio.sampleRate);
        const qsizetype b
            = std::min(audio.samples.size(), qsizetype((t0 + (px + 1 - left) / pxPerS) * audio.sampleRate) + 1);
        float lo = 0, hi = 0;
        for (qsizetype i = a; i < b; ++i) {
            lo = std::min(lo, audio.samples[i]);
            hi = std::max(hi, audio.samples[i]);
        }
        const double h = (waveBottom - waveTop) / 2.0 / peak;
        p.drawLine(QPointF(px, waveMid - hi * h), QPointF(px, waveMid - lo * h));
    }
    // Loudness (ln units, the whole range of the file) and voicing.
    const int curveTop = 310, curveBottom = 540;
    float lMin = 1e9f, lMax = -1e9f;
    for (float v : f.loudness) {
        lMin = std::min(lMin, v);
        lMax = std::max(lMax, v);
    }
    QPainterPath loud, voiced;
    for (int t = f.frameAt(t0); t <= f.frameAt(t1); ++t) {
        const double yl
            = curveBottom - (f.loudness[size_t(t)] - lMin) / std::max(lMax - lMin, 1e-3f) * (curveBottom - curveTop);
        const double yv = curveBottom - f.voicing[size_t(t)] * (curveBottom - curveTop);
        if (t == f.frameAt(t0)) {
            loud.moveTo(x(f.time(t)), yl);
            voiced.moveTo(x(f.time(t)), yv);
        } else {
            loud.lineTo(x(f.time(t)), yl);
            voiced.lineTo(x(f.time(t)), yv);
        }
    }
    p.setPen(QPen(QColor(0, 150, 0), 1));
    p.drawPath(voiced);
    p.setPen(QPen(Qt::black, 1.5));
    p.drawPath(loud);
    p.setPen(Qt::black);
    p.drawText(QPointF(4, curveTop + 12), QStringLiteral("loud"));
    p.setPen(QColor(0, 150, 0));
    p.drawText(QPointF(4, curveTop + 30), QStringLiteral("voic"));
    // Time axis.
    p.setPen(Qt::black);
    p.drawLine(QPointF(left, curveBottom + 10), QPointF(width - right, curveBottom + 10));
    for (int k = int(std::ceil(t0 * 100)); k <= int(t1 * 100); ++k) {
        const double t = k / 100.0;
        p.drawLine(QPointF(x(t), curveBottom + 10), QPointF(x(t), curveBottom + (k % 10 ? 13 : 20)));
        if (k % 10 == 0)
            p.drawText(QPointF(x(t) - 10, curveBottom + 36), QString::number(t, 'f', 1));
    }
    // Aligned syllables.
    for (int k = 0; k < r.syllables.size(); ++k) {
        const LipsyncSyllable &s = r.syllables[k];
        p.setPen(QPen(QColor(120, 170, 255), 1, Qt::DotLine));
        p.drawLine(QPointF(x(s.end), waveTop - 10), QPointF(x(s.end), curveBottom));
        p.setPen(QPen(QColor(0, 60, 230), 2));
        p.drawLine(QPointF(x(s.start), waveTop - 22), QPointF(x(s.start), curveBottom));
        p.drawText(QPointF(x(s.start) + 3, waveTop - 28 + (k % 2) * 14),
            s.text + QLatin1Char(' ') + s.pinyin + QString::number(s.tone));
    }
    for (size_t k = 0; k < truth.size(); ++k) {
        if (std::isnan(truth[k]))
            continue;
        p.setPen(QPen(QColor(220, 0, 0), 2, Qt::DashLine));
        p.drawLine(QPointF(x(truth[k]), waveTop), QPointF(x(truth[k]), curveBottom + 10));
        p.drawText(QPointF(x(truth[k]) + 3, height - 12), QStringLiteral("ref"));
    }
    return img;
}

} // namespace

// Plots of every real file's alignment (as toonface-cli lipsync makes it) for checking by eye;
// written to TOONFACE_PLOT_DIR or /tmp/speechplots.
TOONFACE_BENCHMARK("speech.plots", [] {
    QJsonObject out;
    const QString dir = bench::sharedDataDir();
    if (dir.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QStringLiteral("no shared data"));
        return out;
    }
    QString plotDir = qEnvironmentVariable("TOONFACE_PLOT_DIR");
    if (plotDir.isEmpty())
        plotDir = QStringLiteral("/tmp/speechplots");
    QDir().mkpath(plotDir);
    QJsonArray written;
    for (const RealFile &file : realFiles(dir)) {
        const QString path = dir + QStringLiteral("/speech/") + file.name;
        const AudioResult audio = loadAudio(path);
        if (!audio.ok())
            continue;
        const LipsyncOutcome r = lipsyncRealFile(dir, file);
        const QString title = file.name + QStringLiteral(" — script: ") + file.script + QStringLiteral(" — ")
            + (r.ok() ? file.note : r.error);
        const QString png
            = plotDir + QLatin1Char('/') + QFileInfo(file.name).completeBaseName() + QStringLiteral(".png");
        if (alignmentPlot(audio.audio, r.result, file.truth, title).save(png))
            written.append(png);
    }
    // The English GRID clip with its word tier.
    {
        const AudioResult audio = loadAudio(dir + QStringLiteral("/video/id2_vcd_swwp2s.mpg"));
        const GridWordTier tier = gridWordTier(dir);
        const QStringList &words = tier.words;
        const std::vector<double> &truth = tier.onsets;
        if (!words.isEmpty() && audio.ok()) {
            const Script s = parseScript(words.join(QLatin1Char(' '))).script;
            const AlignResult r = alignScript(audio.audio, s);
            const QString png = plotDir + QStringLiteral("/id2_vcd_swwp2s.png");
            if (alignmentPlot(
                    audio.audio, lipsyncResult(s, r, audio.audio.duration()), truth, words.join(QLatin1Char(' ')))
                    .save(png))
                written.append(png);
        }
    }
    // The synthetic set's recordings (truth from espeak-ng's events), for the voices that
    // slip most.
    quint32 seed = 1;
    for (const Voice &v : kVoices) {
        for (int i = 0; i < sentences().size(); ++i, ++seed) {
            const QString voice = QString::fromLatin1(v.voice).section(QLatin1Char('+'), 1);
            if (voice != QLatin1String("m3") && voice != QLatin1String("klatt"))
                continue;
            const Script s = mandarin(sentences()[i]);
            std::vector<double> truth;
            const Audio rec = syntheticRecording(s, v, seed, &truth);
            const AlignResult r = alignScript(rec, s);
            const QString png = plotDir + QStringLiteral("/synthetic_%1_%2.png").arg(voice).arg(i);
            if (alignmentPlot(rec, lipsyncResult(s, r, rec.duration()), truth, sentences()[i]).save(png))
                written.append(png);
        }
    }
    out.insert(QStringLiteral("plots"), written);
    return out;
});

namespace {

// About `seconds` of synthetic Mandarin speech (a voice other than the reference's) with its
// script; the sentences repeat.
std::pair<Audio, Script> longRecording(double seconds)
{
    TtsOptions o;
    o.voice = QStringLiteral("cmn-latn-pinyin+f2");
    o.rate = 160;
    QString round = sentences().join(QString());
    const double perRound = synthesize(mandarin(round), o).audio.duration();
    QString text;
    for (int k = 0; k < std::max(1, int(std::ceil(seconds / perRound))); ++k)
        text += round;
    if (seconds < perRound) // a prefix of the sentences
        text = round.left(int(round.size() * seconds / perRound) + 1);
    const Script script = mandarin(text);
    return {resampled(synthesize(script, o).audio, kSpeechSampleRate), script};
}

const double kSpeedLengths[] = {10.0, 60.0, 600.0}; // seconds

double threadCpuMs()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

QJsonObject alignSpeed()
{
    QJsonObject out;
    for (const double seconds : kSpeedLengths) {
        const auto recording = longRecording(seconds);
        const Audio &audio = recording.first;
        const Script &script = recording.second;
        AlignResult r;
        // Wall time on a shared machine includes other jobs' time slices: the thread's CPU
        // time (the aligner runs on the calling thread) is reported beside it.
        std::vector<double> cpu;
        const double ms = bench::medianMs(
            [&] {
                const double before = threadCpuMs();
                r = alignScript(audio, script);
                cpu.push_back(threadCpuMs() - before);
            },
            seconds > 100      ? 2
                : seconds > 30 ? 5
                               : 9,
            0);
        std::sort(cpu.begin(), cpu.end());
        const double cpuMs = cpu[cpu.size() / 2];
        QJsonObject o;
        o.insert(QStringLiteral("audioSeconds"), std::round(audio.duration() * 10) / 10);
        o.insert(QStringLiteral("syllables"), int(script.syllables.size()));
        o.insert(QStringLiteral("alignMs"), std::round(ms));
        o.insert(QStringLiteral("timesRealTime"), std::round(audio.duration() * 1000.0 / ms));
        o.insert(QStringLiteral("cpuMs"), std::round(cpuMs));
        o.insert(QStringLiteral("timesRealTimeCpu"), std::round(audio.duration() * 1000.0 / cpuMs));
        // Other jobs on the machine also slow the thread down (caches, shared cores): the
        // fastest run is the least disturbed.
        o.insert(QStringLiteral("cpuMsFastest"), std::round(cpu.front()));
        o.insert(QStringLiteral("ok"), r.ok());
        out.insert(QStringLiteral("%1s").arg(int(seconds)), o);
    }
    out.insert(QStringLiteral("what"),
        QStringLiteral("alignScript on one core, reference rendering included; wall and thread CPU time (median)"));
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) > 0)
        out.insert(QStringLiteral("loadAverage1min"), std::round(load[0] * 100) / 100);
    return out;
}

} // namespace

TOONFACE_BENCHMARK("speech.alignSpeed", alignSpeed);

using bench::ChildRun;
using bench::runMeasured;

QJsonObject toonface::speechbench::lipsyncLongReal(const std::vector<int> &roundCounts)
{
    QJsonObject out;
    const QString dir = bench::sharedDataDir();
    if (dir.isEmpty()) {
        out.insert(QStringLiteral("skipped"), QStringLiteral("no shared data"));
        return out;
    }
    const QStringList names = {QStringLiteral("BAC009S0002W0122.wav"), QStringLiteral("BAC009S0002W0123.wav"),
        QStringLiteral("p2fa_test1.wav"), QStringLiteral("SSB00050015_16k.wav")};
    const QVector<RealFile> files = realFiles(dir);
    QVector<float> round;
    QString roundScript;
    std::vector<double> roundTruth; // per syllable of the round: seconds, or NaN
    for (const QString &name : names) {
        const auto file = std::find_if(files.begin(), files.end(), [&](const RealFile &f) { return f.name == name; });
        const AudioResult a = loadAudio(dir + QStringLiteral("/speech/") + name);
        if (file == files.end() || !a.ok()) {
            out.insert(QStringLiteral("skipped"), QStringLiteral("%1 missing").arg(name));
            return out;
        }
        const double offset = double(round.size()) / kSpeechSampleRate;
        const int syllables = int(parseScript(file->script).script.syllables.size());
        for (int k = 0; k < syllables; ++k)
            roundTruth.push_back(size_t(k) < file->truth.size() ? file->truth[size_t(k)] + offset : std::nan(""));
        roundScript += file->script + QLatin1Char(' ');
        round += a.audio.samples;
    }
    QTemporaryDir tmp;
    QJsonObject runs;
    for (const int rounds : roundCounts) {
        Audio audio;
        QString script;
        std::vector<double> truth;
        for (int r = 0; r < rounds; ++r) {
            const double offset = audio.duration();
            audio.samples += round;
            script += roundScript;
            for (const double t : roundTruth)
                truth.push_back(t + offset);
        }
        const QString wav = tmp.filePath(QStringLiteral("long%1.wav").arg(rounds));
        const QString txt = tmp.filePath(QStringLiteral("long%1.txt").arg(rounds));
        const QString json = tmp.filePath(QStringLiteral("long%1.json").arg(rounds));
        QFile f(txt);
        QString error;
        if (!writeAudio(wav, audio, &error) || !f.open(QIODevice::WriteOnly)) {
            out.insert(QStringLiteral("error"), error);
            return out;
        }
        f.write(script.toUtf8());
        f.close();
        const QStringList args = {QStringLiteral("lipsync"), QStringLiteral("--audio"), wav, QStringLiteral("--script"),
            txt, QStringLiteral("-o"), json};
        std::vector<ChildRun> measured;
        for (int k = 0; k < (rounds > 10 ? 2 : 3); ++k)
            measured.push_back(runMeasured(QStringLiteral(TOONFACE_CLI_PATH), args));
        std::sort(
            measured.begin(), measured.end(), [](const ChildRun &a, const ChildRun &b) { return a.cpuMs < b.cpuMs; });
        const ChildRun &m = measured[measured.size() / 2];
        QJsonObject o;
        o.insert(QStringLiteral("audioSeconds"), std::round(audio.duration() * 10) / 10);
        o.insert(QStringLiteral("wallMs"), std::round(m.wallMs));
        o.insert(QStringLiteral("cpuMs"), std::round(m.cpuMs));
        o.insert(QStringLiteral("timesRealTimeWall"), std::round(audio.duration() * 1000.0 / m.wallMs));
        o.insert(QStringLiteral("timesRealTimeCpu"), std::round(audio.duration() * 1000.0 / m.cpuMs));
        o.insert(QStringLiteral("peakMemoryMb"), std::round(m.peakMb));
        o.insert(QStringLiteral("ok"), m.ok);
        // The alignment of the long recording against the files' reference onsets.
        QFile result(json);
        if (m.ok && result.open(QIODevice::ReadOnly)) {
            const QJsonArray syllables
                = QJsonDocument::fromJson(result.readAll())[QStringLiteral("syllables")].toArray();
            Errors e;
            double shortest = 1e9;
            // Rounds in which some scored onset is more than 0.3 s off: a sentence placed
            // across a pause between the files.
            std::vector<bool> badRound(size_t(rounds), false);
            for (int k = 0; k < syllables.size() && size_t(k) < truth.size(); ++k) {
                const QJsonObject s = syllables[k].toObject();
                const double start = s[QStringLiteral("start")].toDouble();
                shortest = std::min(shortest, (s[QStringLiteral("end")].toDouble() - start) * 1000.0);
                if (!std::isnan(truth[size_t(k)])) {
                    e.add(start, truth[size_t(k)]);
                    if (std::abs(start - truth[size_t(k)]) > 0.3)
                        badRound[size_t(k) / roundTruth.size()] = true;
                }
            }
            QJsonObject accuracy = e.json();
            accuracy.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
            accuracy.insert(
                QStringLiteral("roundsOffBy300Ms"), int(std::count(badRound.begin(), badRound.end(), true)));
            o.insert(QStringLiteral("onsetErrors"), accuracy);
        }
        runs.insert(QStringLiteral("%1s").arg(int(std::lround(audio.duration()))), o);
    }
    out.insert(QStringLiteral("runs"), runs);
    // The process start alone (dynamic linking of the libraries, Qt's set-up): what every run
    // above spends before its first sample.
    {
        std::vector<ChildRun> start;
        for (int k = 0; k < 5; ++k)
            start.push_back(runMeasured(QStringLiteral(TOONFACE_CLI_PATH), {QStringLiteral("--help")}));
        std::sort(start.begin(), start.end(), [](const ChildRun &a, const ChildRun &b) { return a.cpuMs < b.cpuMs; });
        QJsonObject o;
        o.insert(QStringLiteral("cpuMs"), std::round(start[2].cpuMs));
        o.insert(QStringLiteral("wallMs"), std::round(start[2].wallMs));
        out.insert(QStringLiteral("processStart"), o);
    }
    out.insert(QStringLiteral("what"),
        QStringLiteral("toonface-cli lipsync on real recordings joined to ~1 and ~10 min (median by CPU time of "
                       "3 / 2 runs; wall, CPU and peak RSS of that run); onset errors against the P2FA word and "
                       "SSB character references"));
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) > 0)
        out.insert(QStringLiteral("loadAverage1min"), std::round(load[0] * 100) / 100);
    return out;
}

TOONFACE_BENCHMARK("speech.lipsyncLongReal", [] { return lipsyncLongReal({3, 30}); });
