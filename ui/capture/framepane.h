#pragma once

#include <QImage>
#include <QRectF>
#include <QString>
#include <QWidget>

namespace toonface {

// A picture fitted (aspect kept) in the widget on a dark card: a camera's view, a clip's frame
// or the live cartoon, with an optional box over it (the face found, in the picture's pixels)
// and a caption (a countdown, "No camera"). Painting only blits.
class FramePane : public QWidget
{
    Q_OBJECT

public:
    explicit FramePane(QWidget *parent = nullptr);

    void setImage(const QImage &image);
    const QImage &image() const { return m_image; }
    // The face's box in the picture's pixels; empty: none drawn.
    void setBox(const QRectF &box);
    QRectF box() const { return m_box; }
    // Large text over the middle (empty: none).
    void setCaption(const QString &text);
    QString caption() const { return m_caption; }
    // A mirror view, as people expect of their own camera.
    void setMirrored(bool mirrored);

    QSize sizeHint() const override { return {320, 240}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QImage m_image;
    QRectF m_box;
    QString m_caption;
    bool m_mirrored = false;
};

} // namespace toonface
