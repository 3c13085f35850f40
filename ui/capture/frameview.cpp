#include "capture/frameview.h"

#include <QPainter>
#include <QPainterPath>

namespace toonface {

namespace {

const QColor kGround(0x26, 0x28, 0x2b);
const QColor kText(0xc8, 0xcb, 0xd0);

} // namespace

FrameView::FrameView(QWidget *parent)
    : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void FrameView::setImage(const QImage &image)
{
    m_image = image;
    m_text.clear();
    update();
}

void FrameView::setText(const QString &text)
{
    m_text = text;
    m_image = QImage();
    update();
}

void FrameView::setCaption(const QString &caption)
{
    if (caption == m_caption)
        return;
    m_caption = caption;
    update();
}

QSize FrameView::sizeHint() const
{
    return {360, 288};
}

QSize FrameView::minimumSizeHint() const
{
    return {160, 120};
}

void FrameView::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), kGround);
    if (m_image.isNull()) {
        painter.setPen(kText);
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, m_text);
        return;
    }
    QSizeF size = m_image.size();
    size.scale(QSizeF(rect().size()), Qt::KeepAspectRatio);
    const QRectF target(QPointF((width() - size.width()) / 2, (height() - size.height()) / 2), size);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    painter.drawImage(target, m_image);
    if (m_caption.isEmpty())
        return;
    const QFontMetrics metrics(font());
    const QRectF box(target.left() + 6, target.bottom() - metrics.height() - 10,
        metrics.horizontalAdvance(m_caption) + 12, metrics.height() + 4);
    painter.setRenderHint(QPainter::Antialiasing);
    QPainterPath path;
    path.addRoundedRect(box, 4, 4);
    painter.fillPath(path, QColor(0, 0, 0, 150));
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, m_caption);
}

} // namespace toonface
