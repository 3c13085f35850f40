#pragma once

#include "io/jsonfield.h"
#include "render/style.h"

#include <QJsonArray>

namespace toonface {

// The user's layers of a style in a project: [{name, svg, x, y, width, front, visible}], the SVG
// file's content held as text so the project needs no other file; x, y and width in ES0.
QJsonArray styleLayersToJson(const QVector<StyleLayer> &layers);

// A missing field gives no layers. Each layer's SVG must parse as an SVG document (the error
// names the field, e.g. "style.layers[1].svg: not an SVG drawing: line 1, column 7: ...").
bool styleLayersFromJson(const JsonField &field, QVector<StyleLayer> *layers, QString *error);

} // namespace toonface
