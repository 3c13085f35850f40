#pragma once

#include "anim/timeline.h"

#include <QString>
#include <QVector>

#include <atomic>
#include <optional>

namespace toonface {

// The audio track as heard: every clip's heard part ([trimIn, duration - trimOut] of its file)
// at its place, summed into one mono stream that starts at the first clip's start. Where clips
// overlap and the sum would clip, a limiter lowers the gain around those samples only (the
// peak stays at kMixCeiling); a track without overlaps comes out sample for sample.
struct MixedSound
{
    QVector<float> samples; // in [-kMixCeiling, kMixCeiling] where mixing raised the level
    int sampleRate = 0;
    double start = 0; // seconds into the animation of samples[0]

    double duration() const { return sampleRate > 0 ? double(samples.size()) / sampleRate : 0.0; }
};

inline constexpr float kMixCeiling = 0.98f;

// The clips that name a file (a clip with an empty path only holds the timeline's length).
QVector<AudioClip> soundingClips(const QVector<AudioClip> &clips);
// The rate a mix is made at when not chosen: the highest of the clips' own rates, at most this.
inline constexpr int kMaxMixRate = 48000;

// Decodes and mixes the soundingClips() of `clips` at `sampleRate` (0: the clips' highest own rate, at most
// kMaxMixRate). nullopt with *error naming the file when one is not a regular file that decodes
// as sound (or cancelled, *error empty). An empty track mixes to no samples.
std::optional<MixedSound> mixAudioClips(
    const QVector<AudioClip> &clips, int sampleRate, QString *error, const std::atomic_bool *cancel = nullptr);

// The audio track as one file, for what plays or encodes a file (the editor's playback, an
// SVG's or HTML page's sound): the file of the only sounding clip when it is heard whole (no trim), else
// the mix written as a 16-bit WAV named `name` in `folder`. `offset` is where the file starts in
// the animation and `duration` how long it sounds (0 when unknown).
struct TrackSound
{
    QString path; // empty: the track is empty
    double offset = 0;
    double duration = 0;
    bool mixed = false; // path is the mix written in `folder`
};
std::optional<TrackSound> trackSoundFile(const QVector<AudioClip> &clips, const QString &folder, const QString &name,
    QString *error, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
