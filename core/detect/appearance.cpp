#include "detect/appearance.h"

#include "detect/headparse.h"
#include "detect/labcolour.h"
#include "detect/photopixels.h"
#include "detect/skintone.h"
#include "face/fapu.h"

#include <QLineF>
#include <QPainter>
#include <QPolygonF>
#include <QTransform>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <numeric>
#include <optional>
#include <vector>

namespace toonface {

namespace {

// Hair colours: hues from red through orange to yellow (kHairHues[0] .. 360 and 0 .. kHairHues[1]),
// and any colour too dark or too grey to have a hue that shows.
constexpr double kHairHues[2] = {345.0, 55.0};
constexpr double kDarkest = 0.2;
constexpr double kGreyest = 0.2;
constexpr int kColourless = 4; // a skin whose channels differ by less has no colour (a greyscale photo)
// ES0 above the brows: a forehead's skin reaching higher is scalp (hairlines lie 0.6 to 1.2 ES0
// above the brows on the shared photos' haired heads).
constexpr double kScalpAboveBrows = 1.4;
constexpr double kTempleHairShare = 0.2; // share of the temples' samples that must be other than skin
// Skin reaching farther above the head's outline than this share means the outline is not the head's.
constexpr double kMaxSkinReach = 1.3;
// A face tilted further than this (degrees) is measured upright: across a box as wide as the
// mouth, its tilt already moves a point a twentieth of the box's width up or down.
constexpr double kUprightRoll = 3.0;

// A skin without colour: a greyscale photo.
bool colourless(const QColor &skin)
{
    return std::max({skin.red(), skin.green(), skin.blue()}) - std::min({skin.red(), skin.green(), skin.blue()})
        < kColourless;
}

double labDistance(const QColor &a, const QColor &b)
{
    const LabColour p = labOf(a), q = labOf(b);
    return std::hypot(p.l - q.l, p.a - q.a, p.b - q.b);
}

// The hair that shows beside the temples, under a hat as without one: between the face's contour
// (from the temple 11.2 / 11.3 down to the cheek 5.2 / 5.1) and the hair outline at the same
// heights, what is not skin; its lighter half's median (a dark hat's side may share the place
// with the hair below it). Invalid when too little shows (a bald head, ears).
QColor templeHair(const Pixels &px, const FaceModel &face, double es0, const QColor &skin)
{
    std::vector<QRgb> hair;
    int all = 0;
    for (bool left : {true, false}) {
        const QPointF temple = face.point(left ? "11.2" : "11.3"), cheek = face.point(left ? "5.2" : "5.1");
        for (double t : {0.2, 0.4, 0.6, 0.8}) {
            const QPointF q = temple + (cheek - temple) * t;
            // The outline's side (h.1..h.9 image-left, h.19..h.11 right) at q's height.
            std::optional<double> outlineX;
            for (int k = 0; k + 1 < 9 && !outlineX; ++k) {
                const QPointF a = face.point(pt::idx(left ? "h.1" : "h.19") + (left ? k : -k));
                const QPointF b = face.point(pt::idx(left ? "h.1" : "h.19") + (left ? k + 1 : -k - 1));
                if ((a.y() - q.y()) * (b.y() - q.y()) <= 0 && std::abs(a.y() - b.y()) > 1e-9)
                    outlineX = a.x() + (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y());
            }
            if (!outlineX || (left ? q.x() - *outlineX : *outlineX - q.x()) < 0.06 * es0)
                continue;
            for (double across : {0.3, 0.5, 0.7}) {
                const auto b
                    = px.box(around(QPointF(q.x() + (*outlineX - q.x()) * across, q.y()), 0.03 * es0, 0.03 * es0));
                all += int(b.size());
                std::copy_if(b.begin(), b.end(), std::back_inserter(hair), [&](QRgb c) { return !skinLike(c, skin); });
            }
        }
    }
    if (all == 0 || double(hair.size()) < kTempleHairShare * all)
        return {};
    std::sort(hair.begin(), hair.end(), [](QRgb a, QRgb b) { return lumaOf(a) < lumaOf(b); });
    return median(std::vector<QRgb>(hair.begin() + qsizetype(hair.size() / 2), hair.end()));
}

// The forehead's top edge: up each column between the temples from the brows, the first row
// that is not skin (for a run). A hat's brim leaves a straight edge across the forehead; a
// hairline curves (higher in the middle or at the temples) and strands break it. The edge's
// spread about its best straight line (80th percentile of the distances), in ES0; negative when
// the edge is not found across most of the forehead.
double foreheadEdgeSpread(const Pixels &px, const FaceModel &face, double es0, const QColor &skin)
{
    const QPointF l = face.point("11.2"), r = face.point("11.3");
    const double browY = std::min(face.point("4.2").y(), face.point("4.1").y());
    const int need = std::max(2, int(0.03 * es0));
    std::vector<QPointF> ends;
    int columns = 0;
    for (double x = l.x() + 0.1 * (r.x() - l.x()); x <= r.x() - 0.1 * (r.x() - l.x()); x += std::max(1.0, 0.02 * es0)) {
        ++columns;
        int run = 0;
        for (double y = browY - 0.1 * es0; y > browY - 2.0 * es0 && px.inside(int(x), int(y)); y -= 1.0) {
            if (skinLike(px.at(int(x), int(y)), skin)) {
                run = 0;
            } else if (++run >= need) {
                ends.emplace_back(x, y + need - 1);
                break;
            }
        }
    }
    if (columns == 0 || double(ends.size()) < 0.8 * columns)
        return -1;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const QPointF &e : ends) {
        sx += e.x();
        sy += e.y();
        sxx += e.x() * e.x();
        sxy += e.x() * e.y();
    }
    const double n = double(ends.size());
    const double b = (n * sxy - sx * sy) / std::max(1e-9, n * sxx - sx * sx), a = (sy - b * sx) / n;
    std::vector<double> off;
    for (const QPointF &e : ends)
        off.push_back(std::abs(e.y() - (a + b * e.x())));
    return percentile(off, 0.8) / es0;
}

void findHead(const Pixels &px, const FaceModel &face, double es0, const QColor &skin, AppearanceFindings *out)
{
    // Between the face's top contour and the hair outline over the crown (h.8..h.12 above the
    // hairline 11.1 and the temples).
    // The inner part of that band is scalp on a bald head, hair or a hat otherwise, even when
    // the outline strayed into the background.
    int sampled = 0, seen = 0; // boxes in the band, and those the photo shows whole
    auto band = [&](int first, int last, const std::vector<const char *> &contour, double t0, double t1) {
        std::vector<QRgb> pxs;
        for (int k = first; k <= last; ++k) {
            const QPointF h = face.point(pt::idx("h.1") + k - 1);
            QPointF base = face.point(contour.front());
            for (const char *id : contour) {
                if (QLineF(h, face.point(id)).length() < QLineF(h, base).length())
                    base = face.point(id);
            }
            for (int i = 0; i < 4; ++i) {
                const QRectF r = around(base + (h - base) * (t0 + (t1 - t0) * i / 3.0), 0.025 * es0, 0.025 * es0);
                const auto b = px.box(r);
                pxs.insert(pxs.end(), b.begin(), b.end());
                ++sampled;
                seen += px.covers(r);
            }
        }
        return pxs;
    };
    const std::vector<QRgb> crown = band(8, 12, {"11.2", "11.1", "11.3"}, 0.15, 0.5);
    const QPointF hairline = face.point("11.1");
    const double browY = (face.point("4.2").y() + face.point("4.1").y()) / 2.0;
    // A crown the photo cuts off (most of the band beyond its edge) is not seen: no hat, and bald
    // only where the forehead's skin runs up the midline to the photo's edge higher above the
    // brows than any hairline (that is scalp).
    // The crown the parse of the head sees decides bald (a greyscale photo is never bald: without
    // colour a scalp and grey or white hair look alike).
    const bool parsedCrown = !out->crownCut && !(out->topCut && out->headHeight < AppearanceFindings::kMinHeadHeight);
    const bool parsedBald = parsedCrown && !colourless(skin) && out->scalpReach >= AppearanceFindings::kScalpReach
        && out->headHeight >= AppearanceFindings::kMinHeadHeight;
    if (crown.empty() || 2 * seen < sampled) {
        if (parsedCrown) {
            out->appearance.bald = parsedBald;
            return;
        }
        const bool skinToTheEdge = !px.inside(int(hairline.x()), int(std::floor(hairline.y() - 0.05 * es0)));
        out->appearance.bald = skinToTheEdge && browY - hairline.y() >= kScalpAboveBrows * es0;
        return;
    }
    const auto scalp
        = std::count_if(crown.begin(), crown.end(), [&](QRgb c) { return skinLike(c, skin) || shineOnSkin(c, skin); });
    out->baldScore = double(scalp) / double(crown.size());
    // How far up toward the head's top the forehead's skin reaches (11.1, where the skin up the
    // midline ends, over the hair outline's top h.10, from the brows): on a bald or shaved head
    // all the way, whatever the outline strayed into above it.
    const double headTop = browY - face.point("h.10").y();
    // (Seen only where the hairline is in the photo, not beyond an edge that cuts the head off.)
    const bool hairlineSeen = px.inside(int(hairline.x()), int(hairline.y()) - 1);
    out->skinReach = headTop > 0.5 * es0 && hairlineSeen ? (browY - hairline.y()) / headTop : 0.0;
    const bool skinToTheTop
        = out->skinReach >= AppearanceFindings::kSkinReachThreshold && out->skinReach <= kMaxSkinReach;
    // Without colour, a scalp and grey or white hair look alike: a greyscale photo is never bald.
    out->appearance.bald = parsedCrown
        ? parsedBald
        : !colourless(skin) && (out->baldScore >= AppearanceFindings::kBaldThreshold || skinToTheTop);
    if (out->appearance.bald)
        return;
    // A hat by its colour: none that hair grows in (black, browns, blondes, reds, greys and white);
    // its score is how far its hue lies outside that range, weighted by its saturation.
    // A hat of any colour: the crown unlike both the skin and the hair that shows beside the
    // temples, over a straight edge across the forehead (a brim; a hairline curves or breaks).
    const QColor top = median(crown);
    const QColor temples = templeHair(px, face, es0, skin);
    out->templeHair = temples;
    out->crownToHair = temples.isValid() ? labDistance(top, temples) : 0.0;
    out->crownToSkin = labDistance(top, skin);
    out->brimSpread = foreheadEdgeSpread(px, face, es0, skin);
    if (std::min(out->crownToHair, out->crownToSkin) >= AppearanceFindings::kHatContrast && out->brimSpread >= 0
        && out->brimSpread <= AppearanceFindings::kBrimSpread) {
        out->appearance.hat = true;
        out->hat = top;
        return;
    }
    // By its colour alone: none that hair grows in.
    const double hue = top.hsvHueF() * 360.0, sat = top.hsvSaturationF();
    const bool hairHue = hue < 0 || hue <= kHairHues[1] || hue >= kHairHues[0];
    const double outside = hairHue ? 0.0 : std::min(hue - kHairHues[1], kHairHues[0] - hue);
    out->hatScore = top.valueF() < kDarkest || sat < kGreyest ? 0.0 : outside * sat;
    if (out->hatScore >= AppearanceFindings::kHatThreshold) {
        out->appearance.hat = true;
        out->hat = top;
    }
}

// The face's own parts (over the lip, under the eyes, around the lenses) are looked for in boxes
// square to its eyes' line. On a face tilted in the picture's plane the photo's boxes would cut
// across them (at 20 degrees, the lip's top corner rises past the nose's bottom), so the face is
// measured upright: the photo around it turned until the eyes are level, the points with it.
// Where the turned photo does not reach, it shows the skin (nothing there, as outside the photo).
struct Upright
{
    QImage photo;
    FaceModel face;
};

// Nothing for a face already upright (tilted less than kUprightRoll).
std::optional<Upright> upright(const QImage &photo, const FaceModel &face, const QColor &skin, double es0)
{
    QPointF l = face.point("3.6"), r = face.point("3.5");
    if (l.x() > r.x())
        std::swap(l, r);
    const QLineF eyes(l, r);
    const double roll = std::atan2(eyes.dy(), eyes.dx()) * 180.0 / std::numbers::pi; // y down: clockwise
    if (std::abs(roll) < kUprightRoll)
        return std::nullopt;
    const QPointF centre = eyes.center();
    QTransform level;
    level.translate(centre.x(), centre.y());
    level.rotate(-roll);
    level.translate(-centre.x(), -centre.y());
    QPolygonF points;
    for (const QPointF &p : face.points())
        points << level.map(p);
    const QRect area = points.boundingRect().adjusted(-es0, -es0, es0, es0).toAlignedRect();
    Upright out {QImage(area.size(), QImage::Format_RGB32), face};
    out.face.setImageSize(area.size());
    for (int i = 0; i < kPointCount; ++i)
        out.face.setPoint(i, points[i] - area.topLeft(), face.isHandPlaced(i));
    level *= QTransform::fromTranslate(-area.left(), -area.top());
    out.photo.fill(skin);
    {
        QPainter painter(&out.photo);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        painter.setTransform(level);
        painter.drawImage(QPointF(0, 0), photo);
    }
    return out;
}

} // namespace

