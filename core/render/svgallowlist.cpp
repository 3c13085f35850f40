#include "render/svgallowlist.h"

#include <QRegularExpression>
#include <QSet>

namespace toonface::svgallow {

namespace {

QSet<QString> setOf(std::initializer_list<const char *> names)
{
    QSet<QString> out;
    for (const char *n : names)
        out.insert(QString::fromLatin1(n));
    return out;
}

// Lower case, without the white space and control characters a browser skips inside a URL's
// scheme ("java\tscript:").
QString squeezed(QStringView value)
{
    QString out;
    out.reserve(value.size());
    for (const QChar c : value) {
        if (c.unicode() > 0x20)
            out.append(c.toLower());
    }
    return out;
}

} // namespace

bool isDrawingElement(QStringView name)
{
    static const QSet<QString> allowed = setOf({"svg", "g", "defs", "symbol", "use", "switch", "path", "rect", "circle",
        "ellipse", "line", "polyline", "polygon", "text", "tspan", "textPath", "title", "desc", "linearGradient",
        "radialGradient", "stop", "pattern", "clipPath", "mask", "marker", "image", "style", "filter", "feBlend",
        "feColorMatrix", "feComponentTransfer", "feComposite", "feConvolveMatrix", "feDiffuseLighting",
        "feDisplacementMap", "feDistantLight", "feDropShadow", "feFlood", "feFuncA", "feFuncB", "feFuncG", "feFuncR",
        "feGaussianBlur", "feImage", "feMerge", "feMergeNode", "feMorphology", "feOffset", "fePointLight",
        "feSpecularLighting", "feSpotLight", "feTile", "feTurbulence"});
    return allowed.contains(name.toString());
}

bool isDrawingAttribute(QStringView name)
{
    static const QSet<QString> allowed = setOf({"id", "class", "style", "transform", "transform-origin", "x", "y", "x1",
        "y1", "x2", "y2", "cx", "cy", "r", "rx", "ry", "fx", "fy", "fr", "width", "height", "d", "points", "pathLength",
        "viewBox", "preserveAspectRatio", "version", "baseProfile", "offset", "gradientUnits", "gradientTransform",
        "spreadMethod", "patternUnits", "patternContentUnits", "patternTransform", "clipPathUnits", "maskUnits",
        "maskContentUnits", "markerUnits", "markerWidth", "markerHeight", "refX", "refY", "orient", "filterUnits",
        "primitiveUnits", "in", "in2", "result", "stdDeviation", "dx", "dy", "mode", "operator", "k1", "k2", "k3", "k4",
        "values", "type", "tableValues", "slope", "intercept", "amplitude", "exponent", "baseFrequency", "numOctaves",
        "seed", "stitchTiles", "scale", "xChannelSelector", "yChannelSelector", "radius", "order", "kernelMatrix",
        "divisor", "bias", "targetX", "targetY", "edgeMode", "kernelUnitLength", "preserveAlpha", "surfaceScale",
        "diffuseConstant", "specularConstant", "specularExponent", "azimuth", "elevation", "z", "pointsAtX",
        "pointsAtY", "pointsAtZ", "limitingConeAngle", "flood-color", "flood-opacity", "lighting-color", "stop-color",
        "stop-opacity", "fill", "fill-opacity", "fill-rule", "stroke", "stroke-width", "stroke-opacity",
        "stroke-linecap", "stroke-linejoin", "stroke-miterlimit", "stroke-dasharray", "stroke-dashoffset", "opacity",
        "color", "display", "visibility", "clip-path", "clip-rule", "mask", "filter", "marker-start", "marker-mid",
        "marker-end", "font-family", "font-size", "font-weight", "font-style", "font-variant", "font-stretch",
        "text-anchor", "dominant-baseline", "alignment-baseline", "baseline-shift", "letter-spacing", "word-spacing",
        "text-decoration", "writing-mode", "direction", "unicode-bidi", "lengthAdjust", "textLength", "rotate",
        "startOffset", "method", "spacing", "side", "vector-effect", "shape-rendering", "image-rendering",
        "text-rendering", "color-interpolation", "color-interpolation-filters", "mix-blend-mode", "isolation",
        "paint-order", "overflow", "href"});
    return allowed.contains(name.toString());
}

bool isInternalLink(QStringView value, bool pictureAllowed)
{
    const QString v = squeezed(value);
    if (v.startsWith(QLatin1Char('#')))
        return true;
    if (!pictureAllowed)
        return false;
    static const QRegularExpression picture(QStringLiteral("^data:image/(png|jpeg|gif|webp)[;,]"));
    return picture.match(v).hasMatch();
}

bool isInertCss(QStringView text)
{
    // An escape or an at-rule is refused whole: a layer's drawing never needs either.
    if (text.contains(QLatin1Char('\\')) || text.contains(QLatin1Char('@')))
        return false;
    QString v = text.toString().toLower();
    static const QRegularExpression comment(
        QStringLiteral("/\\*.*?(\\*/|$)"), QRegularExpression::DotMatchesEverythingOption);
    v.replace(comment, QStringLiteral(" "));
    const QString s = squeezed(v);
    if (s.contains(QLatin1StringView("javascript:")) || s.contains(QLatin1StringView("vbscript:"))
        || s.contains(QLatin1StringView("data:")))
        return false;
    static const QSet<QString> functions = setOf({"rgb", "rgba", "hsl", "hsla", "hwb", "lab", "lch", "oklab", "",
        "oklch", "color", "translate", "translatex", "translatey", "rotate", "scale", "scalex", "scaley", "matrix",
        "skewx", "skewy", "calc", "min", "max", "clamp", "url", "blur", "brightness", "contrast", "drop-shadow",
        "grayscale", "hue-rotate", "invert", "opacity", "saturate", "sepia"});
    static const QRegularExpression function(QStringLiteral("([-a-z0-9_]*)\\s*\\("));
    for (auto it = function.globalMatch(v); it.hasNext();) {
        if (!functions.contains(it.next().captured(1)))
            return false;
    }
    // url() only of the file's own elements: "url(#id)", quoted or not.
    static const QRegularExpression url(QStringLiteral("url\\(\\s*(['\"]?)\\s*([^'\")\\s]*)"));
    for (auto it = url.globalMatch(v); it.hasNext();) {
        if (!it.next().captured(2).startsWith(QLatin1Char('#')))
            return false;
    }
    return true;
}

} // namespace toonface::svgallow
