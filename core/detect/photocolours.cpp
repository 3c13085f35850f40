#include "detect/photocolours.h"

#include "detect/appearance.h"
#include "detect/browlook.h"
#include "detect/colourbalance.h"
#include "detect/labcolour.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "render/svgbody.h"

#include <QImage>
#include <QLineF>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace toonface {

namespace {

// Measured brow thickness is drawn within these line weights (ES0/100): thinner is a brow not
// seen (too light or under a fringe), thicker is hair or a shadow.
constexpr double kMinBrowWidth = 2.5;
constexpr double kMaxBrowWidth = 8.0;
constexpr double kHairDepthReach = 1.2; // ES0: how deep into the hair its colour is sampled, at most
constexpr double kSameHair = 80.0; // RGB distance within which facial hair is of a kind with the head's
constexpr double kNotHat = 60.0; // RGB distance from a hat's colour beyond which a pixel is not the hat
constexpr double kHairUnderHat = 0.15; // share of the hair band that must be neither hat, room nor skin
constexpr double kBrowSampleRadius = 0.04; // ES0: the discs sampled along a brow's line
constexpr double kBrowDark = 0.8; // a brow's pixel is darker than this share of the skin's grey
constexpr double kBrowShown = 0.2; // share of the brow's samples that must be dark for its colour to be read
constexpr double kBrowContrast = 0.6; // a brow is drawn at most this share of the skin's grey
// The iris's radius (ES0): a grown person's iris is about 11.7 mm across and the pupils 63 mm apart.
constexpr double kIrisRadius = 0.093;
constexpr double kIrisMinChroma = 0.1; // HSV saturation a light iris has at least (a white eye's is less)
// How much of the light's colour, read off the white of the eye, is taken out of the iris's. Of
// 0.5, 0.75 and 1, compared on the 114 faces of faces-attributes whose irises could be labelled by
// eye, read without the photo's balance (light irises read cool 24, 26, 27 of 31; brown ones
// read cool 2, 3, 6 of 73): 0.75; 1 takes the pink of a bloodshot white for a cast. As shipped
// (likeness.eyes): light irises drawn cool 26 of 31 (20 before), brown ones 2 of 73 (3 before).
constexpr double kIrisAdaptation = 0.75;
constexpr double kLightIrisL = 50.0; // L*: a light iris drawn at least this light
constexpr double kLightIrisChroma = 1.5; // ... its colour this much stronger
constexpr double kLightIrisMaxChroma = 30.0; // ... up to this Lab chroma
// Grey or white hair is drawn only on a face the age models (agegroup.h) take for no child's and
// give at least this chance of being elderly (of not being a child): on the younger, strands
// read grey were a shine on dark hair or the wall through it (17 % of black-haired heads drawn
// grey). Fitted by leave-one-out over the 25 labelled faces (of 126) whose strands were drawn grey
// and decided no child: right on 21 held out against 14 without it (thresholds 0.27-0.30; the
// age models are fitted on the same faces, so this is in-sample for them).
constexpr double kGreyHairElderly = 0.287;
// ... unless the strands read white: no dark head of those faces read lighter than L* 60 here
// (the shine and the wall read mid-grey), white and silver hair 63 to 85.
constexpr double kWhiteHairL = 65.0;
// Such hair is dark: drawn in the brows' hue at most this light (L*), the median drawn for heads
// labelled black (20.0) and brown (20.7) over the labelled faces; faint brows read mid-brown.
constexpr double kDarkHairL = 21.0;

double hueDistance(double a, double b)
{
    const double d = std::abs(a - b);
    return std::min(d, 360.0 - d);
}

double rgbDistance(QColor a, QColor b)
{
    return std::hypot(a.red() - b.red(), a.green() - b.green(), a.blue() - b.blue());
}

// Pixels of the photo in a disc; clipped to the image.
class PixelSampler
{
public:
    explicit PixelSampler(const QImage &photo)
        : m_image(photo.convertToFormat(QImage::Format_RGB32))
    { }

