#pragma once

#include <QString>
#include <QStringView>

// What a user's SVG layer may keep: the elements and attributes of static drawing, and the
// style text that refers to nothing outside the file. Everything else is left out by the layer
// reader (render/svglayer.cpp), which asks these questions of every element and attribute.
namespace toonface::svgallow {

// An SVG element of static drawing (shapes, text, paint servers, clipping, masking, filters):
// not script, animation, links to other documents, foreign content or fonts that load files.
bool isDrawingElement(QStringView name);

// An attribute without a namespace that drawing uses (geometry, paint, text, filters, ids).
bool isDrawingAttribute(QStringView name);

// A value of a link (href): to an element of the file itself ("#id"), or, on an <image> or
// <feImage>, a raster picture inside the file (data:image/png|jpeg|gif|webp).
bool isInternalLink(QStringView value, bool pictureAllowed);

// Whether CSS text (a style sheet, a style attribute, or a presentation attribute, which CSS
// parses too) is safe to keep: no escapes (a backslash hides "url" or "import" from a reader
// but not from a browser), no at-rules, no function but colour, transform and maths functions
// and url() of the file's own elements, no script URL.
bool isInertCss(QStringView text);

} // namespace toonface::svgallow
