// Issue 29: long sounds are checked by their header and a few sampled packets, and copied a
// block at a time (animate --video's clip sound): the time of the check and the peak memory of
// the copy on an hour of sound, against decoding it whole.
#include "benchmark.h"

#include "media/mediareader.h"
#include "media/soundcheck.h"
#include "speech/audio.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <sys/resource.h>

#include <cmath>

using namespace toonface;

namespace {

double cpuMs()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1000.0
        + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1000.0;
}

double peakMb()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

// `minutes` of a voice-like sweep at 22.05 kHz (the voice's rate) as FLAC, written a block at a
// time; empty with *error on failure.
QString longSound(const QString &folder, int minutes, QString *error)
{
    const QString path = QDir(folder).filePath(QStringLiteral("long.flac"));
    constexpr int kRate = 22050;
    std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(path, kRate, error);
    if (!writer)
        return {};
    QVector<float> block(kRate);
    for (qint64 second = 0; second < qint64(minutes) * 60; ++second) {
        for (int i = 0; i < kRate; ++i) {
            const double t = double(i) / kRate;
            // A syllable's worth of tone, then a pause: a quarter of a second each.
            block[i] = (i / (kRate / 4)) % 2 ? 0.0f : float(0.3 * std::sin(2 * M_PI * (180.0 + 60.0 * t) * t));
        }
        if (!writer->write(block.constData(), block.size(), error))
            return {};
    }
    return writer->finish(error) ? path : QString();
}

QJsonObject timed(const std::function<QString()> &fn)
{
    QElapsedTimer clock;
    const double cpu = cpuMs();
    clock.start();
    const QString problem = fn();
    QJsonObject o {{QStringLiteral("wallMs"), std::round(double(clock.nsecsElapsed()) / 1e5) / 10},
        {QStringLiteral("cpuMs"), std::round((cpuMs() - cpu) * 10) / 10}};
    if (!problem.isEmpty())
        o.insert(QStringLiteral("error"), problem);
    return o;
}

// The sound check of an export (checkSound) against the decode the check used to be
// (probeMedia), on `hour`.
void measureCheck(const QString &hour, QJsonObject *out)
{
    double seconds = 0;
    out->insert(QStringLiteral("checkSound"), timed([&] {
        const SoundCheck check = checkSound(hour);
        seconds = check.seconds;
        return check.error;
    }));
    out->insert(QStringLiteral("headerSeconds"), std::round(seconds));
    out->insert(QStringLiteral("probeMedia"), timed([&] {
        QString why;
        return probeMedia(hour, &why) ? QString() : why;
    }));
}

// In a process of its own: the peak memory of copying args[0] to args[1] a block at a time
// (args[2] "copy") or decoded whole and written (args[2] "whole").
QJsonObject childCopy(const QStringList &args)
{
    if (args.size() != 3)
        return {{QStringLiteral("error"), QStringLiteral("copy SOURCE TARGET copy|whole")}};
    const double before = peakMb();
    const double cpu = cpuMs();
    QString error;
    if (args[2] == QLatin1StringView("copy")) {
        const AudioResult r = copyAudio(args[0], args[1]);
        error = r.error;
    } else {
        const AudioResult r = loadAudio(args[0]);
        if (!r.ok() || !writeAudio(args[1], r.audio, &error))
            error = r.ok() ? error : r.error;
    }
    QJsonObject o {{QStringLiteral("peakMb"), std::round(peakMb())},
        {QStringLiteral("grewMb"), std::round(peakMb() - before)},
        {QStringLiteral("cpuMs"), std::round(cpuMs() - cpu)}};
    if (!error.isEmpty())
        o.insert(QStringLiteral("error"), error);
    return o;
}

// An hour of sound: the export's sound check against a whole decode, and animate --video's
// copy of a clip's sound a block at a time against decoding it whole (each copy in a process of
// its own, for its peak memory).
QJsonObject benchHour()
{
    QTemporaryDir dir;
    QString error;
    const QString hour = longSound(dir.path(), 60, &error);
    if (hour.isEmpty())
        return {{QStringLiteral("error"), error}};
    QJsonObject out = bench::loadAverage();
    out.insert(QStringLiteral("soundMb"), std::round(double(QFileInfo(hour).size()) / 1e5) / 10);
    measureCheck(hour, &out);
    for (const QString &how : {QStringLiteral("copy"), QStringLiteral("whole")})
        out.insert(
            how, bench::runChild(QStringLiteral("soundCopy"), {hour, dir.filePath(how + QStringLiteral(".wav")), how}));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("sound.hour", benchHour);
TOONFACE_BENCH_CHILD("soundCopy", childCopy);