    std::vector<QRgb> disc(QPointF centre, double radius) const
    {
        std::vector<QRgb> px;
        if (m_image.isNull() || !std::isfinite(centre.x()) || !std::isfinite(centre.y()))
            return px;
        const double r = std::max(radius, 1.0);
        const int x0 = std::max(0, int(std::floor(centre.x() - r)));
        const int x1 = std::min(m_image.width() - 1, int(std::ceil(centre.x() + r)));
        const int y0 = std::max(0, int(std::floor(centre.y() - r)));
        const int y1 = std::min(m_image.height() - 1, int(std::ceil(centre.y() + r)));
        for (int y = y0; y <= y1; ++y) {
            const auto *line = reinterpret_cast<const QRgb *>(m_image.constScanLine(y));
            for (int x = x0; x <= x1; ++x) {
                if (std::hypot(x + 0.5 - centre.x(), y + 0.5 - centre.y()) <= r)
                    px.push_back(line[x]);
            }
        }
        return px;
    }

private:
    QImage m_image;
};

int medianOf(std::vector<int> v)
{
    auto mid = v.begin() + v.size() / 2;
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// Per-channel median; invalid colour for no pixels.
QColor medianColour(const std::vector<QRgb> &px)
{
    if (px.empty())
        return {};
    std::vector<int> r, g, b;
    r.reserve(px.size());
    g.reserve(px.size());
    b.reserve(px.size());
    for (QRgb p : px) {
        r.push_back(qRed(p));
        g.push_back(qGreen(p));
        b.push_back(qBlue(p));
    }
    return QColor(medianOf(r), medianOf(g), medianOf(b));
}

// Hair reads as the colour of its lit strands, not of the shadows between them: the median of
// the pixels between the 40th and 90th percentile of brightness (which also drops glints).
QColor litMedianColour(std::vector<QRgb> px)
{
    if (px.size() < 10)
        return medianColour(px);
    std::sort(px.begin(), px.end(), [](QRgb a, QRgb b) { return qGray(a) < qGray(b); });
    const auto from = px.begin() + qsizetype(px.size() * 0.4);
    const auto to = px.begin() + qsizetype(px.size() * 0.9);
    return medianColour(std::vector<QRgb>(from, to));
}

QColor medianColour(const std::vector<QColor> &colours)
{
    std::vector<QRgb> px;
    for (const QColor &c : colours) {
        if (c.isValid())
            px.push_back(c.rgb());
    }
    return medianColour(px);
}

QColor darkHairOf(const QColor &c)
{
    LabColour lab = labOf(c);
    lab.l = std::min(lab.l, kDarkHairL);
    return colourOfLab(lab);
}

// Hair read as strands (haircolour.h) is drawn in its shade's look as far as its call is sure;
// `seen` (the finder's plain median) where it read nothing. The head's hair's grey asks the
// face's age: grey strands on a face too young for grey hair (kGreyHairElderly) that do not
// read white (kWhiteHairL) are dark hair, drawn in `dark`'s hue (the brows'); on a face decided elderly they are grey
// hair, however near the colour's thresholds they read (grey hair over a dark room reads taupe), drawn as sure grey.
QColor drawnHeadHair(const HairColourReading &reading, const QColor &seen, const AgeDecision &age, const QColor &dark)
{
    if (!reading.valid)
        return seen;
    const HairShadeCall call = classifyHair(reading);
    if (call.shade != HairShade::Grey)
        return drawnHairColour(reading, call);
    const bool ageFits
        = reading.hair.l >= kWhiteHairL || (age.group != AgeGroup::Child && age.elderly >= kGreyHairElderly);
    if (!ageFits)
        return darkHairOf(dark);
    return drawnHairColour(reading, age.group == AgeGroup::Elderly ? HairShadeCall {HairShade::Grey, 1.0} : call);
}

// How much of the skin's chroma a beard's strands keep at most to be grey on an elderly face
// (photocolours.h, drawnFacialHair).
constexpr double kBeardGreyChroma = 0.75;

QColor mix(QColor a, QColor b, double t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t),
        float(a.greenF() + (b.greenF() - a.greenF()) * t), float(a.blueF() + (b.blueF() - a.blueF()) * t));
}

// A skin less saturated than this in a colour photo has lost its colour to the balance (HSV
// saturation).
constexpr double kGreySkin = 0.08;
// The skins drawn from the labelled faces (`toonface-bench likeness.attributes`, 161 photos of
// every tone) lie between these HSV hues (5th and 95th percentiles, degrees) and above this
// saturation (5th percentile): a skin sampled pinker or greyer than that is a cast the balance
// left (drawn as an ashen or mauve face), brought to the nearest natural skin of its lightness.
constexpr double kSkinHues[2] = {5.5, 29.3};
constexpr double kMinSkinSaturation = 0.18;

QColor naturalSkin(const QColor &c)
{
    double h = c.hsvHueF() * 360.0;
    if (h > 180.0)
        h -= 360.0;
    const double hue = std::clamp(h, kSkinHues[0], kSkinHues[1]);
    const double s = std::max(c.hsvSaturationF(), float(kMinSkinSaturation));
    if (hue == h && s == c.hsvSaturationF())
        return c;
    return QColor::fromHsvF(float((hue < 0 ? hue + 360.0 : hue) / 360.0), float(s), c.valueF());
}

