#pragma once

#include <QImage>
#include <QPointF>

#include <opencv2/core.hpp>

#include <vector>

namespace toonface {

class FaceModel;

// A face turned level and scaled so that its pupils lie kLevelEs0 pixels apart, their middle at
// (kLevelCentre, kLevelCentre), in L* with its fine detail and gradient: the measures of age and
// of the brows read every photo at the same scale and upright.
inline constexpr double kLevelEs0 = 48.0;
inline constexpr double kLevelCentre = 100.0;

struct LevelFace
{
    cv::Mat l, detail, gradient, valid; // L* 0..100; |L* - its 3x3 mean|; Sobel magnitude; inside the photo
    cv::Mat affine; // photo (as scaled, see `prescale`) -> level face, 2x3 doubles
    double prescale = 1.0; // the photo was first shrunk by this (area averaging), then turned

    bool isNull() const { return l.empty(); }
    // A photo point in ES0 from the eyes' middle (x right, y down).
    QPointF map(QPointF p) const;
    // The valid pixels of `of` (one of the maps above) in a box centred (cx, cy) with half sizes
    // (hw, hh), all in ES0.
    std::vector<float> box(const cv::Mat &of, double cx, double cy, double hw, double hh) const;
};

// Empty when the pupils lie less than 4 pixels apart.
LevelFace levelFace(const QImage &photo, const FaceModel &face);

} // namespace toonface
