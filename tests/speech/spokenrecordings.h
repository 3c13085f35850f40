#pragma once

#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QString>
#include <QVector>

#include <utility>
#include <vector>

// Recordings made of espeak-ng speech for the aligner's suites, with the onsets they hold,
// and the checks those suites make of an alignment.

namespace toonface::testing {

Script mandarin(const QString &text);

// Median and 90th percentile of absolute onset errors, in ms.
std::pair<double, double> onsetErrors(const AlignResult &r, const std::vector<double> &truth);

// The script spoken in another voice with leading and trailing silence, one pause the script
// does not mark, and white noise `snrDb` under the speech; `truth` gets the onsets.
Audio recording(const Script &script, const TtsOptions &voice, double snrDb, quint32 seed, std::vector<double> *truth,
    int *pausedBefore = nullptr);

// Spoken pieces joined: each piece of the script at its own rate (a speaker who speeds up or
// slows down within a phrase), `gap` seconds of silence before each piece after the first,
// `lead` and 0.4 s of silence around; a hum (50 Hz and its harmonics, loud in the whole band,
// faint in the mid band, as a mains hum or a fan makes) `humDb` under the speech and white
// noise `snrDb` under it over everything, and `leadSnrDb` under it over the lead (a room's
// noise before the speaker's first word, louder than in the pauses after). `truth` gets the
// onsets.
Audio pieces(const QVector<QPair<Script, int>> &parts, const QString &voice, double lead, double gap, double humDb,
    double snrDb, quint32 seed, std::vector<double> *truth, double leadSnrDb = 200,
    const QVector<double> &gainsDb = {});

double shortestSyllable(const AlignResult &r);

// No syllable shorter than 60 ms: a mouth shape held for less is hardly seen (a frame and a
// half at 25 fps). (The aligner's floor is kShortestSyllable; this is what it must give.)
void checkNotSqueezed(const AlignResult &r);

void checkWellFormed(const AlignResult &r, int n, double duration);

} // namespace toonface::testing
