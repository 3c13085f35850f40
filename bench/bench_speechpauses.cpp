#include "benchmark.h"
#include "speechdata.h"

#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/lipsync.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QJsonArray>
#include <QRandomGenerator>

#include <algorithm>
#include <cmath>

using namespace toonface;
using namespace toonface::speechbench;

namespace {

// A held-out voice's reading of `script` with pauses the script does not mark inserted before
// the syllables `before` (of `seconds` each), leading and trailing silence and white noise at
// 20 dB SNR; `truth` gets the syllable onsets. `phrased`: each stretch between pauses is
// spoken as a phrase of its own (espeak-ng lengthens and lowers a phrase's end, as speakers do
// before a pause); `breath`: each pause holds a loud breath (noise 10 dB under the speech's mean
// power, 0.15-0.3 s).
Audio pausedRecording(const Script &script, const Voice &v, const std::vector<int> &before,
    const std::vector<double> &seconds, bool phrased, bool breath, quint32 seed, std::vector<double> *truth)
{
    TtsOptions o;
    o.voice = QString::fromLatin1(v.voice);
    o.rate = v.rate;
    o.pitch = v.pitch;
    // The stretches between pauses: [cuts[i], cuts[i + 1]) syllables.
    std::vector<int> cuts {0};
    std::vector<double> pauseAfter;
    for (int k = 1; k < script.syllables.size(); ++k) {
        const auto at = std::find(before.begin(), before.end(), k);
        if (at != before.end()) {
            cuts.push_back(k);
            pauseAfter.push_back(seconds[size_t(at - before.begin())]);
        }
    }
    cuts.push_back(int(script.syllables.size()));
    QRandomGenerator rng(seed);
    struct Piece
    {
        Audio audio;
        std::vector<double> starts;
    };
    std::vector<Piece> pieces;
    auto render = [&](int from, int to) {
        Script part = script;
        part.syllables = script.syllables.mid(from, to - from);
        part.syllables.last().phraseBreakAfter = true;
        const TtsResult r = synthesize(part, o);
        Piece piece {resampled(r.audio, kSpeechSampleRate), {}};
        for (const TtsUnit &u : r.units)
            piece.starts.push_back(u.start);
        return piece;
    };
    if (phrased) {
        for (size_t c = 0; c + 1 < cuts.size(); ++c)
            pieces.push_back(render(cuts[c], cuts[c + 1]));
    } else {
        // One reading cut at the syllables' onsets.
        const Piece whole = render(0, int(script.syllables.size()));
        for (size_t c = 0; c + 1 < cuts.size(); ++c) {
            const qsizetype from = cuts[c] == 0 ? 0 : qsizetype(whole.starts[size_t(cuts[c])] * kSpeechSampleRate);
            const qsizetype to = cuts[c + 1] >= int(whole.starts.size())
                ? whole.audio.samples.size()
                : qsizetype(whole.starts[size_t(cuts[c + 1])] * kSpeechSampleRate);
            Piece piece {{}, {}};
            piece.audio.samples = whole.audio.samples.mid(from, to - from);
            for (int k = cuts[c]; k < cuts[c + 1]; ++k)
                piece.starts.push_back(whole.starts[size_t(k)] - double(from) / kSpeechSampleRate);
            pieces.push_back(piece);
        }
    }
    double power = 0;
    qsizetype count = 0;
    for (const Piece &piece : pieces) {
        for (float s : piece.audio.samples)
            power += double(s) * s;
        count += piece.audio.samples.size();
    }
    power /= std::max<qsizetype>(count, 1);
    const double lead = 0.3 + 0.4 * rng.generateDouble();
    Audio out;
    out.samples.fill(0.0f, qsizetype(lead * kSpeechSampleRate));
    truth->clear();
    for (size_t c = 0; c < pieces.size(); ++c) {
        const double at = double(out.samples.size()) / kSpeechSampleRate;
        for (const double t : pieces[c].starts)
            truth->push_back(at + t);
        out.samples += pieces[c].audio.samples;
        if (c + 1 < pieces.size()) {
            QVector<float> pause(qsizetype(pauseAfter[c] * kSpeechSampleRate), 0.0f);
            if (breath) {
                const double length = std::min(0.15 + 0.15 * rng.generateDouble(), 0.6 * pauseAfter[c]);
                const qsizetype n = qsizetype(length * kSpeechSampleRate);
                const qsizetype from = (pause.size() - n) / 2;
                const double amplitude = std::sqrt(power / 10.0) * std::sqrt(3.0);
                for (qsizetype i = 0; i < n; ++i) {
                    const double envelope = std::sin(M_PI * double(i) / double(n));
                    pause[from + i] = float(amplitude * envelope * (2 * rng.generateDouble() - 1));
                }
            }
            out.samples += pause;
        }
    }
    out.samples += QVector<float>(qsizetype(0.4 * kSpeechSampleRate), 0.0f);
    const double sigma = std::sqrt(power / 100.0);
    for (float &s : out.samples) {
        const double u1 = std::max(rng.generateDouble(), 1e-12), u2 = rng.generateDouble();
        s += float(sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
    }
    return out;
}

struct RunCount
{
    int runs = 0; // runs of >= 3 syllables > 50 ms off the same way
    int runSyllables = 0;
    QJsonArray examples;
};

// Runs of three or more consecutive onsets more than 50 ms off in the same direction.
void countRuns(const std::vector<double> &signedMs, const QString &what, const QJsonArray &pauses, RunCount *c)
{
    size_t k = 0;
    while (k < signedMs.size()) {
        const double sign = signedMs[k] > 50 ? 1 : signedMs[k] < -50 ? -1 : 0;
        size_t e = k + 1;
        while (sign != 0 && e < signedMs.size() && signedMs[e] * sign > 50)
            ++e;
        if (sign != 0 && e - k >= 3) {
            ++c->runs;
            c->runSyllables += int(e - k);
            if (c->examples.size() < 12) {
                QJsonArray errs;
                for (size_t q = k; q < e; ++q)
                    errs.append(std::round(signedMs[q]));
                c->examples.append(QJsonObject {{QStringLiteral("where"), what}, {QStringLiteral("from"), int(k)},
                    {QStringLiteral("errorsMs"), errs}, {QStringLiteral("pausesBefore"), pauses}});
            }
        }
        k = sign != 0 ? e : k + 1;
    }
}

// Pauses the script does not mark, 0.35-1.2 s, inserted at random syllable boundaries of the
// held-out voices' readings (one long reading of all the sentences per voice, so that the
// speaker adaptation runs, and each sentence alone): the onsets after each pause, runs of
// syllables that slide together, and the shortest syllable.
QJsonObject pauseRunsOf(bool phrased, bool breath)
{
    Errors all, afterPause;
    RunCount runs;
    double shortest = 1e9;
    QString shortestWhere;
    int under60 = 0, syllables = 0;
    QJsonArray perVoice;
    quint32 seed = 5000;
    const QStringList texts = heldOutSentences();
    for (const Voice &v : kHeldOutVoices) {
        Errors voiceErrors;
        std::vector<QString> items;
        items.push_back(texts.join(QString()));
        for (const QString &t : texts)
            items.push_back(t);
        for (size_t item = 0; item < items.size(); ++item) {
            const Script s = mandarin(items[item]);
            const int n = int(s.syllables.size());
            if (n < 4)
                continue;
            QRandomGenerator rng(seed++);
            const int pauses = item == 0 ? 6 : 1;
            std::vector<int> before;
            std::vector<double> seconds;
            for (int p = 0; p < pauses; ++p) {
                const int at = 2 + int(rng.bounded(std::max(1, n - 4)));
                if (std::find(before.begin(), before.end(), at) != before.end())
                    continue;
                before.push_back(at);
                seconds.push_back(0.35 + 0.85 * rng.generateDouble());
            }
            std::vector<double> truth;
            const Audio rec = pausedRecording(s, v, before, seconds, phrased, breath, seed * 7, &truth);
            const LipsyncResult r = lipsyncResult(s, alignScript(rec, s), rec.duration());
            std::vector<double> signedMs;
            for (int k = 0; k < r.syllables.size() && size_t(k) < truth.size(); ++k) {
                const LipsyncSyllable &syl = r.syllables[k];
                all.add(syl.start, truth[size_t(k)], syl.confidence);
                voiceErrors.add(syl.start, truth[size_t(k)], syl.confidence);
                signedMs.push_back((syl.start - truth[size_t(k)]) * 1000);
                // In whole milliseconds, as toonface-cli writes the times.
                const double length = std::round(syl.end * 1000) - std::round(syl.start * 1000);
                if (length < shortest) {
                    shortest = length;
                    const double next = size_t(k) + 1 < truth.size() ? truth[size_t(k) + 1] : syl.end;
                    shortestWhere = QStringLiteral("%1 rate %2, %3 syllable %4 (%5): %6 ms, spoken %7 ms")
                                        .arg(QString::fromLatin1(v.voice))
                                        .arg(v.rate)
                                        .arg(items[item].left(8))
                                        .arg(k)
                                        .arg(s.syllables[k].text)
                                        .arg(length)
                                        .arg(std::round((next - truth[size_t(k)]) * 1000));
                }
                under60 += length < 60 ? 1 : 0;
                ++syllables;
                for (const int b : before)
                    if (k >= b && k < b + 4)
                        afterPause.add(syl.start, truth[size_t(k)], syl.confidence);
            }
            QJsonArray pauseList;
            for (size_t q = 0; q < before.size(); ++q)
                pauseList.append(QStringLiteral("%1: %2 s").arg(before[q]).arg(seconds[q], 0, 'f', 2));
            countRuns(signedMs,
                QStringLiteral("%1 rate %2: %3")
                    .arg(QString::fromLatin1(v.voice))
                    .arg(v.rate)
                    .arg(items[item].left(12)),
                pauseList, &runs);
        }
        QJsonObject o = voiceErrors.json();
        o.insert(QStringLiteral("voice"), QString::fromLatin1(v.voice));
        o.insert(QStringLiteral("rate"), v.rate);
        perVoice.append(o);
    }
    QJsonObject out;
    out.insert(QStringLiteral("all"), all.json());
    out.insert(QStringLiteral("fourAfterEachPause"), afterPause.json());
    out.insert(QStringLiteral("runsOf3Off50MsSameWay"), runs.runs);
    out.insert(QStringLiteral("syllablesInRuns"), runs.runSyllables);
    out.insert(QStringLiteral("runExamples"), runs.examples);
    out.insert(QStringLiteral("shortestSyllableMs"), std::round(shortest));
    out.insert(QStringLiteral("syllablesUnder60Ms"), under60);
    out.insert(QStringLiteral("shortestSyllable"), shortestWhere);
    out.insert(QStringLiteral("syllables"), syllables);
    out.insert(QStringLiteral("voices"), perVoice);
    out.insert(QStringLiteral("what"),
        QStringLiteral("held-out espeak-ng voices and tempi, pauses of 0.35-1.2 s the script does not mark inserted at "
                       "random syllable boundaries (6 in a reading of all sentences, 1 per sentence alone), 20 dB "
                       "noise: onset errors, the 4 onsets after each pause, runs of >= 3 onsets > 50 ms off the "
                       "same way, shortest syllable"));
    return out;
}

QJsonObject pauseRuns()
{
    return QJsonObject {{QStringLiteral("cut"), pauseRunsOf(false, false)},
        {QStringLiteral("phrased"), pauseRunsOf(true, false)},
        {QStringLiteral("phrasedWithBreath"), pauseRunsOf(true, true)}};
}

} // namespace

TOONFACE_BENCHMARK("speech.pauseRuns", pauseRuns);
