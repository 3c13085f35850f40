#pragma once

// What each emotion preset must look like on a face, measured on its still drawing
// (stillEmotionPose) against the same face's neutral one: the geometric signature by which it
// reads as itself and as no other. Shared by the synthetic faces of tst_emotion and the shared
// photos of tst_emotionfaces. In ES0 (eye distances), heights square to the eye line.

#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/restingface.h"

#include <QString>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace toonface::testing {

// Brows that the hairline stopped (keepBrowsUnderHairline) may not rise as the preset says: a
// surprise then reads by its open mouth and wide eyes alone.
inline bool browsAtHairline(const FaceModel &face, const Pose &pose)
{
    const auto p = posedPoints(face, pose);
    const double es0 = face.fapu().es0;
    const double limit = face.point("11.1").y() + kBrowBelowHairline * es0;
    for (const char *id : {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"})
        if (p[pt::idx(id)].y() <= std::max(limit, face.point(id).y()) + 1e-6 * es0)
            return true;
    return false;
}

// The failed conditions, in words (empty: every preset reads as itself on `face`).
inline QStringList emotionSignatureFailures(const FaceModel &face)
{
    QStringList failed;
    auto shape = [&](Emotion e) { return expressionShape(face, stillEmotionPose(face, e, 1.0)); };
    auto check = [&](bool ok, const QString &what) {
        if (!ok)
            failed << what;
    };
    const ExpressionShape n = shape(Emotion::Neutral), sad = shape(Emotion::Sad), angry = shape(Emotion::Angry),
                          smile = shape(Emotion::Smile), surprise = shape(Emotion::Surprise);
    constexpr double eps = 1e-6;
    const BrowRestBands &band = kBrowRest;
    // A low hairline (a fringe, a hat's brim) may keep low brows from rising to the band.
    const bool neutralAtHairline = browsAtHairline(face, stillEmotionPose(face, Emotion::Neutral, 1.0));
    // The lips at rest touch or nearly: restingMouth leaves a gap under a tenth of MNS0.
    const double shut = 0.1 * face.fapu().mns0 / face.fapu().es0 + 0.005;
    auto num = [](double v) { return QString::number(v, 'f', 3); };
    for (int side = 0; side < 2; ++side) {
        const QString s = side == 0 ? QStringLiteral("left") : QStringLiteral("right");
        // Neutral: the brows at rest (height and slant in the bands), the mouth shut and straight.
        const double mean = (n.innerHeight[side] + n.outerHeight[side]) / 2;
        check(n.slant(side) >= band.slantLow - eps && n.slant(side) <= band.slantHigh + eps,
            QStringLiteral("neutral %1 brow slant %2").arg(s, num(n.slant(side))));
        check((mean >= band.heightLow - eps || neutralAtHairline) && mean <= band.heightHigh + eps,
            QStringLiteral("neutral %1 brow height %2").arg(s, num(mean)));
        // Sad: the inner ends raised over the outer ones, far past rest.
        check(sad.slant(side) >= n.slant(side) + 0.25,
            QStringLiteral("sad %1 brow slant %2 (neutral %3)").arg(s, num(sad.slant(side)), num(n.slant(side))));
        // Angry: the inner ends lowered under the outer ones.
        check(angry.slant(side) <= n.slant(side) - 0.2,
            QStringLiteral("angry %1 brow slant %2 (neutral %3)").arg(s, num(angry.slant(side)), num(n.slant(side))));
        // Sad and angry unmistakable: their brows slant opposite ways, far apart.
        check(sad.slant(side) - angry.slant(side) >= 0.45,
            QStringLiteral("sad/angry %1 slants %2 / %3").arg(s, num(sad.slant(side)), num(angry.slant(side))));
    }
    check(n.innerGap >= band.innerGapLow - eps, QStringLiteral("neutral inner brow gap %1").arg(num(n.innerGap)));
    check(n.cornerLift <= eps && n.cornerLift >= -kRestingCornerDrop - eps,
        QStringLiteral("neutral mouth corners %1").arg(num(n.cornerLift)));
    check(n.mouthOpen <= shut, QStringLiteral("neutral mouth open %1").arg(num(n.mouthOpen)));
    // Sad: the corners well down (a pout's arch).
    check(sad.cornerLift <= n.cornerLift - 0.15,
        QStringLiteral("sad mouth corners %1 (neutral %2)").arg(num(sad.cornerLift), num(n.cornerLift)));
    // Angry: the brows drawn together, the lips pressed shut: corners only a little down, far
    // less than sad's.
    check(angry.innerGap <= n.innerGap - 0.1,
        QStringLiteral("angry inner brow gap %1 (neutral %2)").arg(num(angry.innerGap), num(n.innerGap)));
    check(angry.mouthOpen <= shut, QStringLiteral("angry mouth open %1").arg(num(angry.mouthOpen)));
    check(angry.cornerLift <= n.cornerLift + eps && angry.cornerLift >= sad.cornerLift + 0.1,
        QStringLiteral("angry mouth corners %1 (neutral %2, sad %3)")
            .arg(num(angry.cornerLift), num(n.cornerLift), num(sad.cornerLift)));
    check(angry.lipHeight < n.lipHeight - 0.03,
        QStringLiteral("angry lips %1 high (neutral %2)").arg(num(angry.lipHeight), num(n.lipHeight)));
    // Smile: the corners up.
    check(smile.cornerLift >= n.cornerLift + 0.1,
        QStringLiteral("smile mouth corners %1 (neutral %2)").arg(num(smile.cornerLift), num(n.cornerLift)));
    // Surprise: the brows high (unless the hairline stops them) and the jaw dropped.
    const double nMean = (n.innerHeight[0] + n.outerHeight[0] + n.innerHeight[1] + n.outerHeight[1]) / 4;
    const double sMean
        = (surprise.innerHeight[0] + surprise.outerHeight[0] + surprise.innerHeight[1] + surprise.outerHeight[1]) / 4;
    check(sMean >= nMean + 0.15 || browsAtHairline(face, stillEmotionPose(face, Emotion::Surprise, 1.0)),
        QStringLiteral("surprise brow height %1 (neutral %2)").arg(num(sMean), num(nMean)));
    check(surprise.mouthOpen >= 0.2, QStringLiteral("surprise mouth open %1").arg(num(surprise.mouthOpen)));
    return failed;
}

} // namespace toonface::testing
