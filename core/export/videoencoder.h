#pragma once

#include "media/audiosource.h"

#include <QColor>
#include <QImage>
#include <QSize>
#include <QString>
#include <QVector>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

namespace toonface {

enum class VideoFormat {
    Mp4, // H.264 (libx264, yuv420p) + AAC, moov atom first (+faststart)
    Gif, // animated GIF, one 255-colour palette for the whole file, looping
    PngSequence, // a folder of frame_00001.png, frame_00002.png, ... with their alpha
    WebM, // VP9 (libvpx-vp9, yuva420p: the alpha in Matroska's block additions) + Opus
    Mov, // ProRes 4444 (prores_ks, yuva444p10le) with alpha + 16-bit PCM, for video editors
    Apng, // animated PNG (RGBA), looping, silent
    WebP, // animated WebP (libwebp, lossy colour with lossless alpha), looping, silent
};

// .mp4 -> Mp4, .gif -> Gif, .webm -> WebM, .mov -> Mov, .apng -> Apng, .webp -> WebP (any
// case); a path ending in '/' or naming an existing folder -> PngSequence; nullopt otherwise.
std::optional<VideoFormat> videoFormatForPath(const QString &path);

// Whether the format keeps each pixel's alpha (PNG, WebM, MOV, APNG, WebP); GIF keeps one
// transparent colour (VideoOptions::background transparent); MP4 has none.
bool videoFormatHasAlpha(VideoFormat format);
// Whether the format carries sound (MP4, WebM, MOV).
bool videoFormatHasSound(VideoFormat format);

struct VideoOptions
{
    // x264's constant rate factor (0 lossless .. 51; 18-23 look clean on flat cartoon colours)
    // and speed preset.
    int crf = 20;
    QString preset = QStringLiteral("veryfast");
    // Encoder threads; 0 lets the encoder use every core.
    int threads = 0;
    int audioBitRate = 96000;
    // MP4's sound rate: 0 keeps 44.1 kHz for that family of rates and makes every other 48 kHz
    // (what video editors expect); a rate here is used as it is (a book's speech at 24 kHz,
    // whose encoding costs half).
    int mp4AudioRate = 0;
    // VP9's constant quality (WebM): 0 (best) .. 63; higher makes smaller files.
    int vp9Crf = 32;
    // WebP's quality: 0 .. 100 (best); lower makes smaller files.
    int webpQuality = 80;
    // MP4 has no alpha: transparent pixels are composed over this colour. A GIF does the same
    // unless the colour is transparent (alpha 0): then pixels less than half opaque become its
    // transparent colour and each frame replaces the last whole. The formats with alpha keep it.
    QColor background = Qt::white;
    // WebM keeps its alpha unless this is false (frames known to be opaque: a colour or photo
    // behind the face), when it is plain yuv420p, smaller and read by every player.
    bool keepAlpha = true;
    // A GIF keeps every k-th frame, k the smallest integer with fps / k <= gifMaxFps (GIF
    // delays are whole hundredths and browsers slow down delays under 0.02 s).
    double gifMaxFps = 25;
    // GIF: one palette serves the whole file, made from the first frame and these images.
    // Give frames showing colours the first frame lacks (the mouth wide open, the eyes shut);
    // colours seen nowhere map to the nearest palette entry.
    QVector<QImage> paletteSamples;
};

// Writes frames given as QImages at a fixed rate, with optional sound, as an MP4, an animated
// GIF, a PNG sequence, a WebM, a MOV, an animated PNG or an animated WebP.
//
// The output appears only on a successful finish(): MP4 and GIF are written to a hidden
// temporary file next to the target and renamed over it at the end; PNG frames are written
// one by one (each atomically) and removed again when the writer is cancelled. A writer that
// is destroyed before finish() cancels.
//
// Encoding runs in the calling thread, inside addFrame() and finish(): run the export loop in
// a worker thread (writeVideo() is that loop, with progress and cancellation). Not thread-safe:
// use one writer from one thread at a time; separate writers are independent.
class VideoWriter
{
public:
    VideoWriter();
    ~VideoWriter();
    VideoWriter(const VideoWriter &) = delete;
    VideoWriter &operator=(const VideoWriter &) = delete;

    // Starts a video of frames of `size` at `fps` frames a second. MP4 needs an even size:
    // an odd width or height is padded by one pixel (repeating the last column or row).
    // The audio is encoded into MP4, WebM and MOV only (the others have no sound) and cut or padded with
    // silence to the video's length (frames / fps). For a PNG sequence `path` is the folder,
    // created when missing.
    // On failure returns false and sets *error to "<path>: <problem>" (unwritable folder,
    // unsupported size or rate, missing encoder, unreadable audio, ...).
    bool open(const QString &path, VideoFormat format, QSize size, double fps, const AudioSource &audio, QString *error,
        const VideoOptions &options = {});

    // Encodes the next frame. requires: open; frame.size() == the size given to open().
    bool addFrame(const QImage &frame, QString *error);

    // Flushes the encoders, writes the file (or the last frame) and closes; fails (writing
    // nothing) when no frame was added. A PNG sequence's
    // folder ends up holding exactly this export's frame_NNNNN.png files: frames of the same
    // pattern beyond this export's last (left by an earlier, longer export) are removed.
    bool finish(QString *error);

    // Discards everything written so far and closes; harmless when not open.
    void cancel();

    bool isOpen() const;
    int framesAdded() const;
    // The size of the encoded pictures: MP4 and WebM round each side up to even.
    QSize encodedSize() const;
    // Frames per second of the output (a GIF may drop frames, see VideoOptions::gifMaxFps).
    double outputFps() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};

// The whole export: renders frame i with renderFrame(i) for i in [0, frameCount), reports
// progress(done, frameCount) after each frame, and stops when *cancel becomes true (the
// output is then discarded and *error is "<path>: cancelled"). A plain function of its
// arguments, to run with QtConcurrent::run or in a worker thread; progress is called in that
// thread. `progress` and `cancel` may be null.
bool writeVideo(const QString &path, VideoFormat format, QSize size, double fps, int frameCount,
    const std::function<QImage(int)> &renderFrame, const AudioSource &audio, QString *error,
    const VideoOptions &options = {}, const std::function<void(int, int)> &progress = {},
    const std::atomic<bool> *cancel = nullptr);

} // namespace toonface
