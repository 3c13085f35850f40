#include "detect/labcolour.h"
#include "testmain.h"

#include <QTest>

#include <opencv2/imgproc.hpp>

#include <cmath>

using namespace toonface;

namespace {

// Every 8-bit sRGB colour with each channel a multiple of `step` (and 255), one per pixel.
cv::Mat colourCube(int step)
{
    std::vector<int> levels;
    for (int v = 0; v < 256; v += step)
        levels.push_back(v);
    if (levels.back() != 255)
        levels.push_back(255);
    const int n = int(levels.size());
    cv::Mat rgb(n * n, n, CV_8UC3);
    for (int r = 0; r < n; ++r)
        for (int g = 0; g < n; ++g)
            for (int b = 0; b < n; ++b) {
                uchar *p = rgb.ptr<uchar>(r * n + g) + 3 * b;
                p[0] = uchar(levels[r]);
                p[1] = uchar(levels[g]);
                p[2] = uchar(levels[b]);
            }
    return rgb;
}

// CIE Lab of one sRGB colour by the textbook formulas in double precision, in 8-bit Lab's
// encoding but not rounded.
std::array<double, 3> referenceLab(const uchar *rgb)
{
    double lin[3];
    for (int k = 0; k < 3; ++k) {
        const double c = rgb[k] / 255.0;
        lin[k] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    const double x = (0.412453 * lin[0] + 0.357580 * lin[1] + 0.180423 * lin[2]) / 0.950456;
    const double y = 0.212671 * lin[0] + 0.715160 * lin[1] + 0.072169 * lin[2];
    const double z = (0.019334 * lin[0] + 0.119193 * lin[1] + 0.950227 * lin[2]) / 1.088754;
    auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
    const double l = y > 0.008856 ? 116.0 * std::cbrt(y) - 16.0 : 903.3 * y;
    return {l * 255.0 / 100.0, 500.0 * (f(x) - f(y)) + 128.0, 200.0 * (f(y) - f(z)) + 128.0};
}

} // namespace

class TestLabColour : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The conversion is the CIE's: each value is the exact one rounded (a hair off where the
    // exact one lies within a rounding's width of a half).
    void matchesTheCieFormulas()
    {
        const cv::Mat rgb = colourCube(5);
        cv::Mat lab;
        rgbToLab8(rgb, lab);
        QCOMPARE(lab.type(), CV_8UC3);
        QCOMPARE(lab.size(), rgb.size());
        for (int y = 0; y < rgb.rows; ++y)
            for (int x = 0; x < rgb.cols; ++x) {
                const uchar *in = rgb.ptr<uchar>(y) + 3 * x;
                const uchar *out = lab.ptr<uchar>(y) + 3 * x;
                const auto want = referenceLab(in);
                for (int k = 0; k < 3; ++k) {
                    const double expected = std::clamp(want[k], 0.0, 255.0);
                    if (std::abs(out[k] - expected) > 0.5 + 1e-3)
                        QFAIL(qPrintable(QStringLiteral("rgb (%1, %2, %3) channel %4: %5, not %6")
                                             .arg(in[0])
                                             .arg(in[1])
                                             .arg(in[2])
                                             .arg(k)
                                             .arg(out[k])
                                             .arg(expected)));
                }
            }
    }

    // What the hair search's colour models were made with: OpenCV's 8-bit Lab, which
    // interpolates in a table of its own, so that a value may differ from the exact one.
    void agreesWithOpenCv()
    {
        const cv::Mat rgb = colourCube(3);
        cv::Mat ours, theirs;
        rgbToLab8(rgb, ours);
        cv::cvtColor(rgb, theirs, cv::COLOR_RGB2Lab);
        long same = 0, total = 0, withinOne = 0;
        int worst = 0;
        for (int y = 0; y < rgb.rows; ++y) {
            const uchar *a = ours.ptr<uchar>(y);
            const uchar *b = theirs.ptr<uchar>(y);
            for (int i = 0; i < 3 * rgb.cols; ++i, ++total) {
                const int d = std::abs(int(a[i]) - int(b[i]));
                same += d == 0;
                withinOne += d <= 1;
                worst = std::max(worst, d);
            }
        }
        QVERIFY2(double(same) / total > 0.85, qPrintable(QString::number(double(same) / total)));
        QVERIFY2(double(withinOne) / total > 0.999, qPrintable(QString::number(double(withinOne) / total)));
        QVERIFY2(worst <= 3, qPrintable(QString::number(worst)));
    }

    void greysHaveNoColour()
    {
        cv::Mat grey(1, 256, CV_8UC3);
        for (int v = 0; v < 256; ++v)
            grey.at<cv::Vec3b>(0, v) = cv::Vec3b(uchar(v), uchar(v), uchar(v));
        cv::Mat lab;
        rgbToLab8(grey, lab);
        QCOMPARE(int(lab.at<cv::Vec3b>(0, 0)[0]), 0);
        QCOMPARE(int(lab.at<cv::Vec3b>(0, 255)[0]), 255);
        for (int v = 0; v < 256; ++v) {
            const cv::Vec3b p = lab.at<cv::Vec3b>(0, v);
            QVERIFY(std::abs(int(p[1]) - 128) <= 1);
            QVERIFY(std::abs(int(p[2]) - 128) <= 1);
            if (v > 0)
                QVERIFY(p[0] >= lab.at<cv::Vec3b>(0, v - 1)[0]);
        }
    }

    // A view into a larger image (rows with padding) is read row by row.
    void readsViewsWithPadding()
    {
        const cv::Mat whole = colourCube(17);
        const cv::Mat view = whole(cv::Rect(2, 3, whole.cols - 4, whole.rows - 6));
        QVERIFY(!view.isContinuous());
        cv::Mat fromView, fromCopy;
        rgbToLab8(view, fromView);
        rgbToLab8(view.clone(), fromCopy);
        QCOMPARE(cv::norm(fromView, fromCopy, cv::NORM_INF), 0.0);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestLabColour)
#include "tst_labcolour.moc"