bool plausibleSkin(QColor c)
{
    if (!c.isValid())
        return false;
    const double h = c.hsvHueF() * 360.0;
    const double s = c.hsvSaturationF();
    const double v = c.valueF();
    // Skin of any tone is a warm hue, never vivid, never near black.
    return v > 0.12 && s < 0.75 && (s < 0.12 || hueDistance(h, 25.0) < 45.0);
}

bool plausibleLips(QColor c, QColor skin)
{
    if (!c.isValid())
        return false;
    const double h = c.hsvHueF() * 360.0;
    return c.valueF() > 0.15 && hueDistance(h, 5.0) < 40.0 && rgbDistance(c, skin) > 10.0;
}

// An iris is dark, or light but coloured in a hue no skin has (blue, green, grey-blue): a light
// warm or colourless reading is a lid or the white of the eye, not an iris. Light irises used to
// be refused whenever lighter than 0.7, and were drawn in the preset's brown.
bool plausibleIris(QColor c)
{
    if (!c.isValid())
        return false;
    const double h = c.hsvHueF() * 360.0;
    return c.valueF() < 0.7 || (c.hsvSaturationF() > kIrisMinChroma && hueDistance(h, 25.0) > 45.0);
}

// How a light iris is drawn: a blue, green or grey iris reads in a photo as a dull mid grey (its
// lit stroma beside the dark rim and the pupil's edge), which on a small cartoon eye reads as
// dark; a cartoonist paints it light and clear. An iris that is neither near black nor of a brown
// hue (orange to yellow) is drawn at least kLightIrisL light with its colour
// kLightIrisChroma times as strong (at most kLightIrisMaxChroma); a brown or dark one as it is.
QColor drawnIris(const QColor &iris)
{
    LabColour lab = labOf(iris);
    const double chroma = std::hypot(lab.a, lab.b);
    const double hue = std::fmod(std::atan2(lab.b, lab.a) * 180.0 / std::numbers::pi + 360.0, 360.0);
    // A warm grey (a brown hue, too faint to call) is left as read: lifted and strengthened it
    // turns a light brown.
    if (lab.l < 30 || (hue >= 20 && hue <= 100))
        return iris;
    const double k = chroma > 1e-6 ? std::min(kLightIrisChroma, kLightIrisMaxChroma / chroma) : 1.0;
    lab.a *= k;
    lab.b *= k;
    lab.l = std::max(lab.l, kLightIrisL);
    return colourOfLab(lab);
}

// The iris's own colour. The eyeball point is the middle of the eye's six outline points, not of
// the iris: a disc there read the pupil, the lashes' shadow under the upper lid and the iris
// together. Here the iris is first found along the line between the corners (the darkest spot:
// the pupil), then read on a ring around it between the pupil and the rim, on its sides and
// below (the upper lid shades its top), the brightest fifth of the ring (glints, white beyond a
// small iris) left out.
std::vector<QRgb> irisRing(const PixelSampler &sampler, QPointF outer, QPointF inner, QPointF ball, double es0)
{
    const double r = std::max(1.5, kIrisRadius * es0);
    const double probe = std::max(1.0, 0.45 * r);
    QPointF centre = ball;
    double darkest = 1e9;
    for (int k = 0; k <= 12; ++k) {
        const QPointF on = outer + (inner - outer) * (0.2 + 0.6 * k / 12.0);
        const QPointF at(on.x(), ball.y() + (on.y() - (outer.y() + inner.y()) / 2.0));
        const auto px = sampler.disc(at, probe);
        if (px.empty())
            continue;
        double grey = 0;
        for (QRgb c : px)
            grey += qGray(c);
        grey /= double(px.size());
        if (grey < darkest) {
            darkest = grey;
            centre = at;
        }
    }
    std::vector<QRgb> ring;
    for (double degrees : {0.0, 180.0, 20.0, 160.0, 45.0, 135.0, -15.0, 195.0}) {
        const double a = degrees * std::numbers::pi / 180.0; // image y points down: 90 is below
        const auto disc = sampler.disc(centre + QPointF(std::cos(a), std::sin(a)) * (0.65 * r), std::max(1.0, 0.2 * r));
        ring.insert(ring.end(), disc.begin(), disc.end());
    }
    std::sort(ring.begin(), ring.end(), [](QRgb a, QRgb b) { return qGray(a) < qGray(b); });
    ring.resize(ring.size() - ring.size() / 5);
    return ring;
}

