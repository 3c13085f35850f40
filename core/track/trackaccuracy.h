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

} // namespace toonface
