#include "detect/appearanceevidence.h"

#include "detect/labcolour.h"
#include "face/fapu.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toonface {

namespace {

// L* units: the least a pixel must be darker than the cheeks' median to count as hair, whatever
// their spread (a JPEG's blocks and fine pores leave a few units on the smoothest skin).
constexpr double kMinDarker = 5.0;
// ... and in units of the cheeks' own robust spread (1.4826 MAD), so that a blotchy or a
// freckled skin does not count as hair.
constexpr double kSpreads = 2.5;

double medianOf(std::vector<double> v)
{
    if (v.empty())
        return 0;
    auto mid = v.begin() + qsizetype(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// The face's surroundings in L* (0..100, float) with the fine-detail map |L* - its 3x3 mean|.
class LabView
{
public:
    explicit LabView(const QImage &photo)
    {
        if (photo.isNull())
            return;
        const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
        const cv::Mat wrapped(
            rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
        cv::Mat lab;
        rgbToLab8(wrapped, lab);
        std::vector<cv::Mat> channels;
        cv::split(lab, channels);
        channels[0].convertTo(m_l, CV_32F, 100.0 / 255.0);
        channels[1].convertTo(m_a, CV_32F, 1.0, -128.0);
        channels[2].convertTo(m_b, CV_32F, 1.0, -128.0);
        cv::Mat mean;
        cv::blur(m_l, mean, cv::Size(3, 3), cv::Point(-1, -1), cv::BORDER_REPLICATE);
        cv::absdiff(m_l, mean, m_detail);
    }

    // The L*, a*, b* and detail values inside `box` (clipped).
    void values(QRectF box, std::vector<double> *l, std::vector<double> *detail, std::vector<double> *a = nullptr,
        std::vector<double> *b = nullptr) const
    {
        box = box.normalized();
        const int x0 = std::max(0, int(std::floor(box.left()))), x1 = std::min(m_l.cols - 1, int(box.right()));
        const int y0 = std::max(0, int(std::floor(box.top()))), y1 = std::min(m_l.rows - 1, int(box.bottom()));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                l->push_back(m_l.at<float>(y, x));
                if (detail)
                    detail->push_back(m_detail.at<float>(y, x));
                if (a)
                    a->push_back(m_a.at<float>(y, x));
                if (b)
                    b->push_back(m_b.at<float>(y, x));
            }
        }
    }

    // The median L* across `box` of each row (`alongY` true: a profile from top to bottom) or
    // of each column (left to right).
    std::vector<double> profile(QRectF box, bool alongY) const
    {
        box = box.normalized();
        std::vector<double> out;
        const int a0 = int(std::floor(alongY ? box.top() : box.left()));
        const int a1 = int(alongY ? box.bottom() : box.right());
        for (int a = a0; a <= a1; ++a) {
            std::vector<double> l;
            values(alongY ? QRectF(box.left(), a, box.width(), 0.5) : QRectF(a, box.top(), 0.5, box.height()), &l,
                nullptr);
            if (!l.empty())
                out.push_back(medianOf(l));
        }
        return out;
    }

private:
    cv::Mat m_l, m_a, m_b, m_detail;
};

// The strongest thin line across a profile: a point darker than both its neighbours `d` away
// (a dark rim), or lighter than both (a metal one catching the light), by how much, in L*, over
// the profile's median such response (so that wrinkles or grain all along it, lines everywhere,
// are no line). A step (a shadow's edge, the hair's edge) is darker than one neighbour only and
// does not count.
double lineStrength(const std::vector<double> &p, int d)
{
    std::vector<double> responses;
    for (int i = d; i + d < int(p.size()); ++i) {
        const double lo = std::min(p[size_t(i - d)], p[size_t(i + d)]);
        const double hi = std::max(p[size_t(i - d)], p[size_t(i + d)]);
        responses.push_back(std::max({0.0, lo - p[size_t(i)], p[size_t(i)] - hi}));
    }
    if (responses.empty())
        return 0;
    return *std::max_element(responses.begin(), responses.end()) - medianOf(responses);
}

QRectF spanBox(QPointF a, QPointF b)
{
    return QRectF(a, b).normalized();
}

} // namespace

AppearanceEvidence measureEvidence(const QImage &photo, const FaceModel &face)
{
    AppearanceEvidence out;
    const Fapu f = face.fapu();
    if (photo.isNull() || !face.isValid() || f.es0 <= 1)
        return out;
    // The face's surroundings scaled to kEvidenceEs0; points and sizes with it.
    const double scale = kEvidenceEs0 / f.es0;
    const QRect area = face.bounds().adjusted(-f.es0, -f.es0, f.es0, f.es0).toAlignedRect().intersected(photo.rect());
    if (area.isEmpty())
        return out;
    const QImage crop = photo.copy(area).scaled(std::max(1, int(std::lround(area.width() * scale))),
        std::max(1, int(std::lround(area.height() * scale))), Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    const LabView lab(crop);
    auto p = [&](const char *id) { return (face.point(id) - QPointF(area.topLeft())) * scale; };
    const double es0 = kEvidenceEs0, mw0 = f.mw0 * scale;

    // The cheeks under the eyes: the person's own skin, as lit, and its fine texture.
    std::vector<double> cheekL, cheekDetail, cheekA, cheekB;
    for (bool left : {true, false}) {
        const QPointF outer = p(left ? "3.12" : "3.7"), inner = p(left ? "3.8" : "3.11");
        const QPointF ball = p(left ? "3.6" : "3.5");
        lab.values(spanBox(QPointF(outer.x(), ball.y() + 0.45 * es0), QPointF(inner.x(), ball.y() + 0.65 * es0)),
            &cheekL, &cheekDetail, &cheekA, &cheekB);
    }
    if (cheekL.empty())
        return out;
    out.cheekL = medianOf(cheekL);
    const double cheekRed = medianOf(cheekA), cheekYellow = medianOf(cheekB);
    std::vector<double> deviation;
    for (double l : cheekL)
        deviation.push_back(std::abs(l - out.cheekL));
    const double spread = 1.4826 * medianOf(deviation);
    const double darker = std::max(kMinDarker, kSpreads * spread);
    double cheekTexture = 0;
    for (double d : cheekDetail)
        cheekTexture += d;
    cheekTexture = cheekTexture / double(cheekDetail.size()) + 0.5; // + a floor for perfectly smooth skin

    struct Place
    {
        double share = 0, detail = 0, dl = 0, redLoss = 0, colour = 0;
    };
    auto hairIn = [&](const QRectF &box) {
        Place place;
        std::vector<double> l, d, a, b;
        lab.values(box, &l, &d, &a, &b);
        if (l.empty())
            return place;
        const auto dark = std::count_if(l.begin(), l.end(), [&](double v) { return v < out.cheekL - darker; });
        double sum = 0;
        for (double v : d)
            sum += v;
        place.detail = sum / double(d.size()) / cheekTexture;
        place.share = double(dark) / double(l.size());
        place.dl = medianOf(l) - out.cheekL;
        place.redLoss = cheekRed - medianOf(a);
        place.colour = std::hypot(place.dl, place.redLoss, cheekYellow - medianOf(b));
        return place;
    };
    // Upper lip: between the nose's bottom and the lip, the lip's middle half wide.
    const double noseBottom = std::max({p("9.15").y(), p("9.4").y(), p("9.5").y()});
    const double lipTop = std::min({p("8.9").y(), p("8.1").y(), p("8.10").y()});
    const double gap = lipTop - noseBottom;
    if (gap > 2) {
        const double xl = p("8.4").x() + 0.2 * mw0, xr = p("8.3").x() - 0.2 * mw0;
        const Place lip = hairIn(spanBox(QPointF(xl, noseBottom + 0.35 * gap), QPointF(xr, lipTop - 0.1 * gap)));
        out.lipHair = lip.share;
        out.lipDetail = lip.detail;
        out.lipDL = lip.dl;
        out.lipRedLoss = lip.redLoss;
        out.lipColour = lip.colour;
    }
    // Chin: below the lower lip's shadow, above the chin's point.
    const double jawH = p("2.1").y() - p("8.2").y();
    if (jawH > 2) {
        const QPointF c(p("2.1").x(), p("8.2").y() + 0.6 * jawH);
        const Place chin = hairIn(QRectF(c.x() - 0.2 * mw0, c.y() - 0.2 * jawH, 0.4 * mw0, 0.4 * jawH));
        out.chinHair = chin.share;
        out.chinDetail = chin.detail;
        out.chinDL = chin.dl;
        out.chinRedLoss = chin.redLoss;
        // The jaw's sides, inside the contour, at the mouth's height: the weaker side.
        const QPointF mid = (p("5.2") + p("5.1")) / 2.0;
        Place sides[2];
        int k = 0;
        for (const char *side : {"2.12", "2.11"}) {
            const QPointF s = p(side) + (mid - p(side)) * 0.25;
            sides[k++] = hairIn(QRectF(s.x() - 0.06 * es0, s.y() - 0.06 * es0, 0.12 * es0, 0.12 * es0));
        }
        out.jawHair = std::min(sides[0].share, sides[1].share);
        out.jawDetail = std::min(sides[0].detail, sides[1].detail);
        out.jawDL = std::max(sides[0].dl, sides[1].dl);
        out.jawRedLoss = std::min(sides[0].redLoss, sides[1].redLoss);
        // The forehead between the brows, above the eyes' line; where the photo holds none of it
        // the cheeks alone are the reference.
        const double eyesY = (p("3.6").y() + p("3.5").y()) / 2.0;
        const double eyesX = (p("3.8").x() + p("3.11").x()) / 2.0;
        std::vector<double> foreheadL, foreheadA;
        lab.values(
            spanBox(QPointF(eyesX - 0.2 * es0, eyesY - 0.75 * es0), QPointF(eyesX + 0.2 * es0, eyesY - 0.45 * es0)),
            &foreheadL, nullptr, &foreheadA);
        const double flush = foreheadA.empty() ? 0.0 : std::max(0.0, cheekRed - medianOf(foreheadA));
        out.lowerRedLoss = (out.chinRedLoss + out.jawRedLoss) / 2.0 - flush;
    }

    // Glasses: a frame's thin lines, where skin runs smooth: over the nose's middle between the
    // eyes (the bridge), beside the eyes' outer corners (the side rims), under the lower lids.
    const int d = std::max(1, int(std::lround(0.04 * es0)));
    const QPointF in1 = p("3.8"), in2 = p("3.11");
    const double eyeY = (p("3.6").y() + p("3.5").y()) / 2.0;
    const double midX = (in1.x() + in2.x()) / 2.0, half = 0.2 * std::abs(in2.x() - in1.x());
    out.bridgeLine = lineStrength(
        lab.profile(QRectF(QPointF(midX - half, eyeY - 0.4 * es0), QPointF(midX + half, eyeY + 0.1 * es0)), true), d);
    double side = 1e9, lower = 1e9;
    for (bool left : {true, false}) {
        const QPointF outer = p(left ? "3.12" : "3.7"), inner = p(left ? "3.8" : "3.11");
        const QPointF ball = p(left ? "3.6" : "3.5");
        const double out = outer.x() < inner.x() ? -1.0 : 1.0;
        side = std::min(side,
            lineStrength(lab.profile(spanBox(QPointF(outer.x() + out * 0.04 * es0, ball.y() - 0.12 * es0),
                                         QPointF(outer.x() + out * 0.4 * es0, ball.y() + 0.12 * es0)),
                             false),
                d));
        lower = std::min(lower,
            lineStrength(
                lab.profile(
                    spanBox(QPointF(outer.x(), ball.y() + 0.2 * es0), QPointF(inner.x(), ball.y() + 0.6 * es0)), true),
                d));
    }
    out.sideRims = side < 1e9 ? side : 0;
    out.lowerRims = lower < 1e9 ? lower : 0;
    return out;
}

} // namespace toonface
