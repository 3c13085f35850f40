#include "detect/photopixels.h"

#include "face/fapu.h"

namespace toonface {

namespace {

constexpr double kDarkRatio = 0.72; // a pixel this much darker than the skin is hair-dark
// Luma units a hair's point stands out from its neighbours by (above rounding and a JPEG's faint noise).
constexpr double kSpeckleContrast = 3.0;

double darkShare(const std::vector<QRgb> &px, double skinLuma)
{
    if (px.empty())
        return 0;
    const auto n = std::count_if(px.begin(), px.end(), [&](QRgb p) { return lumaOf(p) < kDarkRatio * skinLuma; });
    return double(n) / double(px.size());
}

} // namespace

void findFacialHair(const Pixels &px, const FaceModel &face, double es0, double skinLuma, bool colourless,
    const QColor &skin, AppearanceFindings *out)
{
    auto p = [&](const char *id) { return face.point(id); };
    const Fapu f = face.fapu();
    // Moustache: between the nose's bottom and the upper lip, the lip's middle half wide.
    const double noseBottom = std::max({p("9.15").y(), p("9.4").y(), p("9.5").y()});
    const double lipTop = std::min({p("8.9").y(), p("8.1").y(), p("8.10").y()});
    const double gap = lipTop - noseBottom;
    std::vector<QRgb> lipHair, chinHair, jawHair;
    const double xl = p("8.4").x() + 0.2 * f.mw0, xr = p("8.3").x() - 0.2 * f.mw0;
    const QRectF lipBox(QPointF(xl, noseBottom + 0.35 * gap), QPointF(xr, lipTop - 0.1 * gap));
    if (gap > 2)
        lipHair = px.box(lipBox);
    // Beard: the chin below the lip's shadow, and both jaw sides inside the contour.
    const double jawH = p("2.1").y() - p("8.2").y();
    const QRectF chinBox = around(QPointF(p("2.1").x(), p("8.2").y() + 0.6 * jawH), 0.2 * f.mw0, 0.2 * jawH);
    if (jawH > 2) {
        const auto c = px.box(chinBox);
        chinHair.insert(chinHair.end(), c.begin(), c.end());
        const QPointF mid = (p("5.2") + p("5.1")) / 2.0;
        for (const char *side : {"2.12", "2.11"}) {
            const QPointF s = p(side) + (mid - p(side)) * 0.12;
            const auto j = px.box(around(s, 0.05 * es0, 0.05 * es0));
            chinHair.insert(chinHair.end(), j.begin(), j.end());
            jawHair.insert(jawHair.end(), j.begin(), j.end());
        }
    }
    // Texture and speckle, against the cheeks' under the eyes.
    {
        double cheeks = 0, cheekSpeckle = 0;
        for (bool left : {true, false}) {
            const QPointF outer = p(left ? "3.12" : "3.7"), inner = p(left ? "3.8" : "3.11");
            const QPointF ball = p(left ? "3.6" : "3.5");
            const QRectF cheek(QPointF(std::min(outer.x(), inner.x()), ball.y() + 0.5 * es0),
                QPointF(std::max(outer.x(), inner.x()), ball.y() + 0.62 * es0));
            cheeks += px.texture(cheek) / 2.0;
            cheekSpeckle += px.speckle(cheek, kSpeckleContrast) / 2.0;
        }
        cheeks += kEdgeFloor;
        if (gap > 2) {
            out->moustacheTexture = px.texture(lipBox) / cheeks;
            out->moustacheSpeckle = px.speckle(lipBox, kSpeckleContrast);
            out->cheekSpeckle = cheekSpeckle;
        }
        if (jawH > 2)
            out->beardTexture = px.texture(chinBox) / cheeks;
    }
    // Goatee: the chin alone, from under the lower lip's shadow to above the chin's point.
    std::vector<QRgb> goateeHair;
    if (jawH > 2)
        goateeHair = px.box(around(QPointF(p("2.1").x(), p("8.2").y() + 0.6 * jawH), 0.2 * f.mw0, 0.15 * jawH));
    out->goateeScore = darkShare(goateeHair, skinLuma);
    out->moustacheScore = darkShare(lipHair, skinLuma);
    out->beardScore = darkShare(chinHair, skinLuma);
    out->jawScore = darkShare(jawHair, skinLuma);
    // Hair, dark or not, is textured where skin is smooth: stubble and a sparse or grey beard are
    // a part darker than the skin with much more texture than the cheeks.
    auto stubble = [](double dark, double texture) {
        return dark >= AppearanceFindings::kStubbleDarkShare && texture >= AppearanceFindings::kStubbleTexture;
    };
    // Grey and white hair, no darker than the skin, still shows its strands: finer than a pixel
    // on a small face, many of the lip's pixels stand out from all their neighbours, where the
    // cheeks' are smooth.
    const bool speckled = out->moustacheSpeckle >= AppearanceFindings::kHairSpeckle
        && out->moustacheSpeckle >= AppearanceFindings::kSpeckleOverCheeks * out->cheekSpeckle;
    const bool darkMoustache = out->moustacheScore >= AppearanceFindings::kMoustacheThreshold
        || stubble(out->moustacheScore, out->moustacheTexture);
    // Hair is less red than the skin it grows from; a shadow under the nose or the lip, or a dark
    // jaw line, keeps the skin's redness. (Stubble seen only as a share of dark, textured pixels
    // is left out: on the labelled faces that rule drew stubble on clean-shaven men.) A faint loss on the lip counts
    // only where the lip or the chin shows it clearly. On the chin the hair is also textured. Without colour, the
    // strands (speckle) are the only evidence.
    const AppearanceEvidence &e = out->evidence;
    // Hair far darker than any shadow on the face is hair, whatever its colour.
    // On the lip, the colour unlike the cheeks as a whole (lightness, redness, yellowness) is the
    // evidence; some redness lost on the lip or the chin is asked too, as a shadow keeps it.
    const bool hairyLip = (e.lipColour >= AppearanceFindings::kLipColour
                              && std::max(e.lipRedLoss, e.chinRedLoss) >= AppearanceFindings::kRedLossSure)
        || e.lipDL <= -AppearanceFindings::kLipDarker;
    const bool hairyChin
        = (e.chinRedLoss >= AppearanceFindings::kChinRedLoss && e.chinDetail >= AppearanceFindings::kChinDetail)
        || e.chinDL <= -AppearanceFindings::kChinDarker;
    out->appearance.moustache = hairyLip || (colourless && speckled);
    // A beard covers the jaw's sides too; hair on the chin alone is a goatee.
    out->appearance.beard
        = hairyChin && (e.jawRedLoss >= AppearanceFindings::kJawRedLoss || e.jawDL <= -AppearanceFindings::kChinDarker);
    out->appearance.goatee = hairyChin && !out->appearance.beard;
    std::vector<QRgb> hair;
    if (out->appearance.moustache)
        hair.insert(hair.end(), lipHair.begin(), lipHair.end());
    if (out->appearance.beard)
        hair.insert(hair.end(), chinHair.begin(), chinHair.end());
    if (out->appearance.goatee)
        hair.insert(hair.end(), goateeHair.begin(), goateeHair.end());
    // Grey or white hair seen by its strands alone is the colour of most of it, not of the
    // shadows between the strands.
    out->lightFacialHair
        = out->appearance.moustache && !darkMoustache && !out->appearance.beard && !out->appearance.goatee;
    if (!hair.empty())
        out->facialHair = out->lightFacialHair ? median(hair) : darkest(hair, 0.5);
    // The colour to draw it in: the strands unlike the skin between them, told as a shade like
    // the head's hair (the darker half above is a shadow's colour on a grey or white beard).
    out->facialHairReading = readFacialHairColour(hair, skin);
}

} // namespace toonface