AppearanceFindings findAppearance(const QImage &photo, const FaceModel &face, const QColor &skin)
{
    AppearanceFindings out;
    if (photo.isNull() || !face.isValid() || !skin.isValid())
        return out;
    const double es0 = face.fapu().es0;
    const double skinLuma = std::max(1.0, lumaOf(skin.rgb()));
    const Pixels px(photo);
    if (const std::optional<Upright> level = upright(photo, face, skin, es0)) {
        const Pixels levelPx(level->photo);
        out.evidence = measureEvidence(level->photo, level->face);
        findGlasses(levelPx, level->face, es0, skinLuma, &out);
        findFacialHair(levelPx, level->face, es0, skinLuma, colourless(skin), skin, &out);
    } else {
        out.evidence = measureEvidence(photo, face);
        findGlasses(px, face, es0, skinLuma, &out);
        findFacialHair(px, face, es0, skinLuma, colourless(skin), skin, &out);
    }
    const HeadParse parse = parseHead(photo, face);
    if (parse.valid) {
        out.crownCut = parse.crownCut;
        out.topCut = parse.topCut;
        out.headHeight = parse.headHeight; // eye distances, as ES0
        out.scalpReach = parse.scalpReach;
        out.hairSeen = parse.hairSeen;
        out.hairFall = parse.hairFall;
        out.templeHairSeen = parse.templeHairSeen;
        out.fallCut = parse.fallCut;
        out.roomFall = parse.roomFall;
        out.templeLighter = parse.templeLighter;
        out.measuredFall = parse.measuredFall;
        out.crownSkin = parse.crownSkin;
        out.templeSkin = parse.templeSkin;
        out.cover = measureCover(parse);
        if (parse.hairSeen || parse.templeHairSeen) {
            out.parsedHair = parse.hair;
            out.hairReading = readHairColour(parse);
        }
    }
    findHead(px, face, es0, skin, &out);
    // What lies over the forehead in the parse, where the crown's rules saw no hat (a tight crop
    // shows only the band of a cap or a scarf).
    if (!out.appearance.bald && !out.appearance.hat && isHeadwear(out.cover)) {
        out.appearance.hat = true;
        out.hat = out.cover.colour;
    }
    // Headwear whose colour also covers the bands beside the cheeks wraps the head.
    out.appearance.wrap = out.appearance.hat && out.cover.seen && out.cover.sides >= kWrapSides;
    rateAppearance(face, &out);
    return out;
}

} // namespace toonface
