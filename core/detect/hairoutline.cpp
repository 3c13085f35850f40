#include "detect/hairoutline.h"

#include "detect/appearance.h"
#include "detect/labcolour.h"
#include "detect/landmarkmap.h"
#include "face/pointtable.h"

#include <QLineF>

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <cmath>

// The hair outline from the parse of the head (headparse.h). The parse has cut the person from
// the background as a whole and told the skin apart; what is left beside and above the face is
// hair, a hat or clothes. The silhouette is read row by row in the parse's work frame:
// - above the brows' top, the head is every pixel of the person: from the midline outward to
//   where the person ends (hair, a hat, a bald scalp, a voluminous head of hair: all of it);
// - below it, beside the face, only the hair is: pixels of the person, not skin, of the crown's
//   hair colour, from the face's side line outward. Rows go down while they hold hair (long
//   hair falls to the shoulders; tied-back hair stops beside the temples; a gap of clothes or
//   neck ends it);
// - a row's extent is where its run of such pixels ends (gaps of a few pixels crossed: strands,
//   curls, a shine).
// Each side's extents are smoothed over neighbouring rows (a median) and joined over the crown
// into one line; the model's 19 hair points are placed at equal steps along it.

namespace toonface {

namespace {

constexpr double d = kParseEyeDistance;
// A run of the head's pixels goes on across gaps up to kGap d (a strand, a curl's shadow, a
// shine); beside the face the hair is looked for from kInside d inside the face's side line (hair
// over the cheek) to kReach d outside it, and a row holds hair when at least kMinHair d of its
// run is hair. The fall ends after kFallGap d of rows without hair (the same gap as the parse's
// own fall, headparse.cpp).
constexpr double kGap = 0.12, kInside = 0.1, kReach = 0.6, kMinHair = 0.1, kFallGap = 0.25;
// A pixel of the person within kHairDistance L*a*b* units of the crown's hair colour is hair
// (the parse's own distance for the fall, headparse.cpp).
constexpr double kHairDistance = 18.0;
// Rows' extents are smoothed by a median over kSmoothRows d of rows.
constexpr double kSmoothRows = 0.2;
// Rows above the eyes whose walk meets the photo's edge: up to kMaxCutRows d of them are the top
// edge slanting across the rows (a head tilted by up to about 8 degrees over its width).
constexpr double kMaxCutRows = 0.3;
// ... and a row whose head or hair ends within kClear d of the photo's edge is cut.
constexpr double kClear = 0.3;
// The search's own bound on the outline (hairsearch.cpp): at most 1.6 times the head's geometric
// estimate from its centre.
constexpr double kMaxSpread = 2.0;
// The hairline stays at least kMinForehead d over the brows' top (as low as the search puts it,
// hairsearch.cpp): a fringe lower than that still leaves the brows room to rise in an expression
// (keepBrowsUnderHairline keeps them under the hairline).
constexpr double kMinForehead = 0.2;
// ... read in the forehead's columns within kHairlineHalf d of the midline.
constexpr double kHairlineHalf = 0.15;

using Lab = LabColour;

Lab labOf(const cv::Mat &lab8, int x, int y)
{
    const cv::Vec3b v = lab8.at<cv::Vec3b>(y, x);
    return {v[0] * 100.0 / 255.0, v[1] - 128.0, v[2] - 128.0};
}

double medianOf(std::vector<double> v)
{
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// The face's side line at row y (work frame): the cheek's x at eye level above it, along the
// cheek's line to the jaw below, the jaw's x below that.
double sideLineAt(const QPointF (&cheek)[2], double y)
{
    const QPointF a = cheek[0], b = cheek[1];
    const double t = std::clamp((y - a.y()) / std::max(1.0, b.y() - a.y()), 0.0, 1.0);
    return a.x() + (b.x() - a.x()) * t;
}

// Points at equal steps along a polyline: `count` of them, the first at its start, the last at
// its end.
std::vector<QPointF> resample(const std::vector<QPointF> &line, int count)
{
    std::vector<double> at {0.0};
    for (size_t i = 1; i < line.size(); ++i)
        at.push_back(at.back() + QLineF(line[i - 1], line[i]).length());
    std::vector<QPointF> out;
    size_t seg = 1;
    for (int k = 0; k < count; ++k) {
        const double s = at.back() * k / std::max(1, count - 1);
        while (seg + 1 < line.size() && at[seg] < s)
            ++seg;
        if (line.size() == 1) {
            out.push_back(line[0]);
            continue;
        }
        const double len = at[seg] - at[seg - 1];
        const double t = len > 0 ? std::clamp((s - at[seg - 1]) / len, 0.0, 1.0) : 0.0;
        out.push_back(line[seg - 1] + (line[seg] - line[seg - 1]) * t);
    }
    return out;
}

} // namespace

HairSilhouette hairSilhouette(const HeadParse &parse)
{
    HairSilhouette out;
    // A tight crop cuts the crown off (the forehead's skin runs to the photo's top edge): the hair
    // beside the face is still seen below that edge, in the colour the temples gave (unless that
    // sample was the room, HeadParse::roomFall). Its sides are read from the edge down; above the
    // edge the search's outline stays (outlineHairFromParse), as where hair runs up to the edge.
    const bool cropped = parse.crownCut;
    if (!parse.valid || parse.work.isNull() || (!parse.hairSeen && !(cropped && parse.templeHairSeen))
        || (cropped && parse.roomFall))
        return out;
    const int width = parse.size.width(), height = parse.size.height();
    const QImage rgb = parse.work.convertToFormat(QImage::Format_RGB888);
    const cv::Mat src(
        rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
    cv::Mat lab;
    rgbToLab8(src, lab);
    const Lab hair = labOf(parse.hair);
    auto isHair = [&](int x, int y) {
        if (parse.at(x, y) != HeadParse::Other)
            return false;
        const Lab c = labOf(lab, x, y);
        return std::hypot(c.l - hair.l, c.a - hair.a, c.b - hair.b) < kHairDistance;
    };
    const double mid = width / 2.0;
    const double eyeY = (parse.sideCheeks[0][0].y() + parse.sideCheeks[1][0].y()) / 2.0;
    int top = std::clamp(int(std::lround(parse.browTop - parse.headHeight * d)), 0, height - 1);
    if (cropped) { // the photo's top edge over the midline
        top = 0;
        while (top < height - 1 && parse.at(int(width / 2), top) == HeadParse::Outside)
            ++top;
        if (top >= parse.browTop)
            return out;
    }
    const int browRow = int(std::ceil(parse.browTop));
    const int gap = std::max(1, int(std::lround(kGap * d)));
    const int fallGap = std::max(1, int(std::lround(kFallGap * d)));

    // Each side's extent per row, from the crown's row down to where the hair ends.
    std::array<std::vector<double>, 2> extent;
    std::array<int, 2> lastRow {top, top};
    for (int side = 0; side < 2; ++side) {
        const int outward = side == 0 ? -1 : 1;
        int misses = 0, cutRows = 0;
        double held = mid;
        for (int y = top; y < height; ++y) {
            const bool head = y < browRow;
            // Above the brows the walk starts on the midline (the head touches it), below them
            // just inside the face's side line (the hair is looked for within reach of it).
            const double line = sideLineAt(parse.sideCheeks[side], std::max(double(y), eyeY));
            const int start = head ? int(std::lround(mid)) : int(std::lround(line - outward * kInside * d));
            const int reach = head ? gap : int(std::lround((kInside + kReach) * d));
            int last = -1, found = 0, run = 0, k = 0;
            bool cut = false;
            for (int x = start; x >= 0 && x < width; x += outward, ++k) {
                const HeadParse::Label label = parse.at(x, y);
                if (label == HeadParse::Outside) {
                    cut = last >= 0;
                    break;
                }
                const bool member = head ? label == HeadParse::Skin || label == HeadParse::Other : isHair(x, y);
                if (member) {
                    last = x;
                    ++found;
                    run = 0;
                } else if ((last >= 0 && ++run > gap) || (last < 0 && k > reach)) {
                    break;
                }
            }
            // A head whose edge comes within kClear d of the photo's edge may go on beyond it
            // (the parse takes a background it cannot tell from the hair for the person, up to
            // the photo's edge): it counts as cut.
            for (int j = 1; !cut && last >= 0 && j <= int(kClear * d); ++j) {
                const int x = last + outward * j;
                cut = x < 0 || x >= width || parse.at(x, y) == HeadParse::Outside;
            }
            // The head or its hair goes on beyond the photo's side above the eyes: how wide it
            // is, is not seen (the search's outline stays). A few rows cut are the photo's top
            // edge, slanting across the rows of a tilted head; below the eyes the fall goes on
            // along the edge. A tight crop's hair runs off its sides more often than not (long
            // hair, curls): it is drawn as wide as the photo shows it, no wider (kMaxSpread still
            // bounds it, outlineHairFromParse).
            if (cut && y < eyeY && !cropped && ++cutRows > kMaxCutRows * d)
                return out;
            const bool hairy = head ? last >= 0 : found >= kMinHair * d;
            if (hairy) {
                misses = 0;
                lastRow[size_t(side)] = y;
                held = last;
            } else if (!head && y >= eyeY && ++misses > fallGap) {
                break; // (above the eyes an ear or hair tucked behind it is no end: the parse's
                       // own fall is looked for from the eyes down, headparse.cpp)
            }
            extent[size_t(side)].push_back(held); // (a row without hair holds the last extent)
        }
        extent[size_t(side)].resize(size_t(lastRow[size_t(side)] - top + 1));
    }
    // A median over neighbouring rows: a stray pixel of the background taken for the person, or
    // a gap between curls, does not make a notch.
    const int half = std::max(1, int(std::lround(kSmoothRows * d / 2)));
    for (auto &e : extent) {
        const std::vector<double> raw = e;
        for (size_t i = 0; i < e.size(); ++i) {
            std::vector<double> window;
            for (size_t j = size_t(std::max(0, int(i) - half)); j <= std::min(e.size() - 1, i + size_t(half)); ++j)
                window.push_back(raw[j]);
            e[i] = medianOf(window);
        }
    }
    for (int y = lastRow[0]; y >= top; --y)
        out.left.emplace_back(extent[0][size_t(y - top)], y);
    out.left.emplace_back(mid, top);
    out.right.emplace_back(mid, top);
    for (int y = top; y <= lastRow[1]; ++y)
        out.right.emplace_back(extent[1][size_t(y - top)], y);
    out.top = top;
    out.topCut = parse.topCut || cropped;
    return out;
}

bool outlineHairFromParse(FaceModel *face, const HeadParse &parse)
{
    if (!face->isValid())
        return false;
    const HairSilhouette s = hairSilhouette(parse);
    if (!s.valid())
        return followHairFall(face, parse);
    const QTransform toPhoto = parse.toWork.inverted();
    // A head of hair wider or taller than the search ever lets the outline be (kMaxSpread times
    // the head's estimate, above the eyes) is the background cut as the person (hair as dark as
    // a dark room): the parse is unsure there, the search's outline stays.
    const HeadGeometry g = headGeometry(*face);
    for (const auto *chain : {&s.left, &s.right})
        for (const QPointF &w : *chain) {
            const QPointF q = g.toLocal(toPhoto.map(w)) - g.hairCentre;
            if (q.y() < 0 && std::hypot(q.x() / g.hairAx, q.y() / g.hairAy) > kMaxSpread)
                return followHairFall(face, parse);
        }
    const std::vector<QPointF> left = resample(s.left, 10), right = resample(s.right, 10);
    bool moved = false;
    for (int k = 0; k < 19; ++k) {
        const int i = pt::idx("h.1") + k; // h.1 … h.19 are consecutive
        if (face->isHandPlaced(i))
            continue;
        const QPointF w = k < 10 ? left[size_t(k)] : right[size_t(k - 9)];
        // Where the photo's top edge cuts the head, the crown goes on beyond it: a point the
        // search placed higher than that edge stays (it keeps the crown round, not flat).
        if (s.topCut && w.y() <= s.top + kGap * d && parse.toWork.map(face->point(i)).y() < w.y())
            continue;
        const QPointF p = toPhoto.map(w);
        moved = moved || QLineF(p, face->point(i)).length() > 1e-9;
        face->setPoint(i, p);
    }
    // Where the parse's own measure of the fall (headparse.cpp) sees the hair fall lower than the
    // silhouette's ends (hair of another shade than the crown's below the ears), the ends follow it.
    return followHairFall(face, parse) || moved;
}

bool placeHairlineFromParse(FaceModel *face, const HeadParse &parse)
{
    if (!parse.valid || parse.crownCut || parse.foreheadTop.empty() || !face->isValid()
        || parse.scalpReach >= AppearanceFindings::kScalpReach)
        return false;
    const double eyeY = (parse.sideCheeks[0][0].y() + parse.sideCheeks[1][0].y()) / 2.0;
    // The columns nearest the midline (the forehead's top slopes down toward the temples).
    const double mid = parse.size.width() / 2.0;
    std::vector<double> tops;
    for (const QPoint &p : parse.foreheadTop)
        if (std::abs(p.x() - mid) <= kHairlineHalf * d)
            tops.push_back(p.y());
    if (tops.empty())
        return false;
    const QTransform toPhoto = parse.toWork.inverted();
    const QPointF centre = parse.toWork.map(face->point("11.1"));
    const double oldRise = eyeY - centre.y();
    const double rise = eyeY - std::min(medianOf(tops), parse.browTop - kMinForehead * d);
    if (oldRise <= 1.0)
        return false;
    bool moved = false;
    auto place = [&](const char *id, QPointF work) {
        const int i = pt::idx(id);
        if (face->isHandPlaced(i))
            return;
        const QPointF p = toPhoto.map(work);
        moved = moved || QLineF(p, face->point(i)).length() > 1e-9;
        face->setPoint(i, p);
    };
    // The temples rise in proportion (as the search moves them, hairsearch.cpp).
    for (const char *id : {"11.2", "11.3"}) {
        const QPointF t = parse.toWork.map(face->point(id));
        place(id, QPointF(t.x(), eyeY - (eyeY - t.y()) * rise / oldRise));
    }
    place("11.1", QPointF(centre.x(), eyeY - rise));
    return moved;
}

} // namespace toonface
