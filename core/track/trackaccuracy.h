#pragma once

#include "track/trackvideo.h"

#include <QString>
#include <QVector>

#include <optional>

namespace toonface {

// Per-frame signals of a clip for judging a tracking: the mouth's opening (the inner lips'
// gap 2.2-2.3) and the eyes' aperture (the mean lid distance 3.2-3.4, 3.1-3.3), each in ES0.
struct ClipSignals
{
    QVector<double> times;
    QVector<double> mouthOpen;
    QVector<double> eyeOpen;
};

// The reference: the raw landmark model on every frame, from the face detector's box as
// detection places it (no tracking, no filtering). Frames without a face repeat the frame
// before. nullopt with *error when the clip cannot be read or has no face at all.
std::optional<ClipSignals> referenceSignals(const QString &path, QString *error);

// The same signals from a tracked clip (its filtered motion; lid openings times the neutral's
// aperture so that both are in ES0).
ClipSignals trackedSignals(const TrackResult &track);

struct TrackAccuracy
{
    double mouthCorrelation = 0; // Pearson, tracked vs reference
    double eyeCorrelation = 0;
    int referenceBlinks = 0;
    int blinksFound = 0; // reference blinks with a tracked blink within two frames
    int extraBlinks = 0; // tracked blinks with no reference blink near
};
TrackAccuracy compareSignals(const ClipSignals &tracked, const ClipSignals &reference, double fps);

double pearson(const QVector<double> &a, const QVector<double> &b);

// How a clip's mouth agrees with its own sound, for a speaker whose words the lip sync cannot
// read (GRID is English): the outer lips' parting (8.2's y less 8.9's displacement, ES0) per
// frame against the sound's loudness over that frame (RMS of `samples` in [time, time +
// period)). Speech is loud while the mouth is open on a vowel and quiet while it shuts, and the
// lips lead the sound they shape, so the correlation is the best Pearson over the mouth leading
// by 0 to `maxLeadFrames` frames.
struct SoundAgreement
{
    double correlation = 0; // at the best lead
    double correlationInSync = 0; // with no lead
    int leadFrames = 0;
};
SoundAgreement mouthSoundAgreement(const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate,
    double period, int maxLeadFrames = 3);

} // namespace toonface
