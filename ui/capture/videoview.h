#pragma once

#include <QDockWidget>
#include <QImage>
#include <QPointer>
#include <QWidget>

namespace toonface {

class Document;
class FrameDecoder;
class FrameView;
class Playhead;

// The imported clip (the timeline's video()) beside the cartoon: the clip's frame at the
// playhead's time, floor((time - offset) * fps), so that the person and the cartoon move
// together during playback and scrubbing. Frames are decoded off the GUI thread by a
// FrameDecoder (latest request wins: when decoding falls behind playback, frames are dropped,
// never queued). Before the clip starts and after it ends, a line says so. Holds no document
// state: it re-reads the clip on Change::Animation. Hidden (its dock closed), it decodes nothing.
class VideoView : public QWidget
{
    Q_OBJECT

public:
    VideoView(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    ~VideoView() override;

    // The frame index of the clip at the playhead's time now, or -1 outside the clip / no clip.
    int wantedFrame() const;
    // The frame index shown (its picture is image()), or -1.
    int shownFrame() const { return m_shown; }
    QImage image() const;
    // What is shown instead of a frame ("no clip", an error), or empty.
    QString text() const;
    FrameDecoder *decoder() const { return m_decoder; }

Q_SIGNALS:
    void frameShown(int index);
    // Whether the document has a clip to show changed.
    void hasClipChanged(bool hasClip);

protected:
    void showEvent(QShowEvent *event) override;

private:
    QString noClipText() const;
    void syncClip();
    void follow();
    // Shows m_decoded, which is frame `index`.
    void showDecoded(int index);

    Document *m_document;
    QPointer<Playhead> m_playhead;
    FrameDecoder *m_decoder;
    FrameView *m_view;
    QString m_error; // the clip could not be opened
    QImage m_decoded; // the decoder's last frame (its shownIndex())
    int m_shown = -1;
};

// The dock holding the VideoView ("Video" in View): shown, its tab in front, when the project
// gets a clip (imported, or a project with one opened); hidden when the project has none.
class VideoDock : public QDockWidget
{
    Q_OBJECT

public:
    VideoDock(Document *document, Playhead *playhead, QWidget *parent = nullptr);
    VideoView *view() const { return m_view; }

private:
    VideoView *m_view;
};

} // namespace toonface
