#include "render/svgbody.h"

namespace toonface::svgparts {

namespace {

// Proportions: widths in face widths (between the jaw sides 2.14 and 2.13), heights in ES0.
constexpr double kNeckHalfWidth = 0.33;
constexpr double kNeckFlare = 1.08; // the neck a little wider where it meets the clothes
constexpr double kNeckLength = 0.55; // from the chin to the neckline's sides
constexpr double kNecklineDip = 0.3; // how far the neckline's middle hangs below its sides
constexpr double kShoulderHalfWidth = 1.2;
constexpr double kShoulderDrop = 0.6; // the shoulders' round below the neckline's sides
constexpr double kBodyDepth = 6.0; // how far the clothes reach down: beyond any frame

} // namespace

std::vector<Part> makeBody(const Pt &P, double es0)
{
    const QPointF left = P("2.14"), right = P("2.13"), chin = P("2.1");
    const double width = std::max(right.x() - left.x(), 1e-6);
    const double mx = (left.x() + right.x()) / 2.0;
    const double top = (left.y() + right.y()) / 2.0; // behind the jaw
    const double neckline = chin.y() + kNeckLength * es0;
    const double bottom = chin.y() + kBodyDepth * es0;
    const double nw = kNeckHalfWidth * width;
    const double nb = nw * kNeckFlare;

    // The clothes: from the neck's sides down the slope of the shoulders, round them and down.
    const double slope = neckline - 0.12 * es0;
    const double sw = kShoulderHalfWidth * width;
    const double round = neckline + kShoulderDrop * es0;
    PathData clothes;
    clothes.moveTo({mx - nb, slope})
        .cubic(
            {{mx - nb, slope}, {mx - 0.65 * width, slope + 0.04 * es0}, {mx - sw, round - 0.3 * es0}, {mx - sw, round}})
        .lineTo({mx - sw * 1.04, bottom})
        .horizontalTo(mx + sw * 1.04)
        .lineTo({mx + sw, round})
        .cubic(
            {{mx + sw, round}, {mx + sw, round - 0.3 * es0}, {mx + 0.65 * width, slope + 0.04 * es0}, {mx + nb, slope}})
        .close();

    // The neck: its sides from behind the jaw down to the neckline, which dips between them.
    // Open at the top: the fill closes it behind the jaw, the stroke does not.
    const double dip = neckline + kNecklineDip * es0;
    PathData neck;
    neck.moveTo({mx - nw, top})
        .cubic({{mx - nw, top}, {mx - nw * 0.96, (top + neckline) / 2}, {mx - nb, neckline - 0.2 * es0},
            {mx - nb, neckline}})
        .cubic({{mx - nb, neckline}, {mx - nb * 0.7, dip}, {mx + nb * 0.7, dip}, {mx + nb, neckline}})
        .cubic({{mx + nb, neckline}, {mx + nb, neckline - 0.2 * es0}, {mx + nw * 0.96, (top + neckline) / 2},
            {mx + nw, top}});
    return {{"shoulders", false, "path", {{"d", clothes.data()}}, "body"},
        {"neck", false, "path", {{"d", neck.data()}}, "face"}};
}

} // namespace toonface::svgparts
