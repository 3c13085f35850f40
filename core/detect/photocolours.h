#pragma once

#include "render/style.h"

class QImage;

namespace toonface {

class FaceModel;
struct AgeDecision;
struct AppearanceFindings;
struct HairColourReading;

// Sets `style`'s skin, hair, brow, lip, iris and clothes colours from the photo under the face's
// points, corrected for the photo's white balance (a greyscale photo gets natural colours from its
// tones), and its appearance (glasses, facial hair, hat, bald head) with the colours of what it
// finds; `findings`, when given, receives the appearance detection's measures. A null photo
// leaves the style as it is.
void sampleColours(const QImage &photo, const FaceModel &face, Style *style, AppearanceFindings *findings = nullptr);

// The colour a beard or a moustache read as `reading` (haircolour.h) is drawn in; `seen` where
// nothing was read. A beard's strands lie over the skin and read with its warmth: on the labelled
// grey-haired men's beards, chroma 17 to 22 against the grey shade's 14.6, so they were told fair
// or light brown. On a face decided elderly (`age`), strands at least as light as the grey shade
// asks and much paler than the skin (below 0.75 of its chroma; the labelled faces' red and fair
// beards read 0.8 of it or more) are grey hair, drawn as sure grey. As the head's hair, strands
// read grey on a face too young for grey hair that do not read white are dark hair, drawn in
// `dark`'s hue (the brows'). `grey` receives whether the hair is drawn grey (grey hair is never
// drawn see-through, as stubble is).
QColor drawnFacialHair(
    const HairColourReading &reading, const QColor &seen, const AgeDecision &age, const QColor &dark, bool *grey);

} // namespace toonface
