#include "capture/framepane.h"

#include <QPainter>
#include <QPainterPath>

namespace toonface {

FramePane::FramePane(QWidget *parent)
    : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(120, 90);
}

void FramePane::setImage(const QImage &image)
{
    m_image = image;
    update();
}

void FramePane::setBox(const QRectF &box)
{
    m_box = box;
    update();
}

void FramePane::setCaption(const QString &text)
{
    m_caption = text;
    update();
}

void FramePane::setMirrored(bool mirrored)
{
    m_mirrored = mirrored;
    update();
}

void FramePane::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Shadow).darker(150));
    QRectF target;
    if (!m_image.isNull()) {
        QSizeF fitted = m_image.size();
        fitted.scale(QSizeF(size()), Qt::KeepAspectRatio);
        target = QRectF(QPointF(), fitted);
        target.moveCenter(QRectF(rect()).center());
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        painter.save();
        if (m_mirrored) {
            painter.translate(target.center().x() * 2, 0);
            painter.scale(-1, 1);
        }
        painter.drawImage(target, m_image);
        if (!m_box.isEmpty()) {
            const double s = target.width() / m_image.width();
            const QRectF box(target.topLeft() + m_box.topLeft() * s, m_box.size() * s);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(QPen(QColor(80, 220, 120), 2));
            painter.setBrush(Qt::NoBrush);
            painter.drawRoundedRect(box, 4, 4);
        }
        painter.restore();
    }
    if (!m_caption.isEmpty()) {
        QFont font = painter.font();
        const bool big = m_caption.size() <= 3;
        font.setPointSizeF(big ? std::max(18.0, height() / 5.0) : std::max(10.0, font.pointSizeF() * 1.15));
        font.setBold(big);
        painter.setFont(font);
        const QRect area = rect().adjusted(24, 24, -24, -24);
        const QRect text = painter.boundingRect(area, Qt::AlignCenter | Qt::TextWordWrap, m_caption);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0, 0, 0, 150));
        painter.drawRoundedRect(text.adjusted(-14, -10, 14, 10), 8, 8);
        painter.setPen(Qt::white);
        painter.drawText(area, Qt::AlignCenter | Qt::TextWordWrap, m_caption);
    }
}

} // namespace toonface
