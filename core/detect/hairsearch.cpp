#include "detect/hairsearch.h"

#include "detect/labcolour.h"
#include "detect/landmarkmap.h"

#include <QLineF>
#include <QPainter>
#include <QRectF>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

// How the photo refines the estimated points (thesis 4.3.2, with colour models learnt from
// the photo in place of the thesis' binary face and hair regions):
//
// 1. The head's surroundings are cut out and scaled so that the eyeball centres are at most
//    kEyeDistance pixels apart: every length below is a fixed multiple of the face's size,
//    and the cost does not grow with the photo's resolution.
// 2. Skin: a smoothed Lab histogram of the cheeks and the nose between the eyes and the
//    mouth. A colour is "skin-like" when the model gives it at least the density of the
//    weakest tenth of those samples.
// 3. Forehead: up the face's midline from the brows, the hairline is where the skin-like
//    pixels end (a sustained run of others); 11.1 moves there and the temples follow in
//    proportion. Bangs end it early, a bald head late.
// 4. Hair: sampled just above that forehead line, in a band over the upper head, leaving out
//    skin-like pixels. Background: the cut-out outside the geometric hair ellipse enlarged by
//    a third, above the mouth (below it lie neck and clothes).
// 5. Each pixel's posterior of background (against skin and hair), with a prior for the
//    background that grows with the distance from the head (odds exp(5 (rho - 1)), rho the
//    elliptical radius of the geometric hair ellipse): colours decide where they differ, the
//    geometric estimate where they do not (hair the colour of the background).
// 6. Hair outline: from the ellipse's centre a ray through each geometric hair point; walking
//    outward from inside the head, the outline is where the background begins for good. A ray
//    that leaves the photo still inside the head ends at the border. The radii (as ratios to
//    the geometric ones) are then smoothed: outliers against their neighbours and failed rays
//    take the neighbours' median; mirrored rays that disagree by more than 15% both take the
//    one nearer the estimate; ratios stay within [0.75, 1.6]. With fewer than 7 rays found,
//    the geometric outline stays.
// 7. Ears: in rows of the face frame at ear height, the skin-like protrusion beyond the
//    face contour; one of plausible width (0.12..0.45 eye distances) over a plausible height
//    (half to one and a half ear heights) is the ear, otherwise the ear keeps its estimate.

namespace toonface {

namespace {

constexpr double kEyeDistance = 40.0; // working scale: pixels between the eyeball centres

// A colour histogram over 8-bit Lab: 8 lightness bins, 16 bins for each of a and b over
// their common range [64, 192), smoothed over neighbouring bins so that a few hundred samples
// give a usable density.
class ColourModel
{
public:
    static constexpr int kL = 8, kA = 16, kB = 16;

    void add(const cv::Vec3b &lab)
    {
        ++m_bins[bin(lab)];
        ++m_count;
    }
    int count() const { return m_count; }

    // Normalises and smooths; after this density() answers.
    void finish()
    {
        std::array<double, kL * kA * kB> smooth {};
        for (int l = 0; l < kL; ++l)
            for (int a = 0; a < kA; ++a)
                for (int b = 0; b < kB; ++b) {
                    double sum = 0;
                    for (int dl = -1; dl <= 1; ++dl)
                        for (int da = -1; da <= 1; ++da)
                            for (int db = -1; db <= 1; ++db) {
                                const int L = l + dl, A = a + da, B = b + db;
                                if (L < 0 || L >= kL || A < 0 || A >= kA || B < 0 || B >= kB)
                                    continue;
                                const double w = (dl == 0 ? 2 : 1) * (da == 0 ? 2 : 1) * (db == 0 ? 2 : 1);
                                sum += w * m_bins[(L * kA + A) * kB + B];
                            }
                    smooth[(l * kA + a) * kB + b] = sum;
                }
        double total = 0;
        for (double v : smooth)
            total += v;
        // A small floor keeps unseen colours possible without letting them win.
        const double floor = 1e-3 / smooth.size();
        for (size_t i = 0; i < smooth.size(); ++i)
            m_density[i] = (total > 0 ? smooth[i] / total : 0) + floor;
    }

