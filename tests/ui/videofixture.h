#pragma once

#include "export/videoencoder.h"
#include "imagedifference.h"
#include "talkingface.h"

#include <QFileInfo>
#include <QImage>
#include <QString>

#include <cmath>
#include <cstdlib>

// Clips written at test time for the video tests: a drawn talking face (the mouth opens on
// frames 8-13, the eyes shut on 18-19) and plain grey frames, with or without a tone.
namespace toonface::videofixture {

inline const QString kPortrait = QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png");
inline constexpr int kTalkingFrames = 25;
inline constexpr double kFps = 25.0;

inline bool mouthOpenAt(int i)
{
    return i >= 8 && i < 14;
}
inline bool eyesShutAt(int i)
{
    return i == 18 || i == 19;
}

// Writes `frames` frames from `frame(i)` at kFps to `path` (MP4), with a 440 Hz tone when
// `withSound`; returns the error, or empty.
template<class Frame>
QString writeClip(const QString &path, int frames, bool withSound, Frame frame)
{
    AudioSource sound;
    if (withSound) {
        const int rate = 16000;
        QVector<float> samples(int(rate * frames / kFps));
        for (int i = 0; i < samples.size(); ++i)
            samples[i] = float(0.3 * std::sin(2 * M_PI * 440.0 * i / rate));
        sound = AudioSource::fromSamples(samples, rate);
    }
    VideoWriter writer;
    QString error;
    const QImage first = frame(0);
    if (!writer.open(path, VideoFormat::Mp4, first.size(), kFps, sound, &error))
        return error;
    for (int i = 0; i < frames; ++i) {
        if (!writer.addFrame(i == 0 ? first : frame(i), &error))
            return error;
    }
    return writer.finish(&error) ? QString() : error;
}

// The drawn talking face; empty when the portrait is not installed, else the error or empty.
inline QString writeTalkingClip(const QString &path, bool withSound, bool *skipped)
{
    *skipped = !QFileInfo::exists(kPortrait);
    if (*skipped)
        return {};
    const testing::TalkingFace talking {QImage(kPortrait).scaled(320, 320)};
    if (!talking.isValid())
        return QStringLiteral("the drawn face is not found on the portrait");
    return writeClip(path, kTalkingFrames, withSound,
        [&](int i) { return talking.frame(mouthOpenAt(i) ? 1.0 : 0.0, eyesShutAt(i) ? 0.0 : 1.0); });
}

// Frames whose grey level is 10 * i, so that each frame can be told apart.
inline QString writeGreyClip(const QString &path, int frames)
{
    return writeClip(path, frames, false, [](int i) {
        QImage image(64, 48, QImage::Format_RGB32);
        image.fill(QColor(10 * i, 10 * i, 10 * i));
        return image;
    });
}

using testing::meanDifference;

} // namespace toonface::videofixture
