#pragma once

#include "document/document.h"

#include <QByteArray>
#include <QImage>
#include <QRectF>
#include <QSvgRenderer>
#include <QWidget>

namespace toonface {

// The live cartoon: SvgFace(document face, document style).svg() drawn through QSvgRenderer,
// framed on the face. Changes are coalesced: the SVG is rebuilt once per event-loop turn
// however many changes arrived; painting rasterises it once per change or resize into a
// cached image and otherwise only blits (no detection, no file I/O, no SVG building there).
class PreviewView : public QWidget
{
    Q_OBJECT

public:
    explicit PreviewView(Document *document, QWidget *parent = nullptr);
    ~PreviewView() override;

    // The SVG now shown (rebuilt first if a change is pending); empty without a face.
    QByteArray svg();
    // The picture now shown, at the widget's size.
    QImage image();
    // The part of the drawing in view, in photo pixels: the face with a margin.
    QRectF frame() const { return m_frame; }
    // How many times the SVG was rebuilt (coalescing shows as fewer rebuilds than changes).
    int rebuildCount() const { return m_rebuilds; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void onDocumentChanged(ChangeFlags what);
    void scheduleRebuild();
    void rebuildIfPending();
    void renderCache();
    QRectF targetRect() const;

    Document *m_document;
    QSvgRenderer m_renderer;
    QByteArray m_svg;
    QRectF m_frame;
    QImage m_cache;
    bool m_pending = false;
    bool m_frameStale = true;
    bool m_cacheValid = false;
    int m_rebuilds = 0;
};

} // namespace toonface
