#pragma once

#include <QColor>
#include <QImage>
#include <QRectF>

namespace toonface {

// The photo's white balance, estimated by the grey-edge hypothesis (the average edge of a scene
// is grey: a colour cast shows as unequal edge strength per channel), as channel gains that take
// the cast out. Large areas of one colour (a wall, a suit) have few edges, so they do not pull
// the estimate the way they pull a grey-world average; and since a cast lies over the whole
// scene, the correction fades out where parts of the picture disagree about it (a face on a
// plain coloured backdrop keeps its colours). A plain value type.
struct ColourBalance
{
    double gain[3] = {1.0, 1.0, 1.0}; // red, green, blue; their mean is 1
    bool greyscale = false; // the photo has no colour at all (every pixel nearly grey)

    // Gains are kept within [1 / kMaxGain, kMaxGain]: a stronger "cast" is the scene's colour.
    static constexpr double kMaxGain = 1.5;

    // Measured on `region` of the photo (photo pixels; the whole photo when empty): around the
    // head, so a collage or a group under several lights is balanced for the face at hand.
    static ColourBalance measure(const QImage &photo, const QRectF &region = {});
    QColor apply(const QColor &c) const;
    QImage apply(const QImage &photo) const; // RGB32
    bool isIdentity() const { return gain[0] == 1.0 && gain[1] == 1.0 && gain[2] == 1.0; }
};

// Natural colours for a photo without colour, chosen from its tones: a skin tone as light as
// `grey` (0..255) on a ramp from deep brown to pale, and hair that keeps grey or white when it
// is light and is a brown-black of its shade otherwise.
QColor skinFromGrey(int grey);
QColor hairFromGrey(int grey);

} // namespace toonface
