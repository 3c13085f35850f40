#include "views/stepimagedialog.h"

#include <QLabel>
#include <QResizeEvent>
#include <QScreen>
#include <QVBoxLayout>

#include <algorithm>

namespace toonface {

namespace {

constexpr double kMaxEnlargement = 2.0;

} // namespace

StepImageDialog::StepImageDialog(const QImage &image, const QString &title, QWidget *parent)
    : QDialog(parent)
    , m_image(image)
    , m_label(new QLabel)
{
    setWindowTitle(title);
    m_label->setObjectName(QStringLiteral("stepImage"));
    m_label->setAlignment(Qt::AlignCenter);
    m_label->setMinimumSize(64, 64);
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);

    // Opens at the picture's size, within half of the screen.
    QSize size = image.size();
    if (const QScreen *s = screen()) {
        const QSize room = s->availableSize() / 2;
        if (size.width() > room.width() || size.height() > room.height())
            size.scale(room, Qt::KeepAspectRatio);
    }
    resize(size.expandedTo(QSize(160, 120)));
    rescale();
}

QPixmap StepImageDialog::shownPixmap() const
{
    return m_label->pixmap();
}

void StepImageDialog::resizeEvent(QResizeEvent *event)
{
    QDialog::resizeEvent(event);
    rescale();
}

void StepImageDialog::rescale()
{
    if (m_image.isNull()) {
        m_label->setText(tr("No picture."));
        return;
    }
    QSize target = m_image.size();
    target.scale(m_label->size(), Qt::KeepAspectRatio);
    const double factor = std::min(double(target.width()) / m_image.width(), kMaxEnlargement);
    target = (QSizeF(m_image.size()) * factor).toSize().expandedTo(QSize(1, 1));
    QPixmap pixmap = QPixmap::fromImage(
        m_image.scaled(target * devicePixelRatio(), Qt::KeepAspectRatio, Qt::SmoothTransformation));
    pixmap.setDevicePixelRatio(devicePixelRatio());
    m_label->setPixmap(pixmap);
}

} // namespace toonface
