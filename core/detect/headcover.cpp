#include "detect/headcover.h"

#include "detect/labcolour.h"
#include "detect/photopixels.h"

#include <QLineF>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace toonface {

namespace {

// What lies over the forehead: the person's pixels other than skin kCoverHalf d either side of
// the midline, from kCoverLow to kCoverHigh d above the brows' top, at least kMinCover d² of them.
constexpr double kCoverHalf = 0.6, kCoverLow = 0.25, kCoverHigh = 2.0;
constexpr double kMinCover = 0.03;
// Hair grows in hues (the a*b* plane's angle) from kHairHue[0] to kHairHue[1] degrees: blacks,
// browns, blondes and reds (a red scarf is far more saturated: chroma tells those apart), about
// a skin of hue kSkinHue; a colour cast turns both, so the range turns with the cheeks' hue. Below
// kGreyChroma a colour shows no hue (black, grey, white).
constexpr double kHairHue[2] = {20.0, 100.0};
constexpr double kSkinHue = 55.0;
constexpr double kGreyChroma = 8.0;
// The brows: the person's pixels other than skin within kBrowReach d of their points' line.
constexpr double kBrowReach = 0.1;
// Beside the cheeks: bands from kSideGap to kSideGap + kSideWidth d out from the cheeks' lines;
// a pixel within kSameColour L*a*b* units of the covering's colour is of it.
constexpr double kSideGap = 0.05, kSideWidth = 0.4, kSameColour = 18.0;

struct Lab
{
    double l = 0, a = 0, b = 0;
};

double distance(const Lab &p, const Lab &q)
{
    return std::hypot(p.l - q.l, p.a - q.a, p.b - q.b);
}

double medianOf(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

class LabFrame
{
public:
    explicit LabFrame(const QImage &work)
    {
        const QImage rgb = work.convertToFormat(QImage::Format_RGB888);
        const cv::Mat src(
            rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
        rgbToLab8(src, m_lab);
    }
    Lab at(int x, int y) const
    {
        const cv::Vec3b v = m_lab.at<cv::Vec3b>(y, x);
        return {v[0] * 100.0 / 255.0, v[1] - 128.0, v[2] - 128.0};
    }

private:
    cv::Mat m_lab;
};

struct Sample
{
    std::array<std::vector<double>, 3> channels;
    void add(const Lab &c)
    {
        channels[0].push_back(c.l);
        channels[1].push_back(c.a);
        channels[2].push_back(c.b);
    }
    size_t size() const { return channels[0].size(); }
    Lab median() const { return {medianOf(channels[0]), medianOf(channels[1]), medianOf(channels[2])}; }
};

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}

} // namespace

HeadCover measureCover(const HeadParse &parse)
{
    HeadCover out;
    if (!parse.valid || parse.work.isNull() || parse.foreheadTop.size() < 3)
        return out;
    const double d = kParseEyeDistance;
    const LabFrame lab(parse.work);
    const int w = parse.size.width(), h = parse.size.height();

    // Over the forehead, from above the brows up to the head's top or the photo's edge (in a
    // tight crop only a sliver of hair or a cap's band shows there).
    Sample cover;
    const double mid = w / 2.0;
    for (int y = std::max(0, int(parse.browTop - kCoverHigh * d)); y <= int(parse.browTop - kCoverLow * d); ++y)
        for (int x = int(mid - kCoverHalf * d); x <= int(mid + kCoverHalf * d); ++x)
            if (x >= 0 && x < w && y < h && parse.at(x, y) == HeadParse::Other)
                cover.add(lab.at(x, y));
    if (double(cover.size()) < kMinCover * d * d)
        return out;
    const Lab c = cover.median();
    out.seen = true;
    out.l = c.l;
    out.a = c.a;
    out.b = c.b;
    out.chroma = std::hypot(c.a, c.b);
    {
        cv::Mat one(1, 1, CV_8UC3,
            cv::Scalar(std::clamp(c.l * 255.0 / 100.0, 0.0, 255.0), std::clamp(c.a + 128.0, 0.0, 255.0),
                std::clamp(c.b + 128.0, 0.0, 255.0)));
        cv::Mat rgb;
        cv::cvtColor(one, rgb, cv::COLOR_Lab2RGB);
        const cv::Vec3b v = rgb.at<cv::Vec3b>(0, 0);
        out.colour = QColor(v[0], v[1], v[2]);
    }
    const LabColour cheeks = labOf(parse.cheeks);
    const Lab skin {cheeks.l, cheeks.a, cheeks.b};
    if (out.chroma >= kGreyChroma) {
        const double cast = std::hypot(skin.a, skin.b) >= kGreyChroma
            ? std::remainder(std::atan2(skin.b, skin.a) * 180.0 / std::numbers::pi - kSkinHue, 360.0)
            : 0.0;
        const double hue = std::remainder(std::atan2(c.b, c.a) * 180.0 / std::numbers::pi - cast, 360.0);
        auto off = [](double from, double to) { return std::abs(std::remainder(to - from, 360.0)); };
        out.hueOff
            = hue >= kHairHue[0] && hue <= kHairHue[1] ? 0.0 : std::min(off(hue, kHairHue[0]), off(hue, kHairHue[1]));
    }
    out.toSkin = distance(c, skin);

    Sample brows;
    if (!parse.brows.empty()) {
        double x0 = parse.brows.front().x(), x1 = x0, y0 = parse.brows.front().y(), y1 = y0;
        for (const QPointF &p : parse.brows) {
            x0 = std::min(x0, p.x());
            x1 = std::max(x1, p.x());
            y0 = std::min(y0, p.y());
            y1 = std::max(y1, p.y());
        }
        for (int y = std::max(0, int(y0 - kBrowReach * d)); y <= std::min(h - 1, int(y1 + kBrowReach * d)); ++y)
            for (int x = std::max(0, int(x0)); x <= std::min(w - 1, int(x1)); ++x) {
                if (parse.at(x, y) != HeadParse::Other)
                    continue;
                double nearest = 1e9;
                for (size_t i = 0; i + 1 < parse.brows.size(); ++i)
                    nearest = std::min(nearest, distanceToSegment(QPointF(x, y), parse.brows[i], parse.brows[i + 1]));
                if (nearest <= kBrowReach * d)
                    brows.add(lab.at(x, y));
            }
    }
    const Lab brow = brows.size() > 0 ? brows.median() : skin;
    out.toBrows = distance(c, brow);
    out.lighter = c.l - brow.l;

    // The forehead's top edge: its height over the brows, and how straight it runs.
    std::vector<double> heights;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const QPoint &top : parse.foreheadTop) {
        heights.push_back((parse.browTop - top.y()) / d);
        sx += top.x();
        sy += top.y();
        sxx += double(top.x()) * top.x();
        sxy += double(top.x()) * top.y();
    }
    const double n = double(parse.foreheadTop.size());
    out.edgeHeight = medianOf(heights);
    const double slope = (n * sxy - sx * sy) / std::max(1e-9, n * sxx - sx * sx), at0 = (sy - slope * sx) / n;
    std::vector<double> off;
    for (const QPoint &top : parse.foreheadTop)
        off.push_back(std::abs(top.y() - (at0 + slope * top.x())) / d);
    out.edgeSpread = percentile(off, 0.8);

