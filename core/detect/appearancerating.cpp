#include "detect/appearance.h"

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// A decision's confidence from its margin past its threshold, in the measure's own units of
// doubt (`unit`): 0.5 on the threshold, 0.88 a unit away, 0.98 two units away.
double sureness(double margin, double unit)
{
    return 1.0 / (1.0 + std::exp(-2.0 * std::abs(margin) / unit));
}

void judgeConfidence(AppearanceFindings *out)
{
    using A = AppearanceFindings;
    const AppearanceEvidence &e = out->evidence;
    constexpr double kRedUnit = 3.0, kDetailUnit = 0.3, kLUnit = 8.0, kLineUnit = 2.0;
    // delta E*ab: the redness' unit over its three channels (sqrt 3 x 3, rounded).
    constexpr double kColourUnit = 5.0;
    // A rule "a and b": the smaller margin; "x or y": the larger.
    const double lip = std::max(std::min((e.lipColour - A::kLipColour) / kColourUnit,
                                    (std::max(e.lipRedLoss, e.chinRedLoss) - A::kRedLossSure) / kRedUnit),
        (-e.lipDL - A::kLipDarker) / kLUnit);
    const double chin = std::max(
        std::min((e.chinRedLoss - A::kChinRedLoss) / kRedUnit, (e.chinDetail - A::kChinDetail) / kDetailUnit),
        (-e.chinDL - A::kChinDarker) / kLUnit);
    const double jaw = std::max((e.jawRedLoss - A::kJawRedLoss) / kRedUnit, (-e.jawDL - A::kChinDarker) / kLUnit);
    const double frame = std::max(std::min((e.bridgeLine - A::kBridgeLine) / kLineUnit,
                                      std::max(e.lowerRims - A::kLowerRims, e.sideRims - A::kSideRims) / kLineUnit),
        (out->glassesScore - A::kGlassesThreshold) / 1.0);
    out->confidence.moustache = sureness(lip, 1.0);
    out->confidence.beard = sureness(std::min(chin, jaw), 1.0);
    out->confidence.goatee = sureness(std::min(chin, -jaw), 1.0);
    out->confidence.glasses = sureness(frame, 1.0);
    out->confidence.bald = !out->crownCut ? sureness(out->scalpReach - A::kScalpReach, 0.1)
                                          : sureness(out->baldScore - A::kBaldThreshold, 0.2);
    out->confidence.headwear = out->cover.seen && !out->crownToHair
        ? sureness(out->cover.hueOff * out->cover.chroma / 100.0 - kCoverColourScore, 10.0)
        : sureness(std::min(out->crownToHair, out->crownToSkin) - A::kHatContrast, 15.0);
    out->confidence.hairLength = out->appearance.bald ? out->confidence.bald
        : out->hairSeen
        ? sureness(std::min(std::abs(out->hairFall - A::kFallMedium), std::abs(out->hairFall - A::kFallLong)), 0.3)
        : out->templeHairSeen
        ? sureness(
            std::min(std::abs(out->hairFall - A::kTempleFallMedium), std::abs(out->hairFall - A::kTempleFallLong)), 0.3)
        : sureness(std::min(std::abs(out->hairDrop - A::kHairMedium), std::abs(out->hairDrop - A::kHairLong)), 0.1);
}

HairLength hairLengthOf(const AppearanceFindings &f)
{
    if (f.appearance.bald)
        return HairLength::None;
    // Where the parse saw the crown's hair, how far it falls beside the face; else the outline.
    if (f.hairSeen)
        return f.hairFall >= AppearanceFindings::kFallLong  ? HairLength::Long
            : f.hairFall >= AppearanceFindings::kFallMedium ? HairLength::Medium
                                                            : HairLength::Short;
    if (f.templeHairSeen)
        return f.hairFall >= AppearanceFindings::kTempleFallLong  ? HairLength::Long
            : f.hairFall >= AppearanceFindings::kTempleFallMedium ? HairLength::Medium
                                                                  : HairLength::Short;
    return f.hairDrop >= AppearanceFindings::kHairLong  ? HairLength::Long
        : f.hairDrop >= AppearanceFindings::kHairMedium ? HairLength::Medium
                                                        : HairLength::Short;
}

} // namespace

QString hairLengthName(HairLength length)
{
    switch (length) {
    case HairLength::None: return QStringLiteral("none");
    case HairLength::Short: return QStringLiteral("short");
    case HairLength::Medium: return QStringLiteral("medium");
    case HairLength::Long: return QStringLiteral("long");
    }
    return QStringLiteral("short");
}

void rateAppearance(const FaceModel &face, AppearanceFindings *out)
{
    const double eyeY = (face.point("3.6").y() + face.point("3.5").y()) / 2.0;
    out->hairDrop = (std::max(face.point("h.1").y(), face.point("h.19").y()) - eyeY)
        / std::max(1.0, face.point("2.1").y() - eyeY);
    out->hairLength = hairLengthOf(*out);
    judgeConfidence(out);
}

} // namespace toonface
