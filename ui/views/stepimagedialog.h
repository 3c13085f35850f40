#pragma once

#include <QDialog>
#include <QImage>

class QLabel;

namespace toonface {

// One picture in a small window of its own, scaled to fit the window with its aspect ratio
// kept and never enlarged past twice its size: for the detection's close-ups, which do not
// line up with the photo. Not modal.
class StepImageDialog : public QDialog
{
    Q_OBJECT

public:
    StepImageDialog(const QImage &image, const QString &title, QWidget *parent = nullptr);

    QImage image() const { return m_image; }
    // The picture as shown now (for tests).
    QPixmap shownPixmap() const;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void rescale();

    QImage m_image;
    QLabel *m_label;
};

} // namespace toonface
