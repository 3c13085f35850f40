#pragma once

#include <QByteArray>
#include <QRectF>
#include <QString>

namespace toonface {

struct StyleLayer;

// A user's SVG file made safe to embed in the cartoon and in its exports, which a browser opens:
// the children of its root <svg>, inert. Left out: scripts, foreign objects and other active
// elements (with everything inside), event handler attributes (on...), links and references
// to anything outside the file (href to other files, web addresses, javascript: or data:
// documents other than images; url(...) and @import of other files in styles). Every id is
// prefixed with `idPrefix` (and every reference to it), so the layer's ids never clash with the
// face's ("mouth-inner", "head") or another layer's.
struct LayerDrawing
{
    QByteArray fragment; // the root's children, in the SVG namespace
    QRectF viewBox; // the root's viewBox, or (0, 0, width, height); (0, 0, 100, 100) when neither
};

// Returns false and sets *error (the problem, without the file's name) when the content is not
// an SVG document: not XML, or a root other than <svg>.
bool readLayerSvg(const QByteArray &content, const QString &idPrefix, LayerDrawing *out, QString *error);

// Reads a user's layer file for Style::layers: named after the file, its content as read, placed
// in the middle of the face `width` ES0 wide. On failure, *error names the file and the problem.
bool loadLayerFile(const QString &path, StyleLayer *out, QString *error);

} // namespace toonface
