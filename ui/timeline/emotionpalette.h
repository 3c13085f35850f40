#pragma once

#include "face/emotion.h"

#include <QWidget>

#include <optional>

class QMimeData;

namespace toonface {

// The mime type of an emotion preset dragged from the palette: its name ("smile").
inline constexpr char kEmotionMime[] = "application/x-toonface-emotion";
QMimeData *emotionMimeData(Emotion emotion);
std::optional<Emotion> emotionFromMimeData(const QMimeData *mime);

// The five emotion presets as buttons: click applies one to the selected range (applied()),
// drag one onto the emotion track to place it there.
class EmotionPalette : public QWidget
{
    Q_OBJECT

public:
    explicit EmotionPalette(QWidget *parent = nullptr);

Q_SIGNALS:
    void applied(toonface::Emotion emotion);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QPoint m_pressPos;
};

} // namespace toonface
