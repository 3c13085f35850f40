#pragma once

#include "face/emotion.h"

#include <QString>

namespace toonface {

// The names the files and the CLI use (emotionName(), Style::presetNames(), the appearance's
// variants, the detection methods) as the interface shows them: capitalised in English,
// translated in the other languages (context "toonface::Names").

QString emotionTitle(Emotion emotion);
// A drawing style preset ("normal", "soft", "bold", "cute").
QString styleTitle(const QString &preset);
// An appearance variant (eyebrowVariantName(), noseVariantName(), glassesShapeName()) or a
// detection method ("landmarks", "classic"); an unknown name is shown as it is.
QString variantTitle(const QString &name);
// One of the 72 points (an index of pointTable()) as a user names it: "Mouth, left corner",
// "Left eye, upper lid", "Hair outline, point 3" — never the model's ID ("8.4"). Left and right
// are as the photo shows them.
QString pointTitle(int index);

} // namespace toonface
