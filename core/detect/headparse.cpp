#include "detect/headparse.h"

#include "detect/labcolour.h"
#include "detect/skintone.h"
#include "face/pointtable.h"

#include <QLineF>
#include <QPolygonF>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace toonface {

namespace {

// The work frame, in eye distances d: 3.5 d either side of the eyes' midpoint, from 3.5 d above
// it to 5 d below (the shoulders of a portrait).
constexpr double kHalfWidth = 3.5, kAbove = 3.5, kBelow = 5.0;
// The seeds. Probably the person: an ellipse over the head (its centre kHeadLift d above the
// eyes; half-axes kHeadRx, kHeadRy), and a column kNeckHalf d either side of the midline from
// kNeckTop d below the eyes. Surely not: pixels farther than kFar d from the eyes' midpoint,
// above kFarBelow d under the eyes (lower, clothes may run to the photo's edge).
constexpr double kHeadLift = 0.3, kHeadRx = 1.7, kHeadRy = 2.2;
constexpr double kNeckHalf = 0.8, kNeckTop = 1.0;
// ... and where long hair falls: kCurtainHalf d either side of the midline, from the eyes down to
// kCurtainBottom d below them.
constexpr double kCurtainHalf = 1.8, kCurtainBottom = 3.0;
constexpr double kFar = 3.3, kFarBelow = 1.0;
constexpr int kGrabCutRounds = 2;
constexpr double kMinRoom = 0.5; // d²: less of the room in the photo is not modelled (a tight crop)
// Skin: a pixel whose hue (in the a*b* plane), chroma and L* stay near the cheeks' — light and
// shade change a skin's L* and chroma together and leave its hue (a shine takes both toward white).
// Within kSkinHue degrees of the cheeks' hue, chroma and L* within a factor kSkinRatio of theirs
// (each tolerance widened to kSpreadTimes the cheeks' own spread when that is larger); where the
// skin has too little chroma for a hue (kGreyChroma), a greyscale photo, L* alone decides.
constexpr double kSkinHue = 12.0;
constexpr double kSkinRatio = 1.6;
constexpr double kSpreadTimes = 2.5;
constexpr double kGreyChroma = 4.0;
// The hair's fall: its colour sampled over the forehead (see measureHairFall), at least
// kMinHairSample d² of it; the band beside the face starts kSideGap d out from the cheek's line.
constexpr double kHairSampleLow = 0.3, kHairSampleHigh = 1.3, kHairSampleHalf = 0.7, kMinHairSample = 0.1;
constexpr double kSideGap = 0.05, kSideBand = 0.6, kHairWidth = 0.1, kFallGap = 0.25;
constexpr double kHairColourDistance = 18.0; // L*a*b* units
constexpr double kTempleNear = 0.75, kTempleFar = 1.5, kTempleHigh = 1.0;
constexpr double kBaldSideFar = 1.3, kBaldSideHigh = 0.6;
// The outline follows the fall (followHairFall) where it ends at least kMinFallGain ES0 lower
// than the outline's end: the end and the kFallPoints points above it move onto the line from
// there down to the fall's end.
constexpr double kMinFallGain = 0.25;
constexpr int kFallPoints = 4;
// The forehead's sample: kForeheadHalf d either side of the midline, from kForeheadLow to
// kForeheadHigh d above the brows' top.
constexpr double kForeheadHalf = 0.45, kForeheadLow = 0.08, kForeheadHigh = 0.3;
// The walk up the forehead: columns kWalkHalf d either side of the midline, from kWalkStart d
// above the brows' top; a run of skin (or of the person) goes on across gaps up to kWalkGap d (a
// wrinkle, a shine, a strand of hair).
constexpr double kWalkHalf = 0.5, kWalkStart = 0.1, kWalkGap = 0.12;
// ... where the skin is no darker than the forehead's L* over kScalpDarker.
constexpr double kScalpDarker = 1.3;

struct Lab
{
    double l, a, b;
};

Lab labAt(const cv::Mat &lab8, int x, int y)
{
    const cv::Vec3b v = lab8.at<cv::Vec3b>(y, x);
    return {v[0] * 100.0 / 255.0, v[1] - 128.0, v[2] - 128.0};
}

double hueOf(const Lab &c)
{
    return std::atan2(c.b, c.a) * 180.0 / std::numbers::pi;
}

double chromaOf(const Lab &c)
{
    return std::hypot(c.a, c.b);
}

// The skin model: the cheeks' median hue, chroma and L*, and how far each may stray.
struct SkinModel
{
    double hue = 0, chroma = 0, l = 0;
    double hueTolerance = kSkinHue, chromaRatio = kSkinRatio, lRatio = kSkinRatio;
    bool valid = false;

