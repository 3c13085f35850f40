#pragma once

#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>

#include <memory>

namespace toonface {

// Decodes single frames of one video file off the GUI thread for views that show "the frame at
// index i" (the neutral-frame picker, the video dock). Latest request wins: while a frame is
// being decoded, newer requests replace the waiting one, so a scrub or playback never queues
// frames up; the ones passed over are dropped. Decoding is sequential (core's VideoFileSource):
// a request a little after the last decoded frame reads on from there, so playback costs one
// frame a frame; a jump back or far ahead seeks to the key frame before it and reads on from
// there (a file that cannot seek is read from its start). The last few frames are kept, so
// stepping around a frame and repainting cost nothing.
//
// Lives on the GUI thread; its signals arrive there.
class FrameDecoder : public QObject
{
    Q_OBJECT

public:
    explicit FrameDecoder(QObject *parent = nullptr);
    // Drops the running decode (its result is never reported).
    ~FrameDecoder() override;

    // Opens `path` (reading its header on the calling thread); false with *error "<path>:
    // <problem>" when it is missing, not a video, or has no video stream. Closes the file before.
    bool open(const QString &path, QString *error);
    void close();
    bool isOpen() const { return !m_path.isEmpty(); }
    QString path() const { return m_path; }
    // From the header: frames per second (0 when unknown), the frame count (-1 when unknown),
    // the frame size, whether it has sound, its duration in seconds (0 when unknown).
    double frameRate() const { return m_fps; }
    int frameCount() const { return m_frameCount; }
    QSize frameSize() const { return m_size; }
    bool hasAudio() const { return m_hasAudio; }
    double duration() const { return m_duration; }

    // Asks for frame `index` (0-based); frameReady() or failed() follows unless a newer request
    // replaces this one first. A request for the frame being decoded or just shown is ignored.
    void request(int index);
    // The index of the last frame reported by frameReady(), or -1.
    int shownIndex() const { return m_shown; }
    // Whether a decode runs or waits.
    bool isBusy() const { return m_running >= 0; }
    // How many requests were passed over for newer ones (dropped, never decoded).
    int droppedRequests() const { return m_dropped; }
    // How many frames the file's decoder delivered since open() (what requests cost).
    int framesDecoded() const;

Q_SIGNALS:
    void frameReady(int index, const QImage &image);
    // The frame could not be decoded: "<path>: <problem>" (e.g. past the end of a truncated file).
    void failed(int index, const QString &error);

private:
    struct Reader;
    struct Outcome;
    void startNext();
    void onDecoded(int generation, int index, const QImage &image, const QString &error);

    QString m_path;
    double m_fps = 0;
    int m_frameCount = -1;
    QSize m_size;
    bool m_hasAudio = false;
    double m_duration = 0;
    std::shared_ptr<Reader> m_reader; // used by one pool thread at a time
    int m_generation = 0; // counts open()/close(): results of an older file are dropped
    int m_running = -1; // the index being decoded, or -1
    int m_pending = -1; // the next index to decode, or -1
    int m_shown = -1;
    int m_dropped = 0;
};

} // namespace toonface
