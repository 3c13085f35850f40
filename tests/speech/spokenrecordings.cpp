#include "spokenrecordings.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>

namespace toonface::testing {

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

std::pair<double, double> onsetErrors(const AlignResult &r, const std::vector<double> &truth)
{
    std::vector<double> e;
    for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k)
        e.push_back(std::abs(r.syllables[k].start - truth[size_t(k)]) * 1000);
    std::sort(e.begin(), e.end());
    if (e.empty())
        return {1e9, 1e9};
    return {e[e.size() / 2], e[std::min(e.size() - 1, size_t(0.9 * double(e.size() - 1) + 0.5))]};
}

Audio recording(const Script &script, const TtsOptions &voice, double snrDb, quint32 seed, std::vector<double> *truth,
    int *pausedBefore)
{
    const TtsResult r = synthesize(script, voice);
    const Audio spoken = resampled(r.audio, kSpeechSampleRate);
    QRandomGenerator rng(seed);
    const double lead = 0.4 + 0.4 * rng.generateDouble(), trail = 0.3 + 0.4 * rng.generateDouble();
    const int pauseAfter = 2 + int(rng.bounded(std::max(1, int(script.syllables.size()) - 4)));
    if (pausedBefore)
        *pausedBefore = pauseAfter;
    const double pause = 0.3;
    const qsizetype cut = qsizetype(r.units[pauseAfter].start * kSpeechSampleRate);
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    out.samples += spoken.samples.mid(0, cut);
    out.samples += QVector<float>(qsizetype(pause * kSpeechSampleRate), 0.0f);
    out.samples += spoken.samples.mid(cut);
    out.samples += QVector<float>(qsizetype(trail * kSpeechSampleRate), 0.0f);
    double power = 0;
    for (float s : spoken.samples)
        power += double(s) * s;
    power /= double(spoken.samples.size());
    const double sigma = std::sqrt(power / std::pow(10.0, snrDb / 10));
    for (float &s : out.samples) {
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        s += float(sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    truth->clear();
    for (int k = 0; k < r.units.size(); ++k)
        truth->push_back(lead + r.units[k].start + (k >= pauseAfter ? pause : 0.0));
    return out;
}

Audio pieces(const QVector<QPair<Script, int>> &parts, const QString &voice, double lead, double gap, double humDb,
    double snrDb, quint32 seed, std::vector<double> *truth, double leadSnrDb, const QVector<double> &gainsDb)
{
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    truth->clear();
    for (int p = 0; p < parts.size(); ++p) {
        if (p > 0)
            out.samples += QVector<float>(qsizetype(gap * kSpeechSampleRate), 0.0f);
        TtsOptions o;
        o.voice = voice;
        o.rate = parts[p].second;
        const TtsResult r = synthesize(parts[p].first, o);
        const double at = out.duration();
        for (const TtsUnit &u : r.units)
            truth->push_back(at + u.start);
        QVector<float> spoken = resampled(r.audio, kSpeechSampleRate).samples;
        if (p < gainsDb.size())
            for (float &x : spoken)
                x *= float(std::pow(10.0, gainsDb[p] / 20));
        out.samples += spoken;
    }
    out.samples += QVector<float>(qsizetype(0.4 * kSpeechSampleRate), 0.0f);
    double power = 0;
    qsizetype loud = 0;
    for (float s : out.samples)
        if (std::abs(s) > 1e-4f) {
            power += double(s) * s;
            ++loud;
        }
    power /= double(std::max<qsizetype>(loud, 1));
    const double hum = std::sqrt(2 * power / std::pow(10.0, humDb / 10)) / 2;
    const double sigma = std::sqrt(power / std::pow(10.0, snrDb / 10));
    const double leadSigma = std::sqrt(power / std::pow(10.0, leadSnrDb / 10));
    QRandomGenerator rng(seed);
    for (qsizetype i = 0; i < out.samples.size(); ++i) {
        const double t = double(i) / kSpeechSampleRate;
        if (t < lead - 0.05) {
            const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
            out.samples[i] += float(leadSigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
        }
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        out.samples[i] += float(hum
                * (std::sin(2 * M_PI * 50 * t) + 0.7 * std::sin(2 * M_PI * 100 * t + 1)
                    + 0.4 * std::sin(2 * M_PI * 150 * t + 2))
            + sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    return out;
}

double shortestSyllable(const AlignResult &r)
{
    double shortest = 1e9;
    for (const AlignedSyllable &s : r.syllables)
        shortest = std::min(shortest, s.end - s.start);
    return shortest;
}

void checkNotSqueezed(const AlignResult &r)
{
    QVERIFY2(shortestSyllable(r) >= 0.060 - 1e-6,
        qPrintable(QStringLiteral("shortest %1 ms").arg(shortestSyllable(r) * 1000)));
}

void checkWellFormed(const AlignResult &r, int n, double duration)
{
    QCOMPARE(r.syllables.size(), n);
    for (int k = 0; k < n; ++k) {
        const AlignedSyllable &s = r.syllables[k];
        QVERIFY(s.start >= 0 && s.end <= duration + 0.02);
        QVERIFY(s.end > s.start);
        QVERIFY(s.confidence >= 0 && s.confidence <= 1);
        if (k > 0)
            QVERIFY(s.start >= r.syllables[k - 1].end - 1e-9);
    }
}

} // namespace toonface::testing
