#include "media/audiomix.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"
#include "media/mediareader.h"
#include "media/userfile.h"
#include "speech/audio.h"

#include <QDir>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace toonface {

namespace {

bool cancelled(const std::atomic_bool *cancel)
{
    return cancel && cancel->load();
}

// Lowers the gain where |x| passes the ceiling: the gain each sample needs, then spread so it
// falls over kAttack before such a sample and rises over kRelease after, never above what any
// sample needs (so no sample passes the ceiling, and the gain moves without clicks).
void limit(QVector<float> &x, int rate)
{
    const float peak = std::transform_reduce(
        x.cbegin(), x.cend(), 0.0f, [](float a, float b) { return std::max(a, b); },
        [](float v) { return std::abs(v); });
    if (peak <= kMixCeiling)
        return;
    constexpr double kAttack = 0.005, kRelease = 0.08;
    const double attackStep = 1.0 / std::max(1.0, kAttack * rate);
    const double releaseStep = 1.0 / std::max(1.0, kRelease * rate);
    std::vector<double> gain(size_t(x.size()));
    for (qsizetype i = 0; i < x.size(); ++i) {
        const double a = std::abs(x[i]);
        gain[size_t(i)] = a > kMixCeiling ? kMixCeiling / a : 1.0;
    }
    for (size_t i = 1; i < gain.size(); ++i)
        gain[i] = std::min(gain[i], gain[i - 1] + releaseStep);
    for (size_t i = gain.size() - 1; i-- > 0;)
        gain[i] = std::min(gain[i], gain[i + 1] + attackStep);
    for (qsizetype i = 0; i < x.size(); ++i)
        x[i] = float(std::clamp(x[i] * gain[size_t(i)], -double(kMixCeiling), double(kMixCeiling)));
}

} // namespace

QVector<AudioClip> soundingClips(const QVector<AudioClip> &clips)
{
    QVector<AudioClip> out;
    for (const AudioClip &clip : clips)
        if (!clip.path.isEmpty())
            out.append(clip);
    return out;
}

std::optional<MixedSound> mixAudioClips(
    const QVector<AudioClip> &allClips, int sampleRate, QString *error, const std::atomic_bool *cancel)
{
    const QVector<AudioClip> clips = soundingClips(allClips);
    MixedSound mix;
    if (clips.isEmpty()) {
        mix.sampleRate = sampleRate > 0 ? sampleRate : kSpeechSampleRate;
        return mix;
    }
    for (const AudioClip &clip : clips) {
        if (const QString problem = irregularFileProblem(clip.path); !problem.isEmpty()) {
            *error = withProblem(clip.path, problem);
            return std::nullopt;
        }
    }
    int rate = sampleRate;
    if (rate <= 0) {
        for (const AudioClip &clip : clips) {
            av::AudioFeed feed;
            if (!feed.open(AudioSource::fromFile(clip.path), error))
                return std::nullopt;
            rate = std::max(rate, std::min(feed.sourceRate(), kMaxMixRate));
        }
        rate = rate > 0 ? rate : kMaxMixRate;
    }
    mix.sampleRate = rate;
    mix.start
        = std::max(0.0, std::min_element(clips.cbegin(), clips.cend(), [](const AudioClip &a, const AudioClip &b) {
              return a.start() < b.start();
          })->start());
    for (const AudioClip &clip : clips) {
        if (cancelled(cancel)) {
            error->clear();
            return std::nullopt;
        }
        std::optional<QVector<float>> samples = readAudio(clip.path, rate, error);
        if (!samples)
            return std::nullopt;
        const qsizetype from = std::clamp<qsizetype>(qsizetype(std::llround(clip.trimIn * rate)), 0, samples->size());
        const qsizetype to = clip.duration > 0 ? std::clamp<qsizetype>(
                                 qsizetype(std::llround((clip.duration - clip.trimOut) * rate)), from, samples->size())
                                               : samples->size();
        const qsizetype at = qsizetype(std::llround((clip.start() - mix.start) * rate));
        const qsizetype skip = std::max<qsizetype>(0, -at); // a clip starting before 0 is heard from 0
        if (to - from <= skip)
            continue;
        const qsizetype place = std::max<qsizetype>(0, at);
        const qsizetype count = to - from - skip;
        if (mix.samples.size() < place + count)
            mix.samples.resize(place + count, 0.0f);
        const float *src = samples->constData() + from + skip;
        float *dst = mix.samples.data() + place;
        for (qsizetype i = 0; i < count; ++i)
            dst[i] += src[i];
    }
    limit(mix.samples, rate);
    return mix;
}

std::optional<TrackSound> trackSoundFile(const QVector<AudioClip> &allClips, const QString &folder, const QString &name,
    QString *error, const std::atomic_bool *cancel)
{
    const QVector<AudioClip> clips = soundingClips(allClips);
    TrackSound out;
    if (clips.isEmpty())
        return out;
    if (clips.size() == 1 && clips.first().trimIn == 0 && clips.first().trimOut == 0) {
        const AudioClip &clip = clips.first();
        if (const QString problem = irregularFileProblem(clip.path); !problem.isEmpty()) {
            *error = withProblem(clip.path, problem);
            return std::nullopt;
        }
        out.path = clip.path;
        out.offset = clip.offset;
        out.duration = clip.duration;
        return out;
    }
    const std::optional<MixedSound> mix = mixAudioClips(clips, 0, error, cancel);
    if (!mix)
        return std::nullopt;
    if (mix->samples.isEmpty())
        return out; // trimmed to nothing
    out.path = QDir(folder).filePath(name);
    out.offset = mix->start;
    out.duration = mix->duration();
    out.mixed = true;
    if (!writeAudio(out.path, Audio {mix->samples, mix->sampleRate}, error))
        return std::nullopt;
    return out;
}

} // namespace toonface