    double density(const cv::Vec3b &lab) const { return m_density[bin(lab)]; }

private:
    static int bin(const cv::Vec3b &lab)
    {
        const int l = std::min(kL - 1, lab[0] * kL / 256);
        const int a = std::clamp((lab[1] - 64) / 8, 0, kA - 1);
        const int b = std::clamp((lab[2] - 64) / 8, 0, kB - 1);
        return (l * kA + a) * kB + b;
    }

    std::array<double, kL * kA * kB> m_bins {};
    std::array<double, kL * kA * kB> m_density {};
    int m_count = 0;
};

// The working cut-out: image pixels of `source` scaled by `scale`, offset by `origin`.
struct Workspace
{
    QPointF origin; // image position of the cut-out's (0, 0)
    double scale = 1;
    cv::Mat lab; // CV_8UC3
    cv::Mat pBack; // CV_32F posterior of background, smoothed
    cv::Mat pSkin; // CV_32F posterior of skin, smoothed
    QRectF imageBox; // the whole photo in cut-out pixels

    cv::Point toWork(QPointF image) const
    {
        const QPointF w = (image - origin) * scale;
        return {int(std::lround(w.x())), int(std::lround(w.y()))};
    }
    QPointF toImage(QPointF work) const { return origin + work / scale; }
    bool inside(cv::Point p) const { return p.x >= 0 && p.y >= 0 && p.x < lab.cols && p.y < lab.rows; }
};

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// True when local point q lies inside the ellipse centred at c with semi-axes (ax, ay).
bool inEllipse(QPointF q, QPointF c, double ax, double ay)
{
    const double u = (q.x() - c.x()) / ax, v = (q.y() - c.y()) / ay;
    return u * u + v * v <= 1.0;
}

} // namespace

void refineFromPhoto(FaceModel *face, const QImage &image, HairSearchReport *report, bool withDebugImages)
{
    HairSearchReport localReport;
    HairSearchReport &rep = report ? *report : localReport;
    rep = {};
    if (image.isNull() || !face->isValid())
        return;

    const HeadGeometry f = headGeometry(*face);
    const double d = f.eyeDistance;
    if (d < 4)
        return; // too small a face to search anything
    auto L = [&](const char *id) { return f.toLocal(face->point(id)); };
    const double cheekLX = L("5.2").x(), cheekRX = L("5.1").x();
    const QPointF hairCentre = f.hairCentre;
    const double hairAx = f.hairAx, hairAy = f.hairAy;
    const double chinY = L("2.1").y();
    const double browY = f.browY, noseBaseY = f.noseBaseY, hairlineY = f.hairlineY;

    // 1. The cut-out: the hair ellipse enlarged by 80%, and down to the chin.
    QRectF box;
    for (double a = 0; a < 2 * std::numbers::pi; a += std::numbers::pi / 18) {
        const QPointF q(hairCentre.x() + 1.8 * hairAx * std::cos(a), hairCentre.y() + 1.8 * hairAy * std::sin(a));
        const QPointF img = f.toImage(QPointF(q.x(), std::min(q.y(), chinY)));
        box = box.isNull() ? QRectF(img, QSizeF(1, 1)) : box.united(QRectF(img, QSizeF(1, 1)));
    }
    const QRect crop = box.toAlignedRect().intersected(image.rect());
    if (crop.width() < 8 || crop.height() < 8)
        return;
    Workspace ws;
    ws.scale = std::min(1.0, kEyeDistance / d);
    ws.origin = crop.topLeft();
    {
        const QImage rgb = image.copy(crop).convertToFormat(QImage::Format_RGB888);
        const cv::Mat src(
            rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
        cv::Mat small;
        const cv::Size size(std::max(1, int(std::lround(rgb.width() * ws.scale))),
            std::max(1, int(std::lround(rgb.height() * ws.scale))));
        cv::resize(src, small, size, 0, 0, cv::INTER_AREA);
        rgbToLab8(small, ws.lab); // not cv::cvtColor: its Lab tables cost 0.15-0.2 s to make (labcolour.h)
    }
    ws.imageBox = QRectF((QPointF(0, 0) - ws.origin) * ws.scale, QSizeF(image.size()) * ws.scale);
    const double dw = d * ws.scale; // eye distance in cut-out pixels

    // 2. Colour models.
    ColourModel skin;
    auto sampleRegion = [&](ColourModel &model, QPointF a, QPointF b) {
        // local-frame rectangle with corners a, b, sampled on a grid of about 1.5 px
        const double step = 1.5 / ws.scale;
        for (double y = std::min(a.y(), b.y()); y <= std::max(a.y(), b.y()); y += step)
            for (double x = std::min(a.x(), b.x()); x <= std::max(a.x(), b.x()); x += step) {
                const cv::Point p = ws.toWork(f.toImage(QPointF(x, y)));
                if (ws.inside(p))
                    model.add(ws.lab.at<cv::Vec3b>(p));
            }
    };
    // Cheeks below the eyes, beside the nose, above the mouth; the nose's side between them.
    const double cheekTop = std::max(L("3.4").y(), L("3.3").y()) + 0.2 * d;
    const double cheekBottom = std::max(cheekTop + 0.1 * d, L("9.2").y());
    sampleRegion(skin, QPointF(L("3.12").x(), cheekTop), QPointF(L("3.8").x(), cheekBottom));
    sampleRegion(skin, QPointF(L("3.11").x(), cheekTop), QPointF(L("3.7").x(), cheekBottom));
    sampleRegion(skin, QPointF(L("9.14").x(), L("9.14").y()), QPointF(L("9.13").x(), L("9.2").y()));

    skin.finish();
    if (skin.count() < 30)
        return;
    const int run = std::max(3, int(std::lround(0.08 * dw))); // pixels of a sustained change

    // A colour is skin-like when the skin model gives it at least the density of the weakest
    // tenth of the skin samples themselves: a one-class test, needing no other model.
    std::vector<double> skinDensities;
    {
        const double step = 1.5 / ws.scale;
        for (double y = cheekTop; y <= cheekBottom; y += step)
            for (double x = L("3.12").x(); x <= L("3.7").x(); x += step) {
                const cv::Point p = ws.toWork(f.toImage(QPointF(x, y)));
                if (ws.inside(p))
                    skinDensities.push_back(skin.density(ws.lab.at<cv::Vec3b>(p)));
            }
    }
    std::nth_element(skinDensities.begin(), skinDensities.begin() + skinDensities.size() / 10, skinDensities.end());
    const double skinLevel = skinDensities.empty() ? 0.0 : skinDensities[skinDensities.size() / 10];
    cv::Mat skinLike(ws.lab.size(), CV_32F);
    for (int y = 0; y < ws.lab.rows; ++y)
        for (int x = 0; x < ws.lab.cols; ++x)
            skinLike.at<float>(y, x) = skin.density(ws.lab.at<cv::Vec3b>(y, x)) >= skinLevel ? 1.0f : 0.0f;
    const double sigma = std::max(0.8, dw / 40.0);
    cv::GaussianBlur(skinLike, skinLike, cv::Size(0, 0), sigma);

    // 3. Forehead: up the midline from between the brows while the skin lasts (short breaks,
    // wrinkles and highlights, are crossed). Bangs end it early, a bald head late.
    double hairline = hairlineY;
    {
        const double x = f.midX;
        int notSkin = 0;
        double top = 0;
        for (double y = browY - 0.2 * d; y >= browY - 2.5 * d; y -= 1.0 / ws.scale) {
            const cv::Point p = ws.toWork(f.toImage(QPointF(x, y)));
            if (!ws.inside(p))
                break;
            if (skinLike.at<float>(p) < 0.5f) {
                if (++notSkin >= run) {
                    top = y + (run - 1) / ws.scale;
                    break;
                }
            } else {
                notSkin = 0;
            }
        }
        if (top < browY - 0.2 * d) {
            hairline = top;
            const double oldY = L("11.1").y();
            const double k = std::abs(oldY) > 1e-9 ? top / oldY : 1.0;
            face->setPoint(pt::idx("11.1"), f.toImage(QPointF(L("11.1").x(), top)));
            for (const char *id : {"11.2", "11.3"}) {
                const QPointF q = L(id);
                face->setPoint(pt::idx(id), f.toImage(QPointF(q.x(), q.y() * k)));
            }
        }
    }

    // 4. Hair and background models. Hair: just above the forehead line, in a band over the
    // upper head (between 20 and 160 degrees) from the hairline outward by a third of the
    // eye distance, leaving out skin-like pixels. Background: outside the geometric hair
    // ellipse enlarged by a third, above the mouth.
    const double mouthY = (L("8.4").y() + L("8.3").y()) / 2;
    const double foreheadAx = std::max((cheekRX - cheekLX) / 2, 0.1 * d);
    const double foreheadAy = std::max(-hairline, 0.1 * d);
    const QPointF foreheadCentre(f.midX, 0);
    ColourModel back, hair;
    for (int y = 0; y < ws.lab.rows; y += 2)
        for (int x = 0; x < ws.lab.cols; x += 2) {
            const QPointF q = f.toLocal(ws.toImage(QPointF(x, y)));
            if (q.y() < mouthY && !inEllipse(q, hairCentre, 1.35 * hairAx, 1.3 * hairAy)) {
                back.add(ws.lab.at<cv::Vec3b>(y, x));
                continue;
            }
            const QPointF u = q - foreheadCentre;
            if (u.y() >= -std::sin(20.0 * std::numbers::pi / 180.0) * foreheadAy)
                continue;
            if (!inEllipse(q, foreheadCentre, foreheadAx, foreheadAy)
                && inEllipse(q, foreheadCentre, foreheadAx + 0.33 * d, foreheadAy + 0.33 * d)
                && skinLike.at<float>(y, x) < 0.5f)
                hair.add(ws.lab.at<cv::Vec3b>(y, x));
        }
    back.finish();
    hair.finish();
    const bool haveBackground = back.count() >= 50;
    const bool haveHair = hair.count() >= 30;

    // 5. Posteriors of background and skin, smoothed. Colours alone cannot part hair from a
    // background of the same colour, so the background's prior grows with the elliptical
    // radius rho of the geometric hair ellipse: odds exp(5 (rho - 1)) — even at the ellipse,
    // about 7 times background at half again its size. Where the colours are clear, they win;
    // where they are not, the outline stays near the estimate.
    ws.pBack = cv::Mat(ws.lab.size(), CV_32F);
    ws.pSkin = cv::Mat(ws.lab.size(), CV_32F);
    for (int y = 0; y < ws.lab.rows; ++y)
        for (int x = 0; x < ws.lab.cols; ++x) {
            const cv::Vec3b &c = ws.lab.at<cv::Vec3b>(y, x);
            const QPointF q = f.toLocal(ws.toImage(QPointF(x, y)));
            const double u = (q.x() - hairCentre.x()) / hairAx, v = (q.y() - hairCentre.y()) / hairAy;
            const double rho = std::sqrt(u * u + v * v);
            const double prior = std::exp(std::clamp(5.0 * (rho - 1.0), -20.0, 20.0));
            const double s = skin.density(c);
            const double b = haveBackground ? back.density(c) * prior : 0.0;
            const double h = haveHair ? hair.density(c) : 0.0;
            const double sum = s + b + h;
            ws.pBack.at<float>(y, x) = float(b / sum);
            ws.pSkin.at<float>(y, x) = float(s / sum);
        }
    cv::GaussianBlur(ws.pBack, ws.pBack, cv::Size(0, 0), sigma);
    cv::GaussianBlur(ws.pSkin, ws.pSkin, cv::Size(0, 0), sigma);

    // 6. Hair rays.
    int hairFound = 0;
    if (haveBackground) {
        const QPointF centreImg = f.toImage(hairCentre);
        std::array<double, 19> ratio {};
        std::array<bool, 19> ok {};
        std::array<double, 19> atLeast {}; // where the head goes on beyond the photo's edge
        for (int i = 0; i < 19; ++i) {
            const QPointF geo = f.toImage(f.hairPoint(i));
            const QPointF dir = geo - centreImg;
            const double rGeo = std::hypot(dir.x(), dir.y());
            if (rGeo < 1)
                continue;
            const double stepImg = 1.0 / ws.scale; // one cut-out pixel
            const double r0 = 0.6 * rGeo, r1 = 1.8 * rGeo;
            int inHead = 0, backRun = 0;
            double boundary = -1, last = r0;
            bool leftImage = false;
            for (double r = r0; r <= r1; r += stepImg) {
                const QPointF q = centreImg + dir * (r / rGeo);
                const cv::Point p = ws.toWork(q);
                if (!ws.inside(p) || !ws.imageBox.contains(QPointF(p.x, p.y))) {
                    leftImage = !QRectF(image.rect()).contains(q);
                    break;
                }
                last = r;
                if (ws.pBack.at<float>(p) > 0.5f) {
                    if (++backRun >= run && inHead >= run) {
                        boundary = r - (run - 1) * stepImg;
                        break;
                    }
                } else {
                    backRun = 0;
                    ++inHead;
                }
            }
            // The head goes on beyond the photo's edge: at least to there. How far is not seen,
            // so the ray is not found; it takes its found neighbours' size, as missing rays do
            // (the edge is where the photo stops, not the head: kept there, a cut-off head would
            // be drawn with a flat top).
            if (boundary < 0 && leftImage && inHead >= run)
                atLeast[i] = last / rGeo;
            rep.rays.emplace_back(
                centreImg + dir * (r0 / rGeo), centreImg + dir * ((boundary > 0 ? boundary : last) / rGeo));
            if (boundary > 0) {
                ratio[i] = boundary / rGeo;
                ok[i] = true;
            }
        }
        // Smoothing: each found ratio is compared with the median of its found neighbours
        // (two on each side); one that differs by more than a fifth is replaced. Missing
        // rays take that neighbourhood median, or the median of all found rays.
        std::vector<double> found;
        for (int i = 0; i < 19; ++i)
            if (ok[i])
                found.push_back(ratio[i]);
        if (found.size() >= 7) {
            const double overall = median(found);
            std::array<double, 19> smooth {};
            for (int i = 0; i < 19; ++i) {
                std::vector<double> nb;
                for (int k = std::max(0, i - 2); k <= std::min(18, i + 2); ++k)
                    if (ok[k])
                        nb.push_back(ratio[k]);
                const double m = nb.size() >= 2 ? median(nb) : overall;
                smooth[i] = ok[i] && std::abs(ratio[i] - m) <= 0.2 * m ? ratio[i] : m;
                if (ok[i] && smooth[i] == ratio[i])
                    ++hairFound;
            }
            // The head's outline is nearly symmetric in a frontal photo: where mirrored rays
            // disagree by more than 15%, one of them was fooled (background of the
            // head's colours outside, or hair of the background's inside), and the one nearer
            // the geometric estimate is believed for both.
            for (int i = 0; i < 9; ++i) {
                double &a = smooth[i], &b = smooth[18 - i];
                if (std::abs(a - b) > 0.15 * std::min(a, b)) {
                    const double keep = std::abs(a - 1.0) < std::abs(b - 1.0) ? a : b;
                    hairFound -= int(ok[i] && a != keep) + int(ok[18 - i] && b != keep);
                    a = b = keep;
                }
            }
            for (int i = 0; i < 19; ++i) {
                smooth[i] = std::max(smooth[i], atLeast[i]);
                const QPointF local = hairCentre + std::clamp(smooth[i], 0.75, 1.6) * (f.hairPoint(i) - hairCentre);
                face->setPoint(i, f.toImage(local));
            }
        }
    }
    rep.hairFraction = hairFound / 19.0;

    // 7. Ears: skin beyond the contour, row by row.
    int earsFound = 0;
    auto contourX = [&](double y, bool left) {
        const QPointF cheek = L(left ? "5.2" : "5.1"), jaw = L(left ? "2.14" : "2.13");
        if (y <= cheek.y())
            return cheek.x();
        const double t = (y - cheek.y()) / std::max(jaw.y() - cheek.y(), 1e-6);
        return cheek.x() + std::min(t, 1.0) * (jaw.x() - cheek.x());
    };
    for (const bool left : {true, false}) {
        const double side = left ? -1.0 : 1.0;
        const double earH = std::max(noseBaseY - browY, 0.1 * d);
        std::vector<double> ys, widths;
        for (double y = browY - 0.25 * earH; y <= noseBaseY + 0.25 * earH; y += 1.0 / ws.scale) {
            const double cx = contourX(y, left);
            // The skin must end within reach (a run of other pixels): skin-like colour that
            // goes on is background, not an ear. Such rows count as no ear (width 0).
            double w = 0;
            int gap = 0;
            bool ended = false;
            for (double t = -0.05 * d; t <= 0.5 * d + run / ws.scale; t += 1.0 / ws.scale) {
                const cv::Point p = ws.toWork(f.toImage(QPointF(cx + side * t, y)));
                if (!ws.inside(p))
                    break;
                if (skinLike.at<float>(p) >= 0.5f) {
                    w = t;
                    gap = 0;
                } else if (++gap >= run) {
                    ended = true;
                    break;
                }
            }
            if (!ended)
                w = 0;
            ys.push_back(y);
            widths.push_back(w);
        }
        // The longest run of rows with an ear-like protrusion: wider than 0.12 d, narrower than
        // 0.45 d (beyond that the "skin" is background of skin colour).
        auto at = [&](double y, double out) { return f.toImage(QPointF(contourX(y, left) + side * out, y)); };
        if (!placeEarFromProfile(
                face, left, ys, widths, 1.0 / ws.scale, {0.12 * d, 0.45 * d, 0.5 * earH, 1.5 * earH}, at))
            continue;
        ++earsFound;
    }
    rep.earFraction = earsFound / 2.0;

    // Ears stay in the photo (an ear beyond it is not seen); the hair outline and hairline go on
    // beyond an edge that cuts the head off, like the estimates.
    keepInPhoto(face, image.size(), [](int i) { return pointTable()[i].group == PointGroup::Ears; });

    if (withDebugImages) {
        QImage mask(ws.lab.cols, ws.lab.rows, QImage::Format_RGB32);
        for (int y = 0; y < ws.lab.rows; ++y)
            for (int x = 0; x < ws.lab.cols; ++x) {
                const double b = ws.pBack.at<float>(y, x), s = ws.pSkin.at<float>(y, x);
                const double h = std::max(0.0, 1.0 - b - s);
                mask.setPixel(x, y, qRgb(int(255 * s), int(255 * h), int(255 * b)));
            }
        // Placed on a photo-sized transparent canvas so it overlays the photo.
        QImage canvas(image.size(), QImage::Format_ARGB32_Premultiplied);
        canvas.fill(Qt::transparent);
        QPainter p(&canvas);
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(QRectF(ws.origin, QSizeF(mask.width(), mask.height()) / ws.scale), mask);
        p.end();
        rep.regionMask = canvas;
    }
}

} // namespace toonface
