// speech.alignConfidence: does a syllable's confidence predict its error? Every syllable of
// the espeak-ng voices (kVoices, kHeldOutVoices; each sentence alone and all of them in one
// recording, which the aligner adapts to) and of the shared real recordings with reference
// onsets, with the signs the aligner doubted it by (alignconfidence.h) and its onset error.
// The logistic model of "more than 80 ms off" is refitted leaving one speaker out at a time
// and judged on that speaker; the model fitted on all of them is printed (its weights are the
// ones alignconfidence.cpp ships). The worst syllables are listed with their neighbours.

#include "benchmark.h"
#include "crossvalidation.h"
#include "speechdata.h"

#include "io/textgrid.h"
#include "speech/alignconfidence.h"
#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"

#include <QFile>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace toonface;
using namespace toonface::speechbench;

namespace {

constexpr double kOffMs = 80;
// The doubtful share the flag is allowed on the speakers it is fitted on.
constexpr double kMostFlagged = 0.08;

struct Row
{
    int speaker;
    QString source; // voice or file
    int syllable;
    QString text; // the syllable and its neighbours: "天[气]很"
    double signedMs;
    Doubts doubts; // relative to the recording's (relativeDoubts)
    double confidence; // as shipped
};

struct Collected
{
    std::vector<Row> rows;
    QStringList speakers;
};

QString around(const Script &s, int k)
{
    QString out;
    for (int j = std::max(0, k - 2); j <= std::min(int(s.syllables.size()) - 1, k + 2); ++j)
        out += j == k ? QLatin1Char('[') + s.syllables[j].text + QLatin1Char(']') : s.syllables[j].text;
    return out;
}

void addAlignment(Collected *c, int speaker, const QString &source, const Script &s, const AlignResult &r,
    const std::vector<double> &truth)
{
    std::vector<Doubts> raw;
    for (const AlignedSyllable &a : r.syllables)
        raw.push_back(a.doubts);
    const std::vector<Doubts> relative = relativeDoubts(raw);
    for (int k = 0; r.ok() && k < r.syllables.size() && size_t(k) < truth.size(); ++k) {
        if (std::isnan(truth[size_t(k)]) || r.unspoken.contains(k))
            continue;
        const AlignedSyllable &a = r.syllables[k];
        c->rows.push_back(
            {speaker, source, k, around(s, k), (a.start - truth[size_t(k)]) * 1000, relative[size_t(k)], a.confidence});
    }
}

Collected collect()
{
    Collected c;
    const QStringList texts = heldOutSentences();
    quint32 seed = 5000;
    std::vector<Voice> voices(std::begin(kVoices), std::end(kVoices));
    voices.insert(voices.end(), std::begin(kHeldOutVoices), std::end(kHeldOutVoices));
    for (const Voice &v : voices) {
        const int speaker = int(c.speakers.size());
        c.speakers.append(
            QStringLiteral("%1 rate %2 pitch %3").arg(QString::fromLatin1(v.voice)).arg(v.rate).arg(v.pitch));
        for (const QString &text : texts) {
            const Script s = mandarin(text);
            std::vector<double> truth;
            const Audio rec = syntheticRecording(s, v, seed++, &truth);
            addAlignment(&c, speaker, c.speakers.back(), s, alignScript(rec, s), truth);
        }
        // All the sentences in one recording: long enough to adapt to.
        const Script s = mandarin(texts.join(QString()));
        std::vector<double> truth;
        const Audio rec = syntheticRecording(s, v, seed++, &truth);
        addAlignment(
            &c, speaker, c.speakers.back() + QStringLiteral(" (all sentences)"), s, alignScript(rec, s), truth);
    }
    const QString dir = bench::sharedDataDir();
    if (dir.isEmpty())
        return c;
    for (const RealFile &file : realFiles(dir)) {
        if (file.truth.empty())
            continue;
        const AudioResult a = loadAudio(dir + QStringLiteral("/speech/") + file.name);
        const ScriptParse p = parseScript(file.script);
        if (!a.ok() || !p.ok())
            continue;
        const int speaker = int(c.speakers.size());
        c.speakers.append(file.name);
        addAlignment(&c, speaker, file.name, p.script, alignScript(a.audio, p.script), file.truth);
    }
    return c;
}

using Weights = std::array<double, kDoubtCount + 1>;

// Logistic regression with a little ridge (signs standardised on `rows`), by Newton's method,
// over the signs `active` lets in; returned in the signs' own units. The rare positives are
// weighed up to half the mass.
Weights fitLogisticOn(
    const std::vector<Row> &all, const std::vector<size_t> &rows, const std::array<bool, kDoubtCount> &active)
{
    constexpr int m = kDoubtCount + 1;
    std::array<double, kDoubtCount> mean {}, sd {};
    for (size_t r : rows)
        for (int i = 0; i < kDoubtCount; ++i)
            mean[size_t(i)] += all[r].doubts[size_t(i)] / double(rows.size());
    for (size_t r : rows)
        for (int i = 0; i < kDoubtCount; ++i)
            sd[size_t(i)] += std::pow(all[r].doubts[size_t(i)] - mean[size_t(i)], 2) / double(rows.size());
    for (double &v : sd)
        v = std::max(std::sqrt(v), 1e-6);
    double positives = 0;
    for (size_t r : rows)
        positives += std::abs(all[r].signedMs) > kOffMs ? 1 : 0;
    const double wPos = positives > 0 ? 0.5 * double(rows.size()) / positives : 1.0;
    const double wNeg
        = positives < double(rows.size()) ? 0.5 * double(rows.size()) / (double(rows.size()) - positives) : 1.0;
    std::array<double, m> beta {};
    constexpr double kRidge = 1.0;
    for (int iter = 0; iter < 30; ++iter) {
        std::array<std::array<double, m>, m> h {};
        std::array<double, m> g {};
        for (size_t r : rows) {
            std::array<double, m> x {};
            for (int i = 0; i < kDoubtCount; ++i)
                x[size_t(i)] = active[size_t(i)] ? (all[r].doubts[size_t(i)] - mean[size_t(i)]) / sd[size_t(i)] : 0.0;
            x[m - 1] = 1;
            double z = 0;
            for (int i = 0; i < m; ++i)
                z += beta[size_t(i)] * x[size_t(i)];
            const double p = 1 / (1 + std::exp(-z));
            const bool y = std::abs(all[r].signedMs) > kOffMs;
            const double w = y ? wPos : wNeg;
            for (int i = 0; i < m; ++i) {
                g[size_t(i)] += w * (p - (y ? 1 : 0)) * x[size_t(i)];
                for (int j = 0; j < m; ++j)
                    h[size_t(i)][size_t(j)] += w * p * (1 - p) * x[size_t(i)] * x[size_t(j)];
            }
        }
        for (int i = 0; i + 1 < m; ++i) {
            g[size_t(i)] += kRidge * beta[size_t(i)];
            h[size_t(i)][size_t(i)] += kRidge;
        }
        h[m - 1][m - 1] += 1e-6;
        // Solve h d = g (Gauss-Jordan with partial pivoting).
        std::array<double, m> d = g;
        for (int col = 0; col < m; ++col) {
            int piv = col;
            for (int r = col + 1; r < m; ++r)
                if (std::abs(h[size_t(r)][size_t(col)]) > std::abs(h[size_t(piv)][size_t(col)]))
                    piv = r;
            std::swap(h[size_t(col)], h[size_t(piv)]);
            std::swap(d[size_t(col)], d[size_t(piv)]);
            for (int r = 0; r < m; ++r) {
                if (r == col || h[size_t(col)][size_t(col)] == 0)
                    continue;
                const double f = h[size_t(r)][size_t(col)] / h[size_t(col)][size_t(col)];
                for (int j = 0; j < m; ++j)
                    h[size_t(r)][size_t(j)] -= f * h[size_t(col)][size_t(j)];
                d[size_t(r)] -= f * d[size_t(col)];
            }
        }
        double step = 0;
        for (int i = 0; i < m; ++i) {
            const double delta = h[size_t(i)][size_t(i)] != 0 ? d[size_t(i)] / h[size_t(i)][size_t(i)] : 0.0;
            beta[size_t(i)] -= delta;
            step = std::max(step, std::abs(delta));
        }
        if (step < 1e-8)
            break;
    }
    // Back to the signs' units; the sign flipped so that z > 0 means doubt (alignconfidence.cpp
    // takes confidence = 1 / (1 + e^z)).
    Weights w {};
    w[kDoubtCount] = beta[m - 1];
    for (int i = 0; i < kDoubtCount; ++i) {
        w[size_t(i)] = beta[size_t(i)] / sd[size_t(i)];
        w[kDoubtCount] -= beta[size_t(i)] * mean[size_t(i)] / sd[size_t(i)];
    }
    return w;
}

// The same with every sign a doubt, never a reassurance: a sign whose weight comes out negative
// (it helps only alongside another, in these speakers) is left out and the rest refitted.
Weights fitLogistic(const std::vector<Row> &all, const std::vector<size_t> &rows)
{
    std::array<bool, kDoubtCount> active;
    active.fill(true);
    while (true) {
        const Weights w = fitLogisticOn(all, rows, active);
        int worst = -1;
        for (int i = 0; i < kDoubtCount; ++i)
            if (active[size_t(i)] && w[size_t(i)] < 0 && (worst < 0 || w[size_t(i)] < w[size_t(worst)]))
                worst = i;
        if (worst < 0)
            return w;
        active[size_t(worst)] = false;
    }
}

double doubtOf(const Row &row, const Weights &w)
{
    double z = w[kDoubtCount];
    for (int i = 0; i < kDoubtCount; ++i)
        z += w[size_t(i)] * row.doubts[size_t(i)];
    return z;
}

// The weights with the intercept moved so that z > 0 flags: the cut on `rows` that catches the
// most syllables > 80 ms off while flagging at most kMostFlagged of all.
Weights withCut(const std::vector<Row> &all, const std::vector<size_t> &rows, Weights w)
{
    std::vector<double> z;
    for (size_t r : rows)
        z.push_back(doubtOf(all[r], w));
    std::sort(z.begin(), z.end(), std::greater<>());
    const size_t most = size_t(std::floor(kMostFlagged * double(rows.size())));
    const double cut = most < z.size() ? (most > 0 ? 0.5 * (z[most - 1] + z[most]) : z[0] + 1e-6) : z.back() - 1e-6;
    w[kDoubtCount] -= cut;
    return w;
}

struct Tally
{
    int off = 0, offFlagged = 0, flagged = 0, all = 0;
    void add(bool isOff, bool isFlagged)
    {
        ++all;
        flagged += isFlagged;
        off += isOff;
        offFlagged += isOff && isFlagged;
    }
    QJsonObject json() const
    {
        QJsonObject o;
        o.insert(QStringLiteral("syllables"), all);
        o.insert(QStringLiteral("offBy80Ms"), off);
        o.insert(QStringLiteral("offBy80MsFlagged"), offFlagged);
        o.insert(QStringLiteral("offBy80MsFlaggedShare"), off ? std::round(1000.0 * offFlagged / off) / 1000 : 1.0);
        o.insert(QStringLiteral("flaggedShare"), all ? std::round(1000.0 * flagged / all) / 1000 : 0.0);
        return o;
    }
};

QJsonObject alignConfidence()
{
    const Collected c = collect();
    const std::vector<Row> &rows = c.rows;
    QJsonObject out;
    // Leave one speaker out: fit and cut on the others, judge on it.
    Tally heldOut;
    QJsonArray perSpeaker;
    std::vector<double> heldOutDoubt(rows.size(), 0.0);
    std::vector<bool> offAll(rows.size());
    for (size_t r = 0; r < rows.size(); ++r)
        offAll[r] = std::abs(rows[r].signedMs) > kOffMs;
    for (int sp = 0; sp < c.speakers.size(); ++sp) {
        std::vector<size_t> train, test;
        for (size_t r = 0; r < rows.size(); ++r)
            (rows[r].speaker == sp ? test : train).push_back(r);
        if (test.empty())
            continue;
        const Weights w = withCut(rows, train, fitLogistic(rows, train));
        Tally t;
        for (size_t r : test) {
            heldOutDoubt[r] = doubtOf(rows[r], w);
            t.add(offAll[r], heldOutDoubt[r] > 0);
            heldOut.add(offAll[r], heldOutDoubt[r] > 0);
        }
        QJsonObject o = t.json();
        o.insert(QStringLiteral("speaker"), c.speakers[sp]);
        perSpeaker.append(o);
    }
    std::vector<size_t> everyRow(rows.size());
    std::iota(everyRow.begin(), everyRow.end(), size_t(0));
    QJsonObject loso = heldOut.json();
    loso.insert(QStringLiteral("rocArea"), std::round(1000 * bench::rocArea(heldOutDoubt, offAll, everyRow)) / 1000);
    loso.insert(QStringLiteral("perSpeaker"), perSpeaker);
    out.insert(QStringLiteral("leaveOneSpeakerOut"), loso);
    // As shipped (alignconfidence.cpp's weights; fitted on all of these, so in-sample).
    Tally shipped;
    std::vector<double> shippedDoubt;
    for (const Row &r : rows) {
        shipped.add(std::abs(r.signedMs) > kOffMs, r.confidence < kDoubtfulConfidence);
        shippedDoubt.push_back(1 - r.confidence);
    }
    QJsonObject s = shipped.json();
    s.insert(QStringLiteral("rocArea"), std::round(1000 * bench::rocArea(shippedDoubt, offAll, everyRow)) / 1000);
    out.insert(QStringLiteral("shipped"), s);
    // Fitted on all: what alignconfidence.cpp should ship.
    const Weights all = withCut(rows, everyRow, fitLogistic(rows, everyRow));
    QJsonArray weights;
    for (double v : all)
        weights.append(std::round(v * 1000) / 1000);
    out.insert(QStringLiteral("weightsFittedOnAll"), weights);
    // Each sign alone: its ROC area for "> 80 ms off".
    QJsonObject alone;
    static const char *names[kDoubtCount] = {"unclear", "warpGap", "priorShift", "match", "matchExcess", "lengthMisfit",
        "atMinimum", "nearPause", "passMove", "refineMove", "neighbourGap", "heardMisfit"};
    for (int i = 0; i < kDoubtCount; ++i) {
        std::vector<double> v;
        for (const Row &r : rows)
            v.push_back(r.doubts[size_t(i)]);
        alone.insert(QString::fromLatin1(names[i]), std::round(1000 * bench::rocArea(v, offAll, everyRow)) / 1000);
    }
    out.insert(QStringLiteral("rocAreaPerSign"), alone);
    // The worst syllables.
    std::vector<size_t> order = everyRow;
    std::sort(order.begin(), order.end(),
        [&](size_t a, size_t b) { return std::abs(rows[a].signedMs) > std::abs(rows[b].signedMs); });
    QJsonArray worst;
    for (size_t i = 0; i < std::min<size_t>(30, order.size()); ++i) {
        const Row &r = rows[order[i]];
        QJsonObject o;
        o.insert(QStringLiteral("source"), r.source);
        o.insert(QStringLiteral("syllable"), r.syllable);
        o.insert(QStringLiteral("text"), r.text);
        o.insert(QStringLiteral("errorMs"), std::round(r.signedMs));
        o.insert(QStringLiteral("confidence"), std::round(r.confidence * 100) / 100);
        QJsonObject d;
        for (int k = 0; k < kDoubtCount; ++k)
            d.insert(QString::fromLatin1(names[k]), std::round(r.doubts[size_t(k)] * 1000) / 1000);
        o.insert(QStringLiteral("doubts"), d);
        worst.append(o);
    }
    out.insert(QStringLiteral("worst"), worst);
    // The real recordings' syllables, each with the doubt of the model fitted without it.
    QJsonArray real;
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        if (!r.source.endsWith(QLatin1String(".wav")))
            continue;
        QJsonObject o;
        o.insert(QStringLiteral("source"), r.source);
        o.insert(QStringLiteral("text"), r.text);
        o.insert(QStringLiteral("errorMs"), std::round(r.signedMs));
        o.insert(QStringLiteral("heldOutDoubt"), std::round(heldOutDoubt[i] * 100) / 100);
        QJsonObject d;
        for (int k = 0; k < kDoubtCount; ++k)
            d.insert(QString::fromLatin1(names[k]), std::round(r.doubts[size_t(k)] * 1000) / 1000);
        o.insert(QStringLiteral("doubts"), d);
        real.append(o);
    }
    out.insert(QStringLiteral("realSyllables"), real);
    // Error figures of all the rows, for the tails before and after.
    Errors e;
    for (const Row &r : rows)
        e.add(r.signedMs / 1000, 0, r.confidence);
    out.insert(QStringLiteral("errors"), e.json());
    out.insert(QStringLiteral("what"),
        QStringLiteral("leaveOneSpeakerOut: the confidence model refitted without each speaker (espeak voice or "
                       "real file), its flag cut so that at most 8% of the training syllables are flagged, judged on "
                       "that speaker: of the onsets > 80 ms off how many are flagged, and how many of all"));
    return out;
}

} // namespace

TOONFACE_BENCHMARK("speech.alignConfidence", alignConfidence);
