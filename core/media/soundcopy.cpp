#include "media/soundcopy.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"
#include "speech/audio.h"
#include "speech/progress.h"

#include <QFile>

namespace toonface {

SoundCopy copySound(const QString &source, const QString &target, int sampleRate,
    const std::function<void(double)> &progress, const std::atomic_bool *cancel)
{
    SoundCopy copy;
    const auto fail = [&](SoundCopyStatus status, const QString &error) {
        QFile::remove(target);
        copy.status = status;
        copy.error = error;
        return copy;
    };
    av::AudioFeed feed;
    QString error;
    if (!feed.open(AudioSource::fromFile(source), &error) || !feed.start(sampleRate, &error))
        return fail(SoundCopyStatus::BadInput, error);
    std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(target, sampleRate, &error);
    if (!writer)
        return fail(SoundCopyStatus::Failed, error);
    QVector<float> block;
    while (true) {
        if (isCancelled(cancel)) {
            writer.reset();
            return fail(SoundCopyStatus::Cancelled, withProblem(source, SoundText::tr("cancelled")));
        }
        if (!feed.readBlock(&block, &error)) {
            writer.reset();
            return fail(SoundCopyStatus::BadInput, error);
        }
        if (block.isEmpty())
            break;
        if (!writer->write(block.constData(), block.size(), &error)) {
            writer.reset();
            return fail(SoundCopyStatus::Failed, error);
        }
        copy.samples += block.size();
        if (progress)
            progress(feed.fractionRead());
    }
    if (copy.samples == 0) {
        writer.reset();
        return fail(SoundCopyStatus::BadInput, withProblem(source, SoundText::tr("it holds no sound")));
    }
    if (!writer->finish(&error))
        return fail(SoundCopyStatus::Failed, error);
    copy.status = SoundCopyStatus::Done;
    copy.seconds = double(copy.samples) / sampleRate;
    if (progress)
        progress(1.0);
    return copy;
}

} // namespace toonface
