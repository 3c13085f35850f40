#pragma once

#include <QString>
#include <QVector>

namespace toonface {

// The sound of a video: mono samples in memory, or a file that FFmpeg decodes (any format and
// channel count it reads; channels are mixed down to mono). The sound starts `offset` seconds
// into the video (a negative offset skips the sound's beginning).
struct AudioSource
{
    QVector<float> samples; // in [-1, 1]
    int sampleRate = 0;
    QString path;
    double offset = 0;

    static AudioSource fromSamples(QVector<float> samples, int sampleRate, double offset = 0);
    static AudioSource fromFile(const QString &path, double offset = 0);
    bool isEmpty() const { return samples.isEmpty() && path.isEmpty(); }
};

} // namespace toonface
