#include "dialogs/exportpreview.h"

#include <QPainter>

namespace toonface {

ExportPreview::ExportPreview(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("exportPreview"));
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    setMinimumSize(sizeHint());
}

void ExportPreview::setFrame(const QImage &frame)
{
    m_frame = frame;
    update();
}

QSize ExportPreview::sizeHint() const
{
    return {160, 160};
}

void ExportPreview::paintEvent(QPaintEvent *)
{
    if (m_frame.isNull())
        return;
    const QSize fitted = m_frame.size().scaled(size(), Qt::KeepAspectRatio);
    const QRect target(QPoint((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
    QPainter painter(this);
    paintCheckerboard(&painter, target);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    painter.drawImage(target, m_frame);
}

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
