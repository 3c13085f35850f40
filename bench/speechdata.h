#pragma once

// What the speech benchmarks share: error statistics, synthetic recordings in espeak-ng voices
// with exact syllable times, and the shared data's real recordings with their references.

#include "speech/alignconfidence.h"
#include "speech/audio.h"
#include "speech/lipsync.h"
#include "speech/script.h"

#include <QJsonObject>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toonface::speechbench {

// Onset errors: aligned minus reference, in milliseconds (positive: the mouth is late).
struct Errors
{
    std::vector<double> signedMs;
    std::vector<double> ms; // absolute
    std::vector<bool> flagged; // the aligner doubted the syllable (confidence < kDoubtfulConfidence)
    void add(double aligned, double truth, double confidence = 1.0)
    {
        signedMs.push_back((aligned - truth) * 1000.0);
        ms.push_back(std::abs(aligned - truth) * 1000.0);
        flagged.push_back(confidence < kDoubtful);
    }
    void add(const Errors &more)
    {
        signedMs.insert(signedMs.end(), more.signedMs.begin(), more.signedMs.end());
        ms.insert(ms.end(), more.ms.begin(), more.ms.end());
        flagged.insert(flagged.end(), more.flagged.begin(), more.flagged.end());
    }
    static double quantileOf(std::vector<double> v, double q)
    {
        if (v.empty())
            return 0;
        std::sort(v.begin(), v.end());
        return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
    }
    double quantile(double q) const { return quantileOf(ms, q); }
    double within(double limitMs) const
    {
        if (ms.empty())
            return 0;
        return double(std::count_if(ms.begin(), ms.end(), [&](double e) { return e <= limitMs; })) / double(ms.size());
    }
    QJsonObject json() const;
    // The editor tints syllables below this confidence as doubtful.
    static constexpr double kDoubtful = kDoubtfulConfidence;
};

const QStringList &sentences();

struct Voice
{
    const char *voice;
    int rate, pitch;
};

// The voices alignSynthetic reports (rate, pitch chosen with the aligner's constants).
extern const Voice kVoices[4];

// Speakers no constant of the aligner was chosen on: espeak-ng variants, rates and pitches
// unlike kVoices and the reference's default voice.
extern const Voice kHeldOutVoices[6];

// The shared sentences and some whose tones change in context (一, 不, 3rd before 3rd).
QStringList heldOutSentences();

// A synthetic recording: the script spoken in `v`, with leading and trailing silence, a pause
// the script does not mark, and white noise `snrDb` under the speech; `truth` gets its syllable
// onsets, `pausedBefore` (when given) the syllable the pause comes before.
Audio syntheticRecording(const Script &script, const Voice &v, quint32 seed, std::vector<double> *truth,
    double snrDb = 20, int *pausedBefore = nullptr);

Script mandarin(const QString &text);

// One real recording of the shared data with the script it is aligned with and, when known,
// its reference syllable onsets.
struct RealFile
{
    QString name; // file name under speech/
    QString script;
    std::vector<double> truth; // seconds per syllable (NaN: not known); empty: only the transcript is known
    QString note; // how the script and the truth were chosen
    bool heldOut = false; // measured apart, never tuned on
};

QVector<RealFile> realFiles(const QString &dir);

double shortestMs(const QVector<LipsyncSyllable> &syllables);
double lowestConfidence(const QVector<LipsyncSyllable> &syllables);

// Aligns `file` exactly as `toonface-cli lipsync` does (lipsyncFiles on the audio file and a
// script file).
LipsyncOutcome lipsyncRealFile(const QString &dir, const RealFile &file);

// The GRID clip's word tier (shared/data/video/swwp2s.align, units of 1/25000 s): its words and
// their onsets in seconds, silences left out; empty when absent.
struct GridWordTier
{
    QStringList words;
    std::vector<double> onsets;
};

GridWordTier gridWordTier(const QString &dataDir);

// `toonface-cli lipsync` end to end on the shared recordings joined, round after round (a round
// is about 20 s), timed and scored: {"runs": {"<seconds>s": ...}, "processStart": ...}.
QJsonObject lipsyncLongReal(const std::vector<int> &roundCounts);

} // namespace toonface::speechbench
