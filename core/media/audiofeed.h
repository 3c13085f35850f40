#pragma once

#include "media/audiosource.h"
#include "media/ffmpegutil.h"

#include <QString>
#include <QVector>

#include <vector>

namespace toonface::av {

// The sound of an AudioSource, delayed by its offset and resampled to mono float at a chosen
// rate: what an MP4 export encodes and what readAudio() returns. Decodes as it is read.
class AudioFeed
{
public:
    // Opens the source; sourceRate() is then known.
    bool open(const AudioSource &source, QString *error);

    int sourceRate() const { return m_sourceRate; }

    // Everything the source has left (offset applied), up to its end.
    bool readAll(QVector<float> *out, QString *error);

    // Replaces *out with the next samples the source gives (offset applied; a block of the
    // decoder's, not a fixed count); *out empty: the source has ended. requires: start().
    bool readBlock(QVector<float> *out, QString *error);

    // How far into the source file the reading is, 0..1 (by its bytes; 0 for samples in memory
    // or a file of unknown size).
    double fractionRead() const;

    // Starts resampling to `rate`.
    bool start(int rate, QString *error);

    // Fills dst with the next n samples (silence once the source has ended).
    bool read(float *dst, int n, QString *error);

private:
    QString sourceName() const { return m_source.path.isEmpty() ? QStringLiteral("audio samples") : m_source.path; }

    // Appends resampled samples to m_buffer; at the source's end flushes the resampler and
    // sets m_ended. Returns false on a decoding error.
    bool decodeMore(QString *error);

    bool convert(const uint8_t **in, int n, QString *error);

    bool flush(QString *error);

    AudioSource m_source;
    int m_sourceRate = 0;
    int m_rate = 0;
    InputPtr m_input;
    CodecPtr m_decoder;
    int m_stream = -1;
    PacketPtr m_packet;
    FramePtr m_frame;
    SwrPtr m_swr;
    qsizetype m_memoryPos = 0;
    bool m_draining = false;
    bool m_ended = false;
    qint64 m_silenceBefore = 0;
    qint64 m_skip = 0;
    std::vector<float> m_buffer;
    size_t m_buffered = 0; // samples of m_buffer already read
};

} // namespace toonface::av
