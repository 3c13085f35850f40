#include "detect/labcolour.h"

#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace toonface {

namespace {

// CIE Lab of sRGB under D65 (the primaries' XYZ, the white point, the CIE's constants).
constexpr float kRgbToXyz[3][3] = {
    {0.412453f, 0.357580f, 0.180423f},
    {0.212671f, 0.715160f, 0.072169f},
    {0.019334f, 0.119193f, 0.950227f},
};
constexpr float kWhite[3] = {0.950456f, 1.0f, 1.088754f};
constexpr float kEpsilon = 0.008856f; // below it, the cube root is replaced by a line
constexpr float kKappa = 903.3f;
constexpr int kCbrtSteps = 4096;

struct Tables
{
    std::array<float, 256> linear {}; // an 8-bit sRGB value made linear, in [0, 1]
    std::array<float, kCbrtSteps + 2> f {}; // CIE's f(t) at t = i / kCbrtSteps, interpolated between

    Tables()
    {
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            linear[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        for (int i = 0; i < kCbrtSteps + 2; ++i) {
            const double t = double(i) / kCbrtSteps;
            f[i] = float(t > kEpsilon ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0);
        }
    }

    float cieF(float t) const
    {
        const float at = std::clamp(t, 0.0f, 1.0f) * kCbrtSteps;
        const int i = int(at);
        return f[i] + (f[i + 1] - f[i]) * (at - float(i));
    }
};

const Tables &tables()
{
    static const Tables t;
    return t;
}

uchar toByte(float v)
{
    return uchar(std::clamp(int(std::lround(v)), 0, 255));
}

} // namespace

void rgbToLab8(const cv::Mat &rgb, cv::Mat &lab)
{
    CV_Assert(rgb.type() == CV_8UC3);
    const Tables &t = tables();
    lab.create(rgb.size(), CV_8UC3);
    for (int y = 0; y < rgb.rows; ++y) {
        const uchar *in = rgb.ptr<uchar>(y);
        uchar *out = lab.ptr<uchar>(y);
        for (int x = 0; x < rgb.cols; ++x, in += 3, out += 3) {
            const float r = t.linear[in[0]], g = t.linear[in[1]], b = t.linear[in[2]];
            float xyz[3];
            for (int k = 0; k < 3; ++k)
                xyz[k] = (kRgbToXyz[k][0] * r + kRgbToXyz[k][1] * g + kRgbToXyz[k][2] * b) / kWhite[k];
            const float fx = t.cieF(xyz[0]), fy = t.cieF(xyz[1]), fz = t.cieF(xyz[2]);
            const float lightness = xyz[1] > kEpsilon ? 116.0f * fy - 16.0f : kKappa * xyz[1];
            out[0] = toByte(lightness * 255.0f / 100.0f);
            out[1] = toByte(500.0f * (fx - fy) + 128.0f);
            out[2] = toByte(200.0f * (fy - fz) + 128.0f);
        }
    }
}

LabColour labOf(const QColor &c)
{
    const cv::Mat rgb(1, 1, CV_8UC3, cv::Scalar(c.red(), c.green(), c.blue()));
    cv::Mat lab;
    rgbToLab8(rgb, lab);
    const cv::Vec3b v = lab.at<cv::Vec3b>(0, 0);
    return {v[0] * 100.0 / 255.0, v[1] - 128.0, v[2] - 128.0};
}

QColor colourOfLab(const LabColour &lab)
{
    // CIE Lab (D65) to XYZ to linear sRGB to sRGB.
    const double fy = (lab.l + 16.0) / 116.0, fx = fy + lab.a / 500.0, fz = fy - lab.b / 200.0;
    auto inverse
        = [](double f) { return f > 6.0 / 29.0 ? f * f * f : 3.0 * (6.0 / 29.0) * (6.0 / 29.0) * (f - 4.0 / 29.0); };
    const double x = 0.95047 * inverse(fx), y = inverse(fy), z = 1.08883 * inverse(fz);
    const double lin[3] = {3.2404542 * x - 1.5371385 * y - 0.4985314 * z,
        -0.9692660 * x + 1.8760108 * y + 0.0415560 * z, 0.0556434 * x - 0.2040259 * y + 1.0572252 * z};
    int rgb[3];
    for (int k = 0; k < 3; ++k) {
        const double v = std::clamp(lin[k], 0.0, 1.0);
        const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
        rgb[k] = int(std::lround(255.0 * s));
    }
    return QColor(rgb[0], rgb[1], rgb[2]);
}

} // namespace toonface
