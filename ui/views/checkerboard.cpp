#include "views/checkerboard.h"

#include <QPainter>

namespace toonface {

void paintCheckerboard(QPainter *painter, const QRect &rect, int cell)
{
    painter->save();
    painter->setClipRect(rect);
    painter->fillRect(rect, QColor(255, 255, 255));
    for (int y = rect.top(); y <= rect.bottom(); y += cell) {
        for (int x = rect.left(); x <= rect.right(); x += cell) {
            if (((x - rect.left()) / cell + (y - rect.top()) / cell) % 2)
                painter->fillRect(QRect(x, y, cell, cell), QColor(204, 204, 204));
        }
    }
    painter->restore();
}

} // namespace toonface
