#include "dialogs/exportpreview.h"

#include "views/checkerboard.h"

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

} // namespace toonface