    Lab centre() const
    {
        const double h = hue * std::numbers::pi / 180.0;
        return {l, chroma * std::cos(h), chroma * std::sin(h)};
    }

    bool isSkin(const Lab &c) const
    {
        auto within = [](double v, double ref, double ratio) { return v >= ref / ratio && v <= ref * ratio; };
        if (!within(std::max(c.l, 1.0), l, lRatio))
            return false;
        if (chroma < kGreyChroma)
            return chromaOf(c) < kGreyChroma * chromaRatio;
        const double dh = std::abs(std::remainder(hueOf(c) - hue, 360.0));
        return dh <= hueTolerance && within(std::max(chromaOf(c), 0.1), chroma, chromaRatio);
    }
};

double medianOf(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// Half the spread between the 10th and 90th percentiles.
double spreadOf(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return 0.5 * (v[v.size() * 9 / 10] - v[v.size() / 10]);
}

SkinModel cheekModel(const cv::Mat &lab8, const cv::Mat &inside, const std::vector<QRect> &cheeks)
{
    std::vector<double> hues, chromas, ls;
    for (const QRect &r : cheeks)
        for (int y = std::max(0, r.top()); y <= std::min(lab8.rows - 1, r.bottom()); ++y)
            for (int x = std::max(0, r.left()); x <= std::min(lab8.cols - 1, r.right()); ++x)
                if (inside.at<std::uint8_t>(y, x)) {
                    const Lab c = labAt(lab8, x, y);
                    hues.push_back(hueOf(c));
                    chromas.push_back(chromaOf(c));
                    ls.push_back(c.l);
                }
    SkinModel m;
    if (ls.size() < 20)
        return m;
    // Medians resist a mole, a shadow or a strand across the cheek. (Skin hues lie far from the
    // a*b* plane's seam at 180 degrees, so they are averaged as plain numbers.)
    m.hue = medianOf(hues);
    m.chroma = std::max(0.1, medianOf(chromas));
    m.l = std::max(1.0, medianOf(ls));
    m.hueTolerance = std::max(kSkinHue, kSpreadTimes * spreadOf(hues));
    m.chromaRatio = std::max(kSkinRatio, 1.0 + kSpreadTimes * spreadOf(chromas) / m.chroma);
    m.lRatio = std::max(kSkinRatio, 1.0 + kSpreadTimes * spreadOf(ls) / m.l);
    m.valid = true;
    return m;
}

// The median of each channel over the rectangles' pixels inside the photo (`rgb`: red first).
QColor medianColour(const cv::Mat &rgb, const cv::Mat &inside, const std::vector<QRect> &rects)
{
    std::array<std::vector<double>, 3> channels;
    for (const QRect &r : rects)
        for (int y = std::max(0, r.top()); y <= std::min(rgb.rows - 1, r.bottom()); ++y)
            for (int x = std::max(0, r.left()); x <= std::min(rgb.cols - 1, r.right()); ++x)
                if (inside.at<std::uint8_t>(y, x))
                    for (int c = 0; c < 3; ++c)
                        channels[size_t(c)].push_back(rgb.at<cv::Vec3b>(y, x)[c]);
    if (channels[0].empty())
        return {};
    return QColor(int(medianOf(channels[0])), int(medianOf(channels[1])), int(medianOf(channels[2])));
}

void measureHairFall(HeadParse *parse, const cv::Mat &rgb, const cv::Mat &lab, double skinL, double browTop,
    double eyeY, double chinY, const std::array<QPointF, 2> &leftCheek, const std::array<QPointF, 2> &rightCheek)
{
    const double d = kParseEyeDistance;
    HeadParse &out = *parse;
    const double mid = out.size.width() / 2.0;
    // The hair's colour: the median of the person's pixels other than skin over the forehead
    // (kHairSampleLow..kHairSampleHigh d above the brows, kHairSampleHalf d either side).
    std::array<std::vector<double>, 3> sample, sampleRgb;
    auto take = [&](int x, int y) {
        const Lab c = labAt(lab, x, y);
        sample[0].push_back(c.l);
        sample[1].push_back(c.a);
        sample[2].push_back(c.b);
        const cv::Vec3b p = rgb.at<cv::Vec3b>(y, x);
        for (size_t k = 0; k < 3; ++k)
            sampleRgb[k].push_back(p[int(k)]);
        out.hairSample.push_back(qRgb(p[0], p[1], p[2]));
    };
    for (int y = std::max(0, int(browTop - kHairSampleHigh * d)); y <= int(browTop - kHairSampleLow * d); ++y)
        for (int x = int(mid - kHairSampleHalf * d); x <= int(mid + kHairSampleHalf * d); ++x)
            if (out.at(x, y) == HeadParse::Other)
                take(x, y);
    // A tight crop shows little or nothing over the forehead: the hair beside the temples
    // (kTempleNear..kTempleFar d out from the midline, from kTempleHigh d over the brows' top
    // down to the eyes) tells its colour instead.
    bool fromTemples = false;
    if (sample[0].size() < size_t(kMinHairSample * d * d)) {
        for (auto &c : sample)
            c.clear();
        for (auto &c : sampleRgb)
            c.clear();
        out.hairSample.clear();
        for (int y = std::max(0, int(browTop - kTempleHigh * d)); y <= int(eyeY); ++y)
            for (int x = 0; x < out.size.width(); ++x) {
                const double off = std::abs(x - mid) / d;
                if (off >= kTempleNear && off <= kTempleFar && out.at(x, y) == HeadParse::Other)
                    take(x, y);
            }
        if (sample[0].size() < size_t(kMinHairSample * d * d)) {
            out.hairSample.clear();
            return;
        }
        fromTemples = true;
    }
    const Lab hair {medianOf(sample[0]), medianOf(sample[1]), medianOf(sample[2])};
    out.hairSeen = !fromTemples;
    out.templeHairSeen = fromTemples;
    out.templeLighter = fromTemples ? hair.l - skinL : 0.0;
    // The median of the whole sample, shadows between the strands included: over the labelled
    // faces it orders black, brown, blond and grey hair better than the lit strands' median (the
    // 40th to 90th percentiles of luma, as the band inside the outline reads it) does, which
    // draws black hair brown (rank correlation of L* with that order 0.38 against 0.35).
    out.hair = QColor(int(medianOf(sampleRgb[0])), int(medianOf(sampleRgb[1])), int(medianOf(sampleRgb[2])));
    // Down each side from the eyes' line: a row is hair where at least kHairWidth d of a band
    // beside the face (from the cheek's line outward, kSideBand d wide) is the person, not skin,
    // within kHairColourDistance of the hair's colour (a strand or a curtain of it); the fall ends where kFallGap d of
    // rows have none (past the shoulders, or where the photo ends: reported as cut).
    auto sideLine = [&](const std::array<QPointF, 2> &cheek, double y) {
        const QPointF a = cheek[0], b = cheek[1];
        const double t = std::clamp((y - a.y()) / std::max(1.0, b.y() - a.y()), 0.0, 1.0);
        return a.x() + (b.x() - a.x()) * t;
    };
    const int gap = std::max(1, int(std::lround(kFallGap * d)));
    std::vector<double> falls;
    const QTransform toPhoto = out.toWork.inverted();
    // (In a tight crop beside a short-haired head the temples show the room; a wall far lighter
    // than the skin is seldom hair: over faces-attributes' 44 tight crops whose temples gave the
    // colour, every long- or medium-haired one's sample lay darker than the cheeks, and
    // `toonface-bench likeness.attributes` cross-validates kRoomLighter with the fall's two
    // thresholds. Its fall is the wall's, and is left at the eyes' line.)
    out.roomFall = fromTemples && out.templeLighter >= kRoomLighter;
    int side = 0;
    for (const auto &[cheek, outward] : {std::pair(leftCheek, -1.0), std::pair(rightCheek, 1.0)}) {
        int last = int(eyeY), misses = 0;
        double lastOuter = sideLine(cheek, eyeY);
        bool cut = false;
        for (int y = int(eyeY); y < out.size.height(); ++y) {
            const double edge = sideLine(cheek, y) + outward * kSideGap * d;
            int n = 0, hairy = 0, outside = 0;
            double outer = edge;
            for (int k = 0; k < int(kSideBand * d); ++k) {
                const int x = int(std::lround(edge + outward * k));
                if (x < 0 || x >= out.size.width()) {
                    ++outside;
                    continue;
                }
                const HeadParse::Label label = out.at(x, y);
                if (label == HeadParse::Outside) {
                    ++outside;
                    continue;
                }
                ++n;
                if (label == HeadParse::Other) {
                    const Lab c = labAt(lab, x, y);
                    if (std::hypot(c.l - hair.l, c.a - hair.a, c.b - hair.b) < kHairColourDistance) {
                        ++hairy;
                        outer = x;
                    }
                }
            }
            if (n < kHairWidth * d) { // too little of the band inside the photo to tell
                cut = true;
                break;
            }
            if (hairy >= kHairWidth * d) {
                last = y;
                lastOuter = outer;
                misses = 0;
            } else if (++misses > gap) {
                break;
            }
        }
        falls.push_back((last - chinY) / d);
        if (out.roomFall) {
            last = int(eyeY);
            lastOuter = sideLine(cheek, eyeY);
            cut = false;
        }
        out.fallEnds[side++] = toPhoto.map(QPointF(lastOuter, last));
        out.fallCut = out.fallCut || (cut && last >= int(chinY));
    }
    out.measuredFall = std::max(falls[0], falls[1]);
    out.hairFall = out.roomFall ? (int(eyeY) - chinY) / d : out.measuredFall;
}

} // namespace

bool followHairFall(FaceModel *face, const HeadParse &parse)
{
    // (A fall of the room's colour is no hair's: nothing to follow.)
    if (!parse.valid || !(parse.hairSeen || parse.templeHairSeen) || parse.roomFall || !face->isValid())
        return false;
    const double es0 = QLineF(face->point("3.6"), face->point("3.5")).length();
    bool moved = false;
    // Each side: the outline's lower end h.1 (h.19) and the kFallPoints above it toward h.5 (h.15).
    for (const bool left : {true, false}) {
        const QPointF end = parse.fallEnds[left ? 0 : 1];
        const int lowest = pt::idx(left ? "h.1" : "h.19");
        const int step = left ? 1 : -1;
        const int anchor = lowest + step * kFallPoints;
        if (end.y() - face->point(lowest).y() < kMinFallGain * es0)
            continue;
        const QPointF top = face->point(anchor);
        for (int k = 0; k < kFallPoints; ++k) {
            const double t = double(kFallPoints - k) / kFallPoints; // 1 at the end, toward 0 at the anchor
            const int i = lowest + step * k;
            if (face->isHandPlaced(i))
                continue;
            face->setPoint(i, top + (end - top) * t);
        }
        moved = true;
    }
    return moved;
}

HeadParse parseHead(const QImage &photo, const FaceModel &face)
{
    HeadParse out;
    if (photo.isNull() || !face.isValid())
        return out;
    QPointF l = face.point("3.6"), r = face.point("3.5");
    if (l.x() > r.x())
        std::swap(l, r);
    const QLineF eyes(l, r);
    if (eyes.length() < 1.0)
        return out;
    const double d = kParseEyeDistance;
    const double roll = std::atan2(eyes.dy(), eyes.dx()) * 180.0 / std::numbers::pi;
    const QPointF centre(kHalfWidth * d, kAbove * d);
    out.size = QSize(int(2 * kHalfWidth * d), int((kAbove + kBelow) * d));
    out.toWork.translate(centre.x(), centre.y());
    out.toWork.scale(d / eyes.length(), d / eyes.length());
    out.toWork.rotate(-roll);
    out.toWork.translate(-eyes.center().x(), -eyes.center().y());

    const QImage rgb = photo.convertToFormat(QImage::Format_RGB888);
    const cv::Mat src(
        rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
    const QTransform &t = out.toWork;
    const cv::Matx23d affine(t.m11(), t.m21(), t.dx(), t.m12(), t.m22(), t.dy());
    const cv::Size workSize(out.size.width(), out.size.height());
    cv::Mat work, inside;
    // Beyond the photo's edge the nearest edge pixels are repeated (no colour of its own to
    // seed the models with); those pixels are labelled Outside afterwards.
    cv::warpAffine(src, work, affine, workSize, cv::INTER_AREA, cv::BORDER_REPLICATE);
    cv::warpAffine(cv::Mat(src.size(), CV_8UC1, cv::Scalar(255)), inside, affine, workSize, cv::INTER_NEAREST,
        cv::BORDER_CONSTANT, cv::Scalar(0));

    auto w = [&](const char *id) { return t.map(face.point(id)); };
    // Seeds.
    cv::Mat mask(workSize, CV_8UC1, cv::Scalar(cv::GC_PR_BGD));
    for (int y = 0; y < mask.rows; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            const double dx = (x - centre.x()) / d, dy = (y - centre.y()) / d;
            const bool head = std::pow(dx / kHeadRx, 2) + std::pow((dy + kHeadLift) / kHeadRy, 2) <= 1.0;
            const bool neck = std::abs(dx) < kNeckHalf && dy > kNeckTop;
            const bool curtain = std::abs(dx) < kCurtainHalf && dy > 0 && dy < kCurtainBottom;
            if (head || neck || curtain)
                mask.at<std::uint8_t>(y, x) = cv::GC_PR_FGD;
            else if (std::hypot(dx, dy) > kFar && dy < kFarBelow && inside.at<std::uint8_t>(y, x))
                mask.at<std::uint8_t>(y, x) = cv::GC_BGD;
        }
    }
    static constexpr const char *kContour[] = {"5.2", "2.14", "2.12", "2.1", "2.11", "2.13", "5.1"};
    static constexpr const char *kBrows[] = {"4.5", "4.3a", "4.3", "4.1", "4.2", "4.4", "4.4a", "4.6"};
    std::vector<cv::Point> facePolygon;
    for (const char *id : kContour)
        facePolygon.emplace_back(int(std::lround(w(id).x())), int(std::lround(w(id).y())));
    for (const char *id : kBrows)
        facePolygon.emplace_back(int(std::lround(w(id).x())), int(std::lround(w(id).y() + 0.1 * d)));
    cv::Mat faceMask(workSize, CV_8UC1, cv::Scalar(0));
    cv::fillPoly(faceMask, std::vector<std::vector<cv::Point>> {facePolygon}, cv::Scalar(1));
    const int erode = std::max(1, int(std::lround(0.06 * d)));
    cv::erode(faceMask, faceMask, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * erode + 1, 2 * erode + 1)));
    mask.setTo(cv::Scalar(cv::GC_FGD), faceMask);

    cv::Mat bgModel, fgModel;
    // GrabCut starts its colour models by k-means from the thread's random generator: a fixed
    // seed gives the same parse of the same photo every time.
    const cv::RNG saved = cv::theRNG();
    cv::theRNG() = cv::RNG(0x70f);
    // Only the part the photo covers takes part: the repeated edge pixels beyond it would teach
    // the background model the colours of hair or clothes the photo's edge cuts through.
    // (It needs pixels of both kinds to start from: a photo much smaller than the face's points
    // say has none.)
    const cv::Rect covered = cv::boundingRect(inside);
    bool grabbed = false;
    if (covered.area() > 0) {
        cv::Mat roiMask = mask(covered);
        cv::Mat person = (roiMask == cv::GC_FGD) | (roiMask == cv::GC_PR_FGD);
        const int people = cv::countNonZero(person);
        // A tight crop of the face (the photo holds little or nothing beyond where the person
        // probably is) leaves too little of the room to model: its seeds stand as they are.
        const int room = int(roiMask.total()) - people;
        if (people > 0 && room >= kMinRoom * d * d)
            cv::grabCut(work(covered), roiMask, cv::Rect(), bgModel, fgModel, kGrabCutRounds, cv::GC_INIT_WITH_MASK);
        grabbed = people > 0;
    }
    cv::theRNG() = saved;
    if (!grabbed)
        return out;

    cv::Mat lab;
    rgbToLab8(work, lab);
    // The cheeks: below the lower lids, above the mouth's corners, from the outer eye corners to
    // beside the nostrils.
    const double cheekTop = std::max(w("3.4").y(), w("3.3").y()) + 0.25 * d;
    const double cheekBottom = std::min(w("8.4").y(), w("8.3").y()) - 0.05 * d;
    auto span = [&](double x0, double x1) {
        return QRect(QPoint(int(std::ceil(x0)), int(std::ceil(cheekTop))),
            QPoint(int(std::floor(x1)), int(std::floor(cheekBottom))));
    };
    const std::vector<QRect> cheeks {
        span(w("3.12").x(), w("9.14").x() - 0.1 * d), span(w("9.13").x() + 0.1 * d, w("3.7").x())};
    const SkinModel skin = cheekModel(lab, inside, cheeks);
    if (!skin.valid)
        return out;
    const QColor cheekColour = medianColour(work, inside, cheeks);
    double browTop = w(kBrows[0]).y();
    for (const char *id : kBrows)
        browTop = std::min(browTop, w(id).y());
    // The forehead over the brows, lit more like the crown than the cheeks are: a second model of
    // the skin where its colour is the cheeks' skin (not a fringe of hair, a hat's brim).
    const QRect foreheadBox(
        QPoint(int(std::ceil(centre.x() - kForeheadHalf * d)), int(std::ceil(browTop - kForeheadHigh * d))),
        QPoint(int(std::floor(centre.x() + kForeheadHalf * d)), int(std::floor(browTop - kForeheadLow * d))));
    const SkinModel forehead = cheekModel(lab, inside, {foreheadBox});
    out.work = QImage(work.data, work.cols, work.rows, int(work.step), QImage::Format_RGB888).copy();
    out.cheeks = cheekColour;
    out.browTop = browTop;
    for (const char *id : kBrows)
        out.brows.push_back(w(id));
    out.sideCheeks[0][0] = w("5.2");
    out.sideCheeks[0][1] = w("2.14");
    out.sideCheeks[1][0] = w("5.1");
    out.sideCheeks[1][1] = w("2.13");
    const bool foreheadIsSkin = forehead.valid && skin.isSkin(forehead.centre());
    const double foreheadL = foreheadIsSkin ? forehead.l : skin.l;
    // (Skin also where a shine lights it toward white.)
    auto isSkin = [&](int x, int y) {
        const Lab c = labAt(lab, x, y);
        const cv::Vec3b p = work.at<cv::Vec3b>(y, x);
        return skin.isSkin(c) || (foreheadIsSkin && forehead.isSkin(c))
            || shineOnSkin(qRgb(p[0], p[1], p[2]), cheekColour);
    };

    out.labels.resize(size_t(out.size.width()) * size_t(out.size.height()));
    for (int y = 0; y < mask.rows; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            const std::uint8_t m = mask.at<std::uint8_t>(y, x);
            HeadParse::Label label = HeadParse::Background;
            if (!inside.at<std::uint8_t>(y, x))
                label = HeadParse::Outside;
            else if (m == cv::GC_FGD || m == cv::GC_PR_FGD)
                label = isSkin(x, y) ? HeadParse::Skin : HeadParse::Other;
            out.labels[size_t(y) * size_t(out.size.width()) + size_t(x)] = label;
        }
    }

    // The skin's share over the forehead's middle (kWalkHalf d either side, from kWalkStart d
    // over the brows' top up to the head's top or the photo's edge) and beside the temples
    // (kTempleNear..kBaldSideFar d out, up kBaldSideHigh d from the brows' top).
    auto skinShare = [&](auto within) {
        int n = 0, skinny = 0;
        for (int y = 0; y < int(browTop - kWalkStart * d) && y < out.size.height(); ++y)
            for (int x = 0; x < out.size.width(); ++x) {
                const HeadParse::Label l = out.at(x, y);
                if (within(std::abs(x - centre.x()) / d, (browTop - y) / d)
                    && (l == HeadParse::Skin || l == HeadParse::Other)) {
                    ++n;
                    skinny += l == HeadParse::Skin;
                }
            }
        return n > 0 ? double(skinny) / n : 0.0;
    };
    out.crownSkin = skinShare([](double off, double) { return off <= kWalkHalf; });
    out.templeSkin = skinShare(
        [](double off, double up) { return off >= kTempleNear && off <= kBaldSideFar && up <= kBaldSideHigh; });

    // Up each column from the brows: where the skin's run ends, and where the person's does (the
    // head's top), or the photo's edge.
    const int gap = std::max(1, int(std::lround(kWalkGap * d)));
    std::vector<double> reaches, heights;
    int cut = 0, tops = 0, columns = 0;
    for (int x = int(std::ceil(centre.x() - kWalkHalf * d)); x <= int(std::floor(centre.x() + kWalkHalf * d)); ++x) {
        ++columns;
        const int start = int(std::floor(browTop - kWalkStart * d));
        auto runEnd = [&](int from, auto belongs) {
            int last = from, misses = 0;
            for (int y = from; y >= 0; --y) {
                const HeadParse::Label label = out.at(x, y);
                if (label == HeadParse::Outside)
                    return std::pair(last, true);
                if (belongs(label, y)) {
                    last = y;
                    misses = 0;
                } else if (++misses > gap) {
                    break;
                }
            }
            return std::pair(last, last - gap <= 0);
        };
        if (start < 0 || start >= out.size.height() || out.at(x, start) == HeadParse::Outside) {
            ++cut;
            continue;
        }
        // A scalp is lit as the forehead or more (from above); hair as dark as the skin lies
        // darker than the forehead's own shading goes.
        const auto [skinTop, skinCut] = runEnd(start, [&](HeadParse::Label l, int y) {
            return l == HeadParse::Skin && labAt(lab, x, y).l >= foreheadL / kScalpDarker;
        });
        const auto [headTop, headCut]
            = runEnd(skinTop, [](HeadParse::Label l, int) { return l == HeadParse::Skin || l == HeadParse::Other; });
        if (skinCut) {
            ++cut;
            continue;
        }
        out.foreheadTop.emplace_back(x, skinTop);
        // (Hair or a hat running to the photo's edge still lies over the forehead's skin.)
        tops += headCut;
        const double height = browTop - headTop;
        heights.push_back(height / d);
        reaches.push_back(height > 0 ? (browTop - skinTop) / height : 0.0);
    }
    out.crownCut = columns == 0 || 2 * cut >= columns;
    out.topCut = !heights.empty() && 2 * tops >= int(heights.size());
    if (!heights.empty()) {
        out.headHeight = medianOf(heights);
        out.scalpReach = medianOf(reaches);
    }
    measureHairFall(
        &out, work, lab, skin.l, browTop, w("3.4").y(), w("2.1").y(), {w("5.2"), w("2.14")}, {w("5.1"), w("2.13")});
    out.valid = true;
    return out;
}

} // namespace toonface
