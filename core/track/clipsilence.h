#pragma once

#include "track/tracker.h"

#include <QVector>

namespace toonface {

// Where a tracked clip's speaker is silent, from the clip's own sound: there the mouth is at
// rest, whatever the lips do. GRID speakers hold their lips a little apart before and after
// the sentence; carried into the table's range (track/mouthrange.h) that read as `a`.
//
// A frame is silent when its sound (RMS over the frame) is nearer the clip's room than its
// voice: under the level kSilenceShare of the way (in dB) from the room (the kRoomPercentile
// of its frames' levels) to the voice (the kLoudPercentile: its vowels), or under
// kSilenceGateDb; and so are the frames around it within the lips' lead over the voice
// (kLipLeadS before it, as the lips take their shape before the voice sounds) and their
// closing after it (kLipCloseS). A run of silent frames shorter than kMinSilenceS (a stop's
// closure inside a word) is speech. A clip whose loudest frames are within kMinVoiceRangeDb of
// its room shows no voice to tell from it (music, a steady noise): nothing is silent.
//
// Fitted on the four GRID clips of shared/data/video (bench track.clipSilence sweeps the share):
// their voice is at -7 to -11 dBFS, their room at -39 to -51 dBFS, and a room only 32 dB under
// the voice (lbax4n's) rules out a fixed distance from the voice. The shares that keep each
// clip's leading silence silent and its sentence unbroken: bbaf2n 0.40-0.90 (a breath at
// -34 dBFS in its silence), swwp2s 0.30-0.80 (above, a dip inside "with p two" turns silent),
// lbax4n and pwij3p 0.30-0.90; 0.6 is the middle of all four's 0.40-0.80, and leaving any one
// clip out moves the middle to 0.55-0.65, inside the range of the clip left out. On the clip with
// word times (swwp2s.align) the silence found ends 1.25 frames before the marked `sil` and
// starts 0.75 after it.
inline constexpr int kSilenceSampleRate = 16000; // the rate the sound is read at for this
inline constexpr double kLoudPercentile = 0.95;
inline constexpr double kRoomPercentile = 0.05;
inline constexpr double kSilenceShare = 0.6;
inline constexpr double kMinVoiceRangeDb = 12.0;
inline constexpr double kSilenceGateDb = -60.0; // quieter than this (dBFS) is silence, whatever the clip
// Set, not fitted: 3 and 2 frames at 25 fps, the lead of the lips over the sound that
// mouthSoundAgreement() finds on these clips being 0-3 frames.
inline constexpr double kLipLeadS = 0.12;
inline constexpr double kLipCloseS = 0.08;
inline constexpr double kMinSilenceS = 0.15; // as the lip sync's return to `m` (speech/lipsync.h)

// Each frame's sound: the RMS level of `samples` over [time, time + period), in dBFS (-120
// for none).
QVector<double> frameLevelsDb(
    const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate, double period);

// Which of `frames` are silent (see above); all false when `samples` is empty. `share` is
// there for the bench's fit.
QVector<bool> silentFrames(const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate,
    double period, double share = kSilenceShare);

} // namespace toonface
