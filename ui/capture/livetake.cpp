#include "capture/livetake.h"

#include "document/document.h"
#include "speech/audiomouth.h"
#include "track/retarget.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace toonface {

namespace {

// The context of this file's strings in the translations.
struct LiveTakeText
{
    Q_DECLARE_TR_FUNCTIONS(toonface::LiveTakeText)
};

} // namespace

bool commitTake(Document *document, const LiveTake &take, double at, const QString &audioPath, QString *message)
{
    QString unused;
    QString &out = message ? *message : unused;
    // The microphone's mouth throughout, or (Both) where the camera lost the face.
    const bool soundMouth = take.mouthMode != LiveMouth::Camera && !take.mouth.isEmpty();
    const bool heardOnly = take.frames.isEmpty();
    if (heardOnly && !soundMouth) {
        out = take.duration > 0 ? LiveTakeText::tr("Nothing was recorded: the microphone heard nothing.")
                                : LiveTakeText::tr("Nothing was recorded: no frame with a face was tracked.");
        return false;
    }
    Animation after = document->animation();
    addTakeToTimeline(take.frames, take.fps, take.duration,
        soundMouth ? audioMouthKeys(take.mouth) : QVector<MouthKey> {}, &after.timeline, at,
        take.mouthMode == LiveMouth::Both);

    const bool sound = !take.audio.isEmpty() && !audioPath.isEmpty();
    if (sound) {
        QString error;
        if (!QDir().mkpath(QFileInfo(audioPath).absolutePath()) || !writeAudio(audioPath, take.audio, &error)) {
            out = error.isEmpty() ? LiveTakeText::tr("%1: cannot create its folder").arg(audioPath) : error;
            return false;
        }
        // A new clip where the take was recorded: the recordings there stay (the sounds mix).
        AudioClip clip;
        clip.path = QFileInfo(audioPath).absoluteFilePath();
        clip.offset = at;
        clip.duration = take.audio.duration();
        after.timeline.addAudioClip(clip);
    }
    document->changeAnimation(after, LiveTakeText::tr("Record Live Take"));
    const QString length = QString::number(take.duration, 'f', 1);
    if (heardOnly)
        out = sound ? LiveTakeText::tr("Recorded %1 s of the microphone: the mouth, with its sound saved as %2")
                          .arg(length, QDir::toNativeSeparators(audioPath))
                    : LiveTakeText::tr("Recorded %1 s of the microphone: the mouth, no sound").arg(length);
    else if (sound)
        out = LiveTakeText::tr("Recorded %1 s (%2 frames) with its sound, saved as %3")
                  .arg(length)
                  .arg(take.frames.size())
                  .arg(QDir::toNativeSeparators(audioPath));
    else
        out = LiveTakeText::tr("Recorded %1 s (%2 frames): motion only, no sound").arg(length).arg(take.frames.size());
    return true;
}

} // namespace toonface
