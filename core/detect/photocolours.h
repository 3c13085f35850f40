#pragma once

#include "render/style.h"

class QImage;

namespace toonface {

class FaceModel;
struct AppearanceFindings;

// Sets `style`'s skin, hair, brow, lip, iris and clothes colours from the photo under the face's
// points, corrected for the photo's white balance (a greyscale photo gets natural colours from its
// tones), and its appearance (glasses, facial hair, hat, bald head) with the colours of what it
// finds; `findings`, when given, receives the appearance detection's measures. A null photo
// leaves the style as it is.
void sampleColours(const QImage &photo, const FaceModel &face, Style *style, AppearanceFindings *findings = nullptr);

} // namespace toonface