// The white of the eye: the brightest 30 % of small discs along the line between the corners,
// beside the middle (where the iris is).
std::vector<QRgb> scleraSample(const PixelSampler &sampler, QPointF outer, QPointF inner, double eyeHeight)
{
    std::vector<QRgb> px;
    for (int k = -4; k <= 4; ++k) {
        if (k == 0)
            continue;
        const auto disc = sampler.disc(outer + (inner - outer) * (0.5 + 0.09 * k), std::max(1.0, 0.15 * eyeHeight));
        px.insert(px.end(), disc.begin(), disc.end());
    }
    std::sort(px.begin(), px.end(), [](QRgb a, QRgb b) { return qGray(a) > qGray(b); });
    px.resize(px.size() * 3 / 10);
    return px;
}

// Both irises' colour, seen as under white light: the light in the eyes (a pink room, a warm
// lamp) is read off the white of the eye and taken out per channel (kIrisAdaptation of the way),
// since a grey-blue iris in warm light reads brown. Invalid when nothing could be sampled.
QColor irisColour(const PixelSampler &sampler, const FaceModel &face, double es0)
{
    auto p = [&](const char *id) { return face.point(id); };
    std::vector<QRgb> iris = irisRing(sampler, p("3.12"), p("3.8"), p("3.6"), es0);
    const auto right = irisRing(sampler, p("3.7"), p("3.11"), p("3.5"), es0);
    iris.insert(iris.end(), right.begin(), right.end());
    std::vector<QRgb> white = scleraSample(sampler, p("3.12"), p("3.8"), QLineF(p("3.2"), p("3.4")).length());
    const auto whiteRight = scleraSample(sampler, p("3.7"), p("3.11"), QLineF(p("3.1"), p("3.3")).length());
    white.insert(white.end(), whiteRight.begin(), whiteRight.end());
    const QColor seen = medianColour(iris);
    const QColor light = medianColour(white);
    if (!seen.isValid() || !light.isValid())
        return seen;
    const double mean = (light.red() + light.green() + light.blue()) / 3.0;
    auto adapt = [&](int channel, int lightChannel) {
        return std::clamp(
            int(std::lround(channel * std::pow(mean / std::max(lightChannel, 1), kIrisAdaptation))), 0, 255);
    };
    return QColor(adapt(seen.red(), light.red()), adapt(seen.green(), light.green()), adapt(seen.blue(), light.blue()));
}

QPointF unitVector(QPointF v)
{
    const double l = std::hypot(v.x(), v.y());
    return l > 1e-9 ? v / l : QPointF();
}

// The clothes: left and right of the neck, a little under the neckline, where shirts and jackets
// are. A photo with no room under the chin for the neck shows no body; one whose sample falls
// outside the photo keeps the default colour.
void sampleClothes(
    const PixelSampler &sampler, const FaceModel &face, double es0, int photoHeight, ComponentStyle *body)
{
    const QPointF chin = face.point("2.1");
    const double width = face.point("2.13").x() - face.point("2.14").x();
    if (photoHeight - chin.y() < svgparts::kBodyRoomBelowChin * es0) {
        body->visible = false;
        return;
    }
    const double y = chin.y() + 1.1 * es0;
    const double r = 0.22 * es0;
    std::vector<QRgb> px;
    for (double side : {-1.0, 1.0}) {
        const QPointF c(chin.x() + side * 0.75 * width, y);
        if (c.y() + r < photoHeight) {
            const auto disc = sampler.disc(c, r);
            px.insert(px.end(), disc.begin(), disc.end());
        }
    }
    if (px.size() < 8)
        return;
    const QColor clothes = medianColour(px);
    body->fill = clothes;
    body->stroke = clothes.lightnessF() < 0.25 ? clothes.lighter(160) : clothes.darker(170);
}

