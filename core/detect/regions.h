#pragma once

#include <QImage>
#include <QPointF>
#include <QRect>
#include <QSize>

#include <cstdint>
#include <vector>

namespace toonface {

// One channel of an image as floats, row-major.
struct Plane
{
    QSize size;
    std::vector<float> values;

    float at(int x, int y) const { return values[size_t(y) * size.width() + x]; }
    float &at(int x, int y) { return values[size_t(y) * size.width() + x]; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < size.width() && y < size.height(); }
};

// A binary image, row-major, one byte per pixel (0 or 1).
struct Mask
{
    QSize size;
    std::vector<std::uint8_t> values;

    std::uint8_t at(int x, int y) const { return values[size_t(y) * size.width() + x]; }
    std::uint8_t &at(int x, int y) { return values[size_t(y) * size.width() + x]; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < size.width() && y < size.height(); }
    QImage toImage() const; // 1 white, 0 black
};

// The HSI intensity I = (R + G + B) / 3, on the 0..255 scale of the 8-bit channels.
Plane intensityPlane(const QImage &image);

// The HSI hue as a signed angle normalised to [-127, 128] (thesis 3.3.4): hue 0 (red) maps to
// 0 and the scale is 255/360 per degree, so skin tones, which straddle red, do not wrap.
// Pixels with too little saturation to have a hue (S < kMinSaturation) get 128, the hue
// farthest from red, so grey backgrounds stay apart from skin.
inline constexpr double kMinSaturation = 0.05;
Plane huePlane(const QImage &image);

// The default central rectangle of Algorithm 4.1 (the middle third of each side: a large
// frontal face covers it).
QRect centralRect(QSize size);

// Algorithm 4.1: t1 = m1 - s1 of the intensity in `rect` (eqs. 3.1-3.3); B1 = 1 where I > t1.
struct FirstLevel
{
    QRect rect;
    double m1 = 0, s1 = 0, t1 = 0;
    Mask b1;
};
// `k` generalises eq. (3.3) to t1 = m1 - k s1 (the thesis: k = 1).
// requires: rect intersects the plane and holds at least two pixels.
FirstLevel firstLevelThreshold(const Plane &intensity, QRect rect, double k = 1.0);

// Algorithm 4.3: m2, s2 of the hue in `rect` (eqs. 3.6-3.7); B2 = 1 (background) where
// |H - m2| > s2 (eqs. 3.8-3.9), 0 (face) where |H - m2| <= s2 and B1 = 1. Dark pixels
// (B1 = 0), which eq. 3.9 leaves open, are not face: B2 = 1.
struct SecondLevel
{
    double m2 = 0, s2 = 0;
    Mask b2;
};
SecondLevel secondLevelThreshold(const Plane &hue, const Mask &b1, QRect rect);

// A connected region of equal mask values (8-connected).
struct Region
{
    int label = 0; // in the label image of growRegions
    int area = 0; // pixels
    QRect box;
    QPointF centroid;
    bool touchesBorder = false;
};

// Region growing from every pixel of value `value`: the 8-connected components, with a
// label image (0 = not of `value`, k = region k - 1 of the returned list).
std::vector<Region> growRegions(const Mask &mask, std::uint8_t value, std::vector<int> *labels = nullptr);

// Algorithm 4.4 (eqs. 3.10-3.12): F_final = everything but the background regions of B2 that
// touch the image border; B3 = B1 AND B2; H_final = everything but the regions of B3 that
// touch the border. The hair region proper is H_final minus F_final.
struct RefinedRegions
{
    Mask face; // F_final
    Mask b3;
    Mask hair; // H_final - F_final
};
RefinedRegions refineRegions(const Mask &b1, const Mask &b2);

} // namespace toonface
