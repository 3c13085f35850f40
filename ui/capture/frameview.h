#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

namespace toonface {

// A video frame drawn as large as fits, centred on a dark ground with its aspect kept, or a
// line of text in its place (no clip, an error). Painting only; the frames come from outside.
class FrameView : public QWidget
{
    Q_OBJECT

public:
    explicit FrameView(QWidget *parent = nullptr);

    void setImage(const QImage &image);
    const QImage &image() const { return m_image; }
    // Shown instead of the frame (clears it); empty shows nothing.
    void setText(const QString &text);
    QString text() const { return m_text; }
    // A small caption drawn in a corner over the frame (e.g. "frame 12 · 0.48 s").
    void setCaption(const QString &caption);
    QString caption() const { return m_caption; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QImage m_image;
    QString m_text;
    QString m_caption;
};

} // namespace toonface
