#pragma once

// sRGB to CIE Lab at 8 bits, in OpenCV's encoding of 8-bit Lab (L* scaled by 255/100, a* and
// b* offset by 128), without OpenCV: its cvtColor builds its Lab tables in software floating
// point the first time it is asked for Lab (0.15-0.2 s of one core), a cost a process that
// detects one face would pay inside its first detection. Here the tables are two small ones
// (256 gamma values, a cube root sampled 4096 times) made in well under a millisecond.

#include <QColor>

namespace cv {
class Mat;
}

namespace toonface {

// `rgb` (CV_8UC3, red first) in Lab, as CV_8UC3 in `lab` (reallocated as needed): within one
// unit of what cv::cvtColor(rgb, lab, cv::COLOR_RGB2Lab) gives.
void rgbToLab8(const cv::Mat &rgb, cv::Mat &lab);

// One colour in CIE Lab (D65): L* in 0..100, a* and b* about 0 (through the same 8-bit tables).
struct LabColour
{
    double l = 0, a = 0, b = 0;
};
LabColour labOf(const QColor &c);
// ... and back to sRGB (exactly, not through the 8-bit tables), clipped to the gamut.
QColor colourOfLab(const LabColour &lab);

} // namespace toonface
