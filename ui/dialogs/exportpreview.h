#pragma once

#include <QImage>
#include <QWidget>

namespace toonface {

// A still of the export as it will look: the frame drawn over a grey checkerboard, so what is
// transparent shows as transparent (as image editors show it) and a colour or photo background
// shows as itself.
class ExportPreview : public QWidget
{
    Q_OBJECT

public:
    explicit ExportPreview(QWidget *parent = nullptr);

    // The frame to show (any size: scaled to fit, aspect kept); a null image shows nothing.
    void setFrame(const QImage &frame);
    const QImage &frame() const { return m_frame; }

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QImage m_frame;
};

} // namespace toonface
