#include "capture/videoview.h"

#include "capture/framedecoder.h"
#include "capture/frameview.h"
#include "document/document.h"
#include "playback/playhead.h"

#include <QFileInfo>
#include <QVBoxLayout>

#include <cmath>

namespace toonface {

VideoView::VideoView(Document *document, Playhead *playhead, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_playhead(playhead)
    , m_decoder(new FrameDecoder(this))
    , m_view(new FrameView(this))
{
    m_view->setObjectName(QStringLiteral("videoFrame"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);

    connect(m_document, &Document::changed, this, [this](ChangeFlags what) {
        if (what & Change::Animation)
            syncClip();
    });
    if (m_playhead)
        connect(m_playhead, &Playhead::timeChanged, this, &VideoView::follow);
    connect(m_decoder, &FrameDecoder::frameReady, this, [this](int index, const QImage &image) {
        m_decoded = image;
        showDecoded(index);
        // Playback moved on while this one was decoded: catch up with the newest.
        follow();
    });
    connect(m_decoder, &FrameDecoder::failed, this, [this](int, const QString &error) {
        m_shown = -1;
        m_view->setText(error);
    });
    m_view->setText(noClipText());
    syncClip();
}

VideoView::~VideoView() = default;

QImage VideoView::image() const
{
    return m_view->image();
}

QString VideoView::text() const
{
    return m_view->text();
}

int VideoView::wantedFrame() const
{
    const std::optional<VideoClip> &clip = m_document->timeline().video();
    if (!clip || !m_decoder->isOpen())
        return -1;
    const double fps = clip->fps > 0 ? clip->fps : m_decoder->frameRate();
    if (fps <= 0)
        return -1;
    const double t = (m_playhead ? m_playhead->time() : 0.0) - clip->offset;
    if (t < -1e-9)
        return -1;
    const int index = int(std::floor(t * fps + 1e-9));
    const int count = m_decoder->frameCount() > 0 ? m_decoder->frameCount()
        : clip->duration > 0                      ? int(std::ceil(clip->duration * fps - 1e-9))
                                                  : -1;
    return count >= 0 && index >= count ? -1 : index;
}

QString VideoView::noClipText() const
{
    return tr("No video: Animation ▸ Import Video… tracks a clip and shows it here.");
}

void VideoView::syncClip()
{
    const std::optional<VideoClip> &clip = m_document->timeline().video();
    const QString path = clip ? clip->path : QString();
    const bool had = m_decoder->isOpen() || !m_error.isEmpty();
    if (path == m_decoder->path() && (!path.isEmpty() || !had)) {
        follow();
        return;
    }
    m_shown = -1;
    m_decoded = QImage();
    m_error.clear();
    m_decoder->close();
    if (path.isEmpty()) {
        m_view->setText(noClipText());
    } else if (!m_decoder->open(path, &m_error)) {
        m_view->setText(m_error);
    }
    if (had != !path.isEmpty())
        Q_EMIT hasClipChanged(!path.isEmpty());
    follow();
}

void VideoView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    follow();
}

void VideoView::follow()
{
    const std::optional<VideoClip> &clip = m_document->timeline().video();
    // A closed dock decodes nothing; it catches up when shown.
    if (!clip || !m_decoder->isOpen() || !isVisible())
        return;
    const int index = wantedFrame();
    if (index < 0) {
        const double t = m_playhead ? m_playhead->time() : 0.0;
        m_shown = -1;
        m_view->setText(t < clip->offset ? tr("The clip starts at %1 s").arg(clip->offset, 0, 'f', 2)
                                         : tr("The clip ended at %1 s").arg(clip->offset + clip->duration, 0, 'f', 2));
        return;
    }
    if (index == m_shown)
        return;
    if (index == m_decoder->shownIndex() && !m_decoded.isNull())
        showDecoded(index);
    else
        m_decoder->request(index);
}

void VideoView::showDecoded(int index)
{
    m_shown = index;
    m_view->setImage(m_decoded);
    const std::optional<VideoClip> &clip = m_document->timeline().video();
    const double fps = clip && clip->fps > 0 ? clip->fps : m_decoder->frameRate();
    m_view->setCaption(
        fps > 0 ? tr("frame %1 · %2 s").arg(index).arg(index / fps, 0, 'f', 2) : tr("frame %1").arg(index));
    Q_EMIT frameShown(index);
}

VideoDock::VideoDock(Document *document, Playhead *playhead, QWidget *parent)
    : QDockWidget(tr("Video"), parent)
    , m_view(new VideoView(document, playhead, this))
{
    setObjectName(QStringLiteral("videoDock"));
    m_view->setObjectName(QStringLiteral("videoView"));
    setWidget(m_view);
    setVisible(document->timeline().video().has_value());
    connect(m_view, &VideoView::hasClipChanged, this, [this](bool hasClip) {
        setVisible(hasClip);
        // Shown again in its tab group (a project with a clip opened), its tab comes to the
        // front: shown behind Appearance's tab, nothing would say the project has a clip.
        if (hasClip)
            raise();
    });
}

} // namespace toonface
