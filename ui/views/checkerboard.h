#pragma once

#include <QRect>

class QPainter;

namespace toonface {

// The checkerboard behind transparent pixels, as image editors show it: `cell`-pixel squares of
// white and light grey from the rectangle's top left. The export's preview and the editor's
// transparent view both draw it.
void paintCheckerboard(QPainter *painter, const QRect &rect, int cell = 8);

} // namespace toonface