// The brows' colour as the photo shows it: along each brow's line (and a little under it, where
// the brow's body is when the points sit on its upper edge), the pixels clearly darker than the
// skin; their darker half's median, which is the brow and not its thin edge blending into skin.
// Invalid when too few of them are dark (brows too light or hidden to say).
QColor browColour(const PixelSampler &sampler, const FaceModel &face, const QColor &skin, double es0)
{
    const double radius = std::max(1.0, kBrowSampleRadius * es0);
    const int skinGrey = qGray(skin.rgb());
    std::vector<QRgb> all, dark;
    for (const auto &brow : {std::array {"4.6", "4.4a", "4.4", "4.2"}, std::array {"4.1", "4.3", "4.3a", "4.5"}}) {
        for (size_t i = 0; i + 1 < brow.size(); ++i) {
            const QPointF a = face.point(brow[i]), b = face.point(brow[i + 1]);
            const int steps = std::max(1, int(QLineF(a, b).length() / radius));
            for (int k = 0; k < steps; ++k) {
                const QPointF at = a + (b - a) * (double(k) / steps) + QPointF(0, 0.5 * radius);
                for (QRgb c : sampler.disc(at, radius)) {
                    all.push_back(c);
                    if (qGray(c) < kBrowDark * skinGrey)
                        dark.push_back(c);
                }
            }
        }
    }
    if (all.empty() || double(dark.size()) < kBrowShown * double(all.size()))
        return {};
    std::sort(dark.begin(), dark.end(), [](QRgb a, QRgb b) { return qGray(a) < qGray(b); });
    dark.resize((dark.size() + 1) / 2);
    return medianColour(dark);
}

} // namespace

QColor drawnFacialHair(
    const HairColourReading &reading, const QColor &seen, const AgeDecision &age, const QColor &dark, bool *grey)
{
    *grey = false;
    if (!reading.valid)
        return seen;
    const HairShadeCall call = classifyHair(reading);
    const bool paleStrands = age.group == AgeGroup::Elderly && reading.hair.l >= HairShadeRules::fitted().greyL
        && reading.chroma() < kBeardGreyChroma * std::hypot(reading.skin.a, reading.skin.b);
    if (call.shade == HairShade::Grey && !paleStrands) {
        // As the head's: grey strands on a face too young for grey hair that do not read white
        // are dark stubble over the skin (a young man's dark beard on medium skin reads L* 40 and
        // grey), drawn dark.
        const bool ageFits
            = reading.hair.l >= kWhiteHairL || (age.group != AgeGroup::Child && age.elderly >= kGreyHairElderly);
        if (!ageFits)
            return darkHairOf(dark);
    }
    *grey = call.shade == HairShade::Grey || paleStrands;
    return drawnHairColour(reading, paleStrands ? HairShadeCall {HairShade::Grey, 1.0} : call);
}

