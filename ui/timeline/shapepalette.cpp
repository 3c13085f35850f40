#include "timeline/shapepalette.h"

#include "timeline/mouthicons.h"
#include "timeline/timelinepainter.h"

#include <QHBoxLayout>
#include <QPainter>

namespace toonface {

namespace {

// The lips on a chip of the shape's colour, the letter beside them.
QIcon shapeIcon(MouthShape shape, const QImage &lips)
{
    const qreal ratio = 2.0;
    QPixmap pixmap(QSize(44, 22) * ratio);
    pixmap.setDevicePixelRatio(ratio);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(mouthShapeColor(shape).darker(125));
    p.drawRoundedRect(QRectF(0.5, 0.5, 43, 21), 4, 4);
    if (!lips.isNull())
        p.drawImage(QRectF(2, 2, 29, 18), lips);
    QFont font = p.font();
    font.setBold(true);
    font.setPixelSize(13);
    p.setFont(font);
    p.setPen(Qt::white);
    p.drawText(QRectF(lips.isNull() ? 0 : 30, 0, lips.isNull() ? 44 : 14, 22), Qt::AlignCenter, mouthShapeName(shape));
    p.end();
    return QIcon(pixmap);
}

} // namespace

ShapePalette::ShapePalette(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(1);
    for (MouthShape shape : kAllMouthShapes) {
        auto *button = new QToolButton(this);
        button->setObjectName(QStringLiteral("shape-%1").arg(mouthShapeName(shape)));
        button->setAutoRaise(true);
        button->setIconSize(QSize(44, 22));
        button->setIcon(shapeIcon(shape, {}));
        button->setToolTip(
            tr("Mouth shape %1 (key %2): replaces the selected mouth keys, or inserts one at the playhead")
                .arg(mouthShapeName(shape), mouthShapeName(shape).toUpper()));
        connect(button, &QToolButton::clicked, this, [this, shape]() { Q_EMIT shapeChosen(shape); });
        m_buttons[int(shape)] = button;
        layout->addWidget(button);
    }
}

void ShapePalette::setIcons(const MouthIcons &icons)
{
    for (MouthShape shape : kAllMouthShapes)
        m_buttons[int(shape)]->setIcon(shapeIcon(shape, icons.icon(shape)));
}

} // namespace toonface
