#pragma once

// The colour of head and facial hair, read from the pixels a finder says are hair (the parse's
// hair sample, the beard's boxes) and told as one of five shades: black, brown, red (copper,
// auburn), blond, grey (grey and white). The reading keeps only the pixels unlike the skin and the
// room around the head, and of those the middle of their lightness (neither the shadows between
// strands nor a shine), so a grey beard is not read as the skin between its hairs nor white hair
// as the wall behind it. The shade is told by thresholds on L*, chroma and hue (HairShadeRules,
// fitted on the labelled faces); the drawn colour keeps what was read and is pushed toward the
// shade's own look (grey without colour, red with it) only as far as the call is sure.

#include "detect/labcolour.h"

#include <QColor>
#include <QString>

#include <vector>

namespace toonface {

struct HeadParse;

enum class HairShade { Black, Brown, Red, Blond, Grey };
QString hairShadeName(HairShade shade); // "black", "brown", "red", "blond", "grey"

struct HairColourReading
{
    bool valid = false;
    LabColour hair; // the strands' colour (L* 0..100)
    LabColour skin; // the skin it was told from
    double kept = 0; // share of the sample kept as hair (the rest was like the skin or the room)
    int pixels = 0; // how many pixels were kept

    double chroma() const;
    double hue() const; // degrees in the a*b* plane, -180..180 (0: red-magenta, 90: yellow)
    QColor colour() const; // `hair` in sRGB
};

// Reads the hair's colour from `sample` (sRGB pixels said to be hair), against the skin's colour
// and, when valid, the room's (the background beside the head). Invalid with too few pixels.
HairColourReading readHairColour(const std::vector<QRgb> &sample, const QColor &skin, const QColor &room = {});
// ... from the parse's hair sample, against its cheeks and its background above the eyes.
HairColourReading readHairColour(const HeadParse &parse);

// The thresholds that tell the shade, tried in this order: grey (little chroma, light), red
// (chroma at a red hue), blond (light), black (dark), else brown.
struct HairShadeRules
{
    double greyChroma = 0; // grey: chroma below this ...
    double greyL = 0; // ... and L* from this
    double redChroma = 0; // red: chroma from this ...
    double redHue = 0; // ... at a hue below this (degrees; redder)
    double blondL = 0; // blond: L* from this
    double blackL = 0; // black: L* below this

    // The thresholds `toonface-bench likeness.attributes` fits on all the labelled faces (it
    // prints the held-out folds' figures of the same fit).
    static HairShadeRules fitted();
};

struct HairShadeCall
{
    HairShade shade = HairShade::Brown;
    double confidence = 0; // 0 (on a threshold) .. 1 (far past every threshold of its rule)
};
HairShadeCall classifyHair(const HairColourReading &reading, const HairShadeRules &rules = HairShadeRules::fitted());

// The colour to draw: the reading's own, pushed toward the shade's look as far as the call is
// sure (grey loses its chroma and is drawn at least mid-grey, red keeps a copper's chroma, blond
// a blond's lightness, black is drawn dark); a brown stays as read.
QColor drawnHairColour(const HairColourReading &reading, const HairShadeCall &call);

} // namespace toonface
