#include "timeline/emotionpalette.h"

#include "timeline/timelineicons.h"
#include "views/displaynames.h"

#include <QApplication>
#include <QDrag>
#include <QHBoxLayout>
#include <QMimeData>
#include <QMouseEvent>
#include <QToolButton>

namespace toonface {

QMimeData *emotionMimeData(Emotion emotion)
{
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(kEmotionMime), emotionName(emotion).toUtf8());
    return mime;
}

std::optional<Emotion> emotionFromMimeData(const QMimeData *mime)
{
    if (!mime || !mime->hasFormat(QString::fromLatin1(kEmotionMime)))
        return std::nullopt;
    return emotionFromName(QString::fromUtf8(mime->data(QString::fromLatin1(kEmotionMime))));
}

EmotionPalette::EmotionPalette(QWidget *parent)
    : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(1);
    for (Emotion emotion : kAllEmotions) {
        auto *button = new QToolButton(this);
        button->setObjectName(QStringLiteral("emotion-%1").arg(emotionName(emotion)));
        button->setIcon(emotionIcon(emotion));
        button->setAutoRaise(true);
        button->setToolTip(tr("%1: click to apply to the selection (or 2 s from the playhead), or drag onto the "
                              "emotion track")
                               .arg(emotionTitle(emotion)));
        button->setProperty("emotion", int(emotion));
        button->installEventFilter(this);
        connect(button, &QToolButton::clicked, this, [this, emotion]() { Q_EMIT applied(emotion); });
        layout->addWidget(button);
    }
}

bool EmotionPalette::eventFilter(QObject *watched, QEvent *event)
{
    auto *button = qobject_cast<QToolButton *>(watched);
    if (!button)
        return QWidget::eventFilter(watched, event);
    if (event->type() == QEvent::MouseButtonPress) {
        m_pressPos = static_cast<QMouseEvent *>(event)->position().toPoint();
    } else if (event->type() == QEvent::MouseMove) {
        auto *move = static_cast<QMouseEvent *>(event);
        if ((move->buttons() & Qt::LeftButton)
            && (move->position().toPoint() - m_pressPos).manhattanLength() >= QApplication::startDragDistance()) {
            const auto emotion = Emotion(button->property("emotion").toInt());
            button->setDown(false);
            auto *drag = new QDrag(button);
            drag->setMimeData(emotionMimeData(emotion));
            drag->setPixmap(button->icon().pixmap(24, 24));
            drag->exec(Qt::CopyAction);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace toonface
