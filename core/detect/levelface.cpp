#include "detect/levelface.h"

#include "detect/labcolour.h"
#include "face/facemodel.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toonface {

namespace {

const cv::Size kLevelSize(200, 260);

} // namespace

QPointF LevelFace::map(QPointF p) const
{
    const double *a = affine.ptr<double>(0), *b = affine.ptr<double>(1);
    const double x = p.x() * prescale, y = p.y() * prescale;
    return {(a[0] * x + a[1] * y + a[2] - kLevelCentre) / kLevelEs0,
        (b[0] * x + b[1] * y + b[2] - kLevelCentre) / kLevelEs0};
}

std::vector<float> LevelFace::box(const cv::Mat &of, double cx, double cy, double hw, double hh) const
{
    const int x0 = std::max(0, int(kLevelCentre + (cx - hw) * kLevelEs0));
    const int x1 = std::min(of.cols, int(kLevelCentre + (cx + hw) * kLevelEs0));
    const int y0 = std::max(0, int(kLevelCentre + (cy - hh) * kLevelEs0));
    const int y1 = std::min(of.rows, int(kLevelCentre + (cy + hh) * kLevelEs0));
    std::vector<float> out;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            if (valid.at<uchar>(y, x))
                out.push_back(of.at<float>(y, x));
    return out;
}

LevelFace levelFace(const QImage &photo, const FaceModel &face)
{
    LevelFace f;
    const QPointF le = face.point("3.6"), re = face.point("3.5");
    const double es = std::hypot(re.x() - le.x(), re.y() - le.y());
    if (photo.isNull() || es < 4.0)
        return f;
    const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
    cv::Mat source(
        rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
    // A large photo is shrunk by averaging first: sampled straight down, fine texture would alias.
    double scale = kLevelEs0 / es;
    if (scale < 1.0) {
        cv::Mat smaller;
        cv::resize(source, smaller, cv::Size(), scale, scale, cv::INTER_AREA);
        source = smaller;
        f.prescale = scale;
        scale = 1.0;
    }
    const QPointF c = (le + re) / 2.0 * f.prescale;
    const double angle = std::atan2(re.y() - le.y(), re.x() - le.x()) * 180.0 / std::numbers::pi;
    f.affine = cv::getRotationMatrix2D(cv::Point2f(float(c.x()), float(c.y())), angle, scale);
    f.affine.at<double>(0, 2) += kLevelCentre - c.x();
    f.affine.at<double>(1, 2) += kLevelCentre - c.y();
    cv::Mat level, lab;
    cv::warpAffine(source, level, f.affine, kLevelSize, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    cv::warpAffine(cv::Mat(source.size(), CV_8U, cv::Scalar(255)), f.valid, f.affine, kLevelSize, cv::INTER_NEAREST,
        cv::BORDER_CONSTANT);
    rgbToLab8(level, lab);
    cv::Mat channels[3];
    cv::split(lab, channels);
    channels[0].convertTo(f.l, CV_32F, 100.0 / 255.0);
    cv::Mat mean, gx, gy;
    cv::blur(f.l, mean, cv::Size(3, 3), cv::Point(-1, -1), cv::BORDER_REPLICATE);
    cv::absdiff(f.l, mean, f.detail);
    cv::Sobel(f.l, gx, CV_32F, 1, 0);
    cv::Sobel(f.l, gy, CV_32F, 0, 1);
    cv::magnitude(gx, gy, f.gradient);
    return f;
}

} // namespace toonface