    // Beside the cheeks, from eye level to the jaw: the share of the bands in the covering's colour.
    int seen = 0, same = 0;
    for (int side = 0; side < 2; ++side) {
        const QPointF a = parse.sideCheeks[side][0], b = parse.sideCheeks[side][1];
        const double outward = side == 0 ? -1.0 : 1.0;
        for (int y = std::max(0, int(a.y())); y <= std::min(h - 1, int(b.y())); ++y) {
            const double t = std::clamp((y - a.y()) / std::max(1.0, b.y() - a.y()), 0.0, 1.0);
            const double edge = a.x() + (b.x() - a.x()) * t + outward * kSideGap * d;
            for (int k = 0; k < int(kSideWidth * d); ++k) {
                const int x = int(std::lround(edge + outward * k));
                if (x < 0 || x >= w || parse.at(x, y) == HeadParse::Outside)
                    continue;
                ++seen;
                same += parse.at(x, y) == HeadParse::Other && distance(lab.at(x, y), c) < kSameColour;
            }
        }
    }
    out.sides = seen > 0 ? double(same) / seen : 0.0;
    return out;
}

bool isHeadwear(const HeadCover &cover)
{
    return cover.seen
        && ((cover.colour.valueF() >= kCoverDarkest && cover.hueOff * cover.chroma / 100.0 >= kCoverColourScore)
            || (cover.l >= kCoverWhiteL && cover.lighter >= kCoverWhiteOverBrows));
}

} // namespace toonface