void sampleColours(const QImage &original, const FaceModel &face, Style *style, AppearanceFindings *findings)
{
    QMap<QString, ComponentStyle> &components = style->components;
    Appearance &appearance = style->appearance;
    if (original.isNull())
        return;
    if (components.isEmpty())
        components = Style::baseComponents();
    // Every colour is read from the photo with its colour cast taken out, as seen around the head.
    const QRectF head = face.bounds();
    const ColourBalance balance = ColourBalance::measure(
        original, head.adjusted(-head.width(), -0.5 * head.height(), head.width(), 0.5 * head.height()));
    const QImage photo = balance.apply(original);
    const PixelSampler sampler(photo);
    const Fapu f = Fapu::measure(face);
    const double es0 = f.es0 > 0 ? f.es0 : std::max(1.0, face.bounds().width() / 2.5);
    auto p = [&](const char *id) { return face.point(id); };
    auto regionMedian = [&](QPointF c, double r) { return medianColour(sampler.disc(c, r)); };

    // Skin: the median of five region medians (cheeks, forehead, nose bridge, chin), so a fringe,
    // a beard or a shadow on one of them does not decide.
    const double rs = 0.07 * es0;
    const QPointF leftCheek = (p("3.4") + p("8.4") + p("5.2") + p("9.2")) / 4.0;
    const QPointF rightCheek = (p("3.3") + p("8.3") + p("5.1") + p("9.1")) / 4.0;
    const QPointF browMid = (p("4.2") + p("4.1")) / 2.0;
    const QPointF forehead = browMid + (p("11.1") - browMid) * 0.45;
    const QPointF bridge = (p("9.14") + p("9.13") + p("9.6") + p("9.7")) / 4.0;
    const QPointF chin = (p("8.2") + p("2.1") * 2.0) / 3.0;
    const QColor skin = medianColour(std::vector<QColor> {regionMedian(leftCheek, rs), regionMedian(rightCheek, rs),
        regionMedian(forehead, rs), regionMedian(bridge, rs * 0.6), regionMedian(chin, rs * 0.6)});
    // A photo without colour says nothing about hues: skin and hair take natural colours of the
    // photo's tones, lips follow the skin and the irises a dark brown.
    const bool monochrome = balance.greyscale || original.allGray();
    // A skin sampled in a colour no skin has (a cast the balance left, a coloured light) still
    // tells the person's lightness: it is drawn as a natural skin of that tone, never as the
    // preset's pale skin (a dark-skinned face drawn pink).
    // So is a grey one in a colour photo (a balance that took a pale person's warmth for a cast).
    const bool skinOk = skin.isValid();
    const bool greyInColour = !monochrome && skinOk && skin.hsvSaturationF() < kGreySkin;
    const QColor skinDrawn = skinOk && (monochrome || greyInColour || !plausibleSkin(skin))
        ? skinFromGrey(qGray(skin.rgb()))
        : skinOk ? naturalSkin(skin)
                 : skin;
    const QColor skinUsed = skinOk ? skinDrawn : components.value(QStringLiteral("face")).fill;
    if (skinOk) {
        for (const char *key : {"face", "jaw", "ears"})
            components[QLatin1StringView(key)].fill = skinDrawn;
    }

    // Hair: a band inside the outline h.3..h.17, a quarter and half way to the hairline;
    // compared with a band just outside, so a hair outline drawn around background is noticed.
    const QPointF centre = (p("11.1") + p("2.1")) / 2.0;
    const QPointF hairline[] = {p("11.2"), p("11.1"), p("11.3"), p("5.2"), p("5.1")};
    std::vector<QRgb> inside, outside;
    for (int k = 3; k <= 17; ++k) {
        const QPointF h = face.point(pt::idx("h.1") + k - 1); // h.1..h.19 are consecutive
        double gap = 1e300;
        for (const QPointF &q : hairline)
            gap = std::min(gap, QLineF(h, q).length());
        const QPointF in = unitVector(centre - h);
        const double thickness = std::min(gap, 0.5 * es0);
        if (thickness < 3.0)
            continue;
        const double radius = std::max(1.0, 0.12 * thickness);
        // A quarter and half way into the hair, however thick: the edge of big hair is wisps over
        // the background, darker than the hair (or lighter than dark hair on a light wall).
        const double depthOf = std::min(gap, kHairDepthReach * es0);
        for (double depth : {0.25 * depthOf, 0.5 * depthOf}) {
            const auto a = sampler.disc(h + in * depth, radius);
            inside.insert(inside.end(), a.begin(), a.end());
        }
        const auto b = sampler.disc(h - in * (0.12 * es0), radius);
        outside.insert(outside.end(), b.begin(), b.end());
    }
    const QColor hairSeen = litMedianColour(inside);
    const QColor background = medianColour(outside);
    bool hairOk = hairSeen.isValid();
    if (hairOk && background.isValid()) {
        const auto nearBackground = std::count_if(
            inside.begin(), inside.end(), [&](QRgb c) { return rgbDistance(QColor(c), background) < 40.0; });
        hairOk = nearBackground * 2 < qsizetype(inside.size());
    }
    if (hairOk && rgbDistance(hairSeen, skin) < 30.0)
        hairOk = false; // bald or the band fell on the forehead
    QColor hair = hairOk && monochrome ? hairFromGrey(qGray(hairSeen.rgb())) : hairSeen;
    auto setBrows = [&](const QColor &brow) {
        components[QStringLiteral("eyebrows")].fill = brow;
        components[QStringLiteral("eyebrows")].stroke = brow;
    };
    auto setHair = [&](const QColor &c) {
        components[QStringLiteral("hair")].fill = c;
        components[QStringLiteral("hair")].stroke = c.darker(170);
        setBrows(c.valueF() > 0.45 ? c.darker(150) : c.darker(120));
    };
    if (hairOk)
        setHair(hair);

    // Brow colour: the brows' own pixels where they show, so a bald head, a hat or a hair colour
    // unlike the brows' does not decide it (the hair's colour stays for brows too light to show).
    const QColor browSeen = skin.isValid() ? browColour(sampler, face, skin, es0) : QColor();
    // Brow thickness: the unbroken run of pixels clearly darker than the skin through each brow's
    // middle, up and down from it (a shadow or a lid apart from the brow does not count).
    if (skin.isValid()) {
        std::vector<int> runs;
        auto dark = [&](QPointF q) {
            const auto px = sampler.disc(q, 0.5);
            return !px.empty() && qGray(px.front()) < kBrowDark * qGray(skin.rgb());
        };
        for (const auto &[a, b] : {std::pair {"4.4a", "4.4"}, std::pair {"4.3", "4.3a"}}) {
            const QPointF mid = (p(a) + p(b)) / 2.0;
            int run = 0;
            for (int dir : {-1, 1}) {
                for (double d = dir > 0 ? 1.0 : 0.0; d <= 0.12 * es0 && dark(mid + QPointF(0, dir * d)); d += 1.0)
                    ++run;
            }
            runs.push_back(run);
        }
        const double thickness = (runs[0] + runs[1]) / 2.0 / (es0 / 100.0); // in ES0/100
        if (thickness >= kMinBrowWidth)
            components[QStringLiteral("eyebrows")].strokeWidth = std::min(thickness, kMaxBrowWidth);
    }

    // What the person wears or grows, found on the balanced photo against its own skin.
    AppearanceFindings found = findAppearance(photo, face, skin);
    found.ageEvidence = measureAgeEvidence(photo, face);
    found.age = decideAge(found.ageEvidence);
    found.appearance.age = found.age.group;
    if (findings)
        *findings = found;
    appearance = found.appearance;
    // The parse of the head saw the hair as a whole (the person's pixels other than skin over the
    // forehead, or beside the temples in a tight crop): its median is the hair's own colour, where
    // the band inside the outline may have caught the room or the skin.
    // Seen only beside the temples (a tight crop) and far lighter than the skin (kRoomLighter,
    // headparse.h: the parse leaves the fall of such a sample out too), that "hair" is
    // more often the room or a shine on dark skin than grey or blond hair, and the band inside the
    // outline read the same place: the hair is drawn in the brows' colour instead (most people's
    // brows are of their hair's colour), or the preset's. Not on a face the age models take for an
    // elderly person's (as grey hair asks, drawnHeadHair): there the light sample is grey or white
    // hair, most of all on dark skin, where grey hair is far lighter than the cheeks. Of the 21
    // labelled crops so sampled, this draws light 4 whose hair is grey or white (fa_s096, s104,
    // s140, s146; s096 is labelled black, its photo shows short grey hair) and one young man's
    // black hair whose age the models get wrong (s078); the age threshold is grey hair's own.
    const bool agedGrey = found.age.group != AgeGroup::Child && found.age.elderly >= kGreyHairElderly;
    const bool lightBesideTemples
        = found.templeHairSeen && skinOk && !agedGrey && labOf(found.parsedHair).l - labOf(skin).l > kRoomLighter;
    const QColor browsOrPreset = !browSeen.isValid() ? Style::baseComponents().value(QStringLiteral("hair")).fill
        : monochrome                                 ? hairFromGrey(qGray(browSeen.rgb()))
                                                     : browSeen;
    if (lightBesideTemples) {
        hairOk = false;
        hair = browsOrPreset;
        setHair(hair);
    }
    if (found.parsedHair.isValid() && !appearance.bald && !appearance.hat && !lightBesideTemples) {
        hair = monochrome ? hairFromGrey(qGray(found.parsedHair.rgb()))
                          : drawnHeadHair(found.hairReading, found.parsedHair, found.age, browsOrPreset);
        hairOk = true;
        setHair(hair);
    }
    if (found.hat.isValid()) {
        const QColor hat = monochrome ? hairFromGrey(qGray(found.hat.rgb())) : found.hat;
        components[QStringLiteral("hat")].fill = hat;
        components[QStringLiteral("hat")].stroke = hat.darker(160);
        // The hair band, when it saw no room, fell mostly on the hat: the hair is what of it is
        // neither the hat's colour nor the room's nor skin, else the hair seen beside the
        // temples, else the preset's.
        if (hairOk) {
            std::vector<QRgb> rest;
            std::copy_if(inside.begin(), inside.end(), std::back_inserter(rest), [&](QRgb c) {
                return rgbDistance(QColor(c), found.hat) >= kNotHat
                    && (!background.isValid() || rgbDistance(QColor(c), background) >= 40.0)
                    && rgbDistance(QColor(c), skin) >= 30.0;
            });
            QColor under;
            if (double(rest.size()) >= kHairUnderHat * double(inside.size()))
                under = litMedianColour(rest);
            else if (found.templeHair.isValid())
                under = found.templeHair;
            if (under.isValid() && monochrome)
                under = hairFromGrey(qGray(under.rgb()));
            hairOk = under.isValid();
            hair = hairOk ? under : Style::baseComponents().value(QStringLiteral("hair")).fill;
            setHair(hair);
        }
    }
    // Brows seen in a colour of their own (a bald or hatted head's, brows unlike the hair) are
    // drawn in it, dark enough against the skin to read as brows.
    if (browSeen.isValid() && !(hairOk && rgbDistance(browSeen, hair) < kSameHair)) {
        QColor brow = monochrome ? hairFromGrey(qGray(browSeen.rgb())) : browSeen;
        const double most = kBrowContrast * qGray(skinUsed.rgb());
        if (qGray(brow.rgb()) > most)
            brow = brow.darker(int(std::ceil(100.0 * qGray(brow.rgb()) / std::max(1.0, most))));
        setBrows(brow);
    }
    // How thick and how dark the brows are against this photo's skin (browlook.h): over the run
    // measured above, which is only kept where the brows do not show clearly.
    applyBrowLook(measureBrows(photo, face), skinUsed, &components[QStringLiteral("eyebrows")]);
    if (found.glassesFrame.isValid()) {
        const QColor frame = monochrome
            ? QColor(qGray(found.glassesFrame.rgb()), qGray(found.glassesFrame.rgb()), qGray(found.glassesFrame.rgb()))
            : found.glassesFrame;
        components[QStringLiteral("glasses")].stroke = frame;
    }
    if (found.facialHair.isValid()) {
        // In the person's hair colour where the hair was seen; stubble (not much darker than the
        // skin) is drawn see-through, grey or white hair as full as it is.
        bool greyRead = false;
        const QColor seen = monochrome
            ? hairFromGrey(qGray(found.facialHair.rgb()))
            : drawnFacialHair(found.facialHairReading, found.facialHair, found.age, browsOrPreset, &greyRead);
        if (monochrome)
            greyRead = found.facialHairReading.valid && classifyHair(found.facialHairReading).shade == HairShade::Grey;
        // Evened out with the head's hair when it is of a kind with it; a hair colour far from
        // it is another person's hair (a grey beard under dark hair) or the room the hair
        // outline strayed into around a shaved head, and is left out. Where both were read as
        // strands, of a kind means of one shade (a grey beard stays grey under brown hair).
        const bool bothRead = !monochrome && found.facialHairReading.valid && found.hairReading.valid;
        const HairShade beardShade = greyRead ? HairShade::Grey : classifyHair(found.facialHairReading).shade;
        const bool sameShade = !bothRead || beardShade == classifyHair(found.hairReading).shade;
        QColor fill = hairOk && sameShade && rgbDistance(seen, hair) < kSameHair ? mix(seen, hair, 0.5) : seen;
        const bool stubble
            = !found.lightFacialHair && !greyRead && qGray(found.facialHair.rgb()) > 0.55 * qGray(skin.rgb());
        const QColor stroke = fill.darker(140);
        if (stubble)
            fill.setAlpha(150);
        for (const char *key : {"moustache", "beard"}) {
            components[QLatin1StringView(key)].fill = fill;
            components[QLatin1StringView(key)].stroke = stroke;
        }
    }

    if (monochrome) {
        const QColor lipUsed = mix(skinUsed, QColor(0xc0, 0x50, 0x4d), 0.45);
        components[QStringLiteral("lips")].fill = lipUsed;
        components[QStringLiteral("lips")].stroke = lipUsed.darker(150);
        components[QStringLiteral("eyeballs")].fill = QColor(0x5a, 0x3d, 0x2b);
        return;
    }

    // Lips: the middle of each lip.
    const double rl = std::max(1.0, 0.3 * std::min(f.upperLipH, f.lowerLipH));
    const QColor lips = medianColour(std::vector<QColor> {regionMedian((p("8.1") + p("2.2")) / 2.0, rl),
        regionMedian((p("2.3") + p("8.2")) / 2.0, rl),
        regionMedian(((p("8.9") + p("8.4")) / 2.0 + (p("8.4") + p("2.2")) / 2.0) / 2.0, rl)});
    const QColor lipUsed = plausibleLips(lips, skinUsed) ? lips : mix(skinUsed, QColor(0xc0, 0x50, 0x4d), 0.45);
    components[QStringLiteral("lips")].fill = lipUsed;
    components[QStringLiteral("lips")].stroke = lipUsed.darker(150);

    // Iris: a ring around each pupil, in white light (irisColour).
    const QColor iris = irisColour(sampler, face, es0);
    if (plausibleIris(iris))
        components[QStringLiteral("eyeballs")].fill = drawnIris(iris); // judged as read, drawn lifted

    sampleClothes(sampler, face, es0, photo.height(), &components[QStringLiteral("body")]);
    // Expression lines are a shadow of the skin, so they show on every skin tone.
    QColor crease = skinUsed.darker(190);
    crease.setAlpha(
        components.value(QStringLiteral("creases"), Style::baseComponents().value(QStringLiteral("creases")))
            .fill.alpha());
    components[QStringLiteral("creases")].fill = crease;
}

} // namespace toonface
