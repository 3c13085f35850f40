#pragma once

#include "document/document.h"
#include "views/previewrenderer.h"

#include <QByteArray>
#include <QImage>
#include <QPointer>
#include <QRectF>
#include <QTransform>
#include <QWidget>

#include <memory>
#include <optional>

class QAction;

namespace toonface {

class Playhead;
class PoseKeyDrag;

// The live cartoon: the pose of the document's animation at the playhead's time, drawn by a
// PreviewRenderer (SvgFace -> QSvgRenderer, off the GUI thread when a frame does not fit its
// budget) on a card framed on the head. Painting only blits the last picture.
//
// With "Edit Pose" on (editPoseAction()), the control points a pose key frame moves (mouth
// corners and lips, lids, brows, the chin for the jaw) show as handles; dragging one sets a pose
// key at the playhead's time (thesis 2.2.4), one drag one undo step.
//
// With "Transparent Background" on (transparentAction()), the cartoon is drawn without its
// background over a checkerboard, as a transparent sticker or WebM exports it.
class PreviewView : public QWidget
{
    Q_OBJECT

public:
    explicit PreviewView(Document *document, QWidget *parent = nullptr);
    // Follows `playhead` (may be null: time 0).
    PreviewView(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    ~PreviewView() override;

    // The SVG now shown (brought up to date first); empty without a face.
    QByteArray svg();
    // The picture now shown, at the widget's size (brought up to date first).
    QImage image();
    // The part of the drawing in view, in photo pixels: the head with a margin.
    QRectF frame() const { return m_renderer->frame(); }
    // How many times the scene was rebuilt (coalescing shows as fewer rebuilds than changes).
    int rebuildCount() const { return m_renderer->rebuildCount(); }
    PreviewRenderer *renderer() const { return m_renderer; }

    // A checkable action toggling the pose handles.
    QAction *editPoseAction() const { return m_editPoseAction; }
    // A checkable action toggling the transparent view (off at first; the window remembers it).
    QAction *transparentAction() const { return m_transparentAction; }
    // Whether the handles are shown: "Edit Pose" on, a face, and the playhead not playing.
    bool isEditingPose() const;
    // Where the handle of point `id` ("8.4", "2.1", ...) is drawn now, in widget coordinates;
    // nullopt when it is not shown.
    std::optional<QPointF> handlePosition(const QString &id) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    void paintCard(QPainter &painter, const QRect &area) const;
    void paintHandles(QPainter &painter) const;
    QRectF targetRect() const;
    // Photo pixels (before head motion) -> widget, for the pose now shown.
    QTransform photoToWidget() const;
    int handleAt(QPointF pos) const;
    void updateImageSize();

    Document *m_document;
    QPointer<Playhead> m_playhead;
    PreviewRenderer *m_renderer;
    QAction *m_editPoseAction;
    QAction *m_transparentAction;
    std::unique_ptr<PoseKeyDrag> m_drag;
    QPointF m_dragStart; // the press, in photo pixels before head motion
    QTransform m_dragHead; // photoToWidget() at the press
    int m_hovered = -1;
};

} // namespace toonface
