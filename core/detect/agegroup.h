#pragma once

#include "face/appearance.h"

#include <QImage>

#include <array>

namespace toonface {

class FaceModel;

// What a photo and its points say of the person's age, measured on the face turned level and
// scaled (levelface.h). Proportions are in ES0 from the eyes' middle; textures
// are the mean fine detail (|L* - its 3x3 mean|) over the photo's sharpness (the strongest edges
// of the eyes' band: lids and irises), so that a sharp portrait and a soft crop read alike.
struct AgeEvidence
{
    // A child's lower face is short: mouth to chin and eyes to the nose's tip are small against
    // the eye distance, the face wide for its height.
    double mouthToChin = 0, noseDrop = 0, roundness = 0;
    // Wrinkles: the cheeks', the crow's feet's (beside the outer corners) and under the eyes'.
    double cheekTexture = 0, crowTexture = 0, underTexture = 0;
    // Elderly noses widen and eyes narrow (lids droop over the corners).
    double noseWidth = 0, eyeWidth = 0;
    bool measured = false; // false: the face lies too far outside the photo to say
};

AgeEvidence measureAgeEvidence(const QImage &photo, const FaceModel &face);

// The features each model reads, in its coefficients' order (the bench fits them by name).
inline constexpr std::array<const char *, 5> kChildFeatures {
    "mouthToChin", "noseDrop", "roundness", "cheekTexture", "crowTexture"};
inline constexpr std::array<const char *, 4> kElderlyFeatures {"cheekTexture", "underTexture", "noseWidth", "eyeWidth"};
double ageFeature(const AgeEvidence &e, const char *name);

struct AgeDecision
{
    AgeGroup group = AgeGroup::Adult;
    double child = 0, elderly = 0; // the two models' probabilities (elderly: if not a child)
    double confidence = 0.5; // the chosen group's probability: child, (1-child)*elderly, or the rest
};

// Child first (its model over every face), else elderly (its model fitted on faces that are not
// children), else adult. The thresholds favour precision: an adult drawn as a child is worse than
// a child drawn as an adult.
AgeDecision decideAge(const AgeEvidence &e);

// The same with given models (bias then one weight per feature, on the raw features) and
// thresholds: for the bench's cross-validation.
struct AgeModels
{
    std::array<double, kChildFeatures.size() + 1> child {};
    std::array<double, kElderlyFeatures.size() + 1> elderly {};
    double childThreshold = 0.8, elderlyThreshold = 0.75;
};
AgeModels shippedAgeModels();
AgeDecision decideAge(const AgeEvidence &e, const AgeModels &models);

} // namespace toonface
