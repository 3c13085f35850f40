#include "track/neutralchoice.h"

#include "i18n/coretext.h"
#include "media/mediareader.h"
#include "track/clipsilence.h"
#include "track/mouthrange.h"
#include "track/videofilesource.h"

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

double outerParting(const TrackedFrame &f)
{
    const auto &d = f.motion.displacementEs0;
    return d[pt::idx(kMouthControlIds[Down])].y() - d[pt::idx(kMouthControlIds[Up])].y();
}

double eyesOpen(const TrackedFrame &f)
{
    return std::min(f.motion.leftEyeOpen, f.motion.rightEyeOpen);
}

} // namespace

NeutralChoice chooseNeutralFrame(const QString &path, const std::atomic_bool *cancel)
{
    NeutralChoice choice;
    VideoFileSource source;
    if (!source.open(path, &choice.error))
        return choice;
    const double fps = source.frameRate() > 0 ? source.frameRate() : 25.0;
    const int window = std::max(1, int(std::lround(kNeutralSearchS * fps)));
    // The face is looked for every kFindEvery frames until found (a clip may open on a title
    // or a turned head: a detection costs far more than tracking one), then tracked from there.
    constexpr int kFindEvery = 5;
    Tracker tracker;
    QVector<TrackedFrame> frames;
    int seen = 0;
    while (seen < window && !(cancel && cancel->load())) {
        std::optional<VideoFrame> f = source.next();
        if (!f)
            break;
        ++seen;
        if (!tracker.hasNeutral()) {
            QString ignored;
            if ((seen - 1) % kFindEvery != 0 || !tracker.setNeutral(f->image, &ignored))
                continue;
        }
        frames.append(tracker.track(*f));
    }
    if (seen == 0 && choice.error.isEmpty())
        choice.error = !source.error().isEmpty() ? source.error()
                                                 : VideoText::tr("%1: no video frame could be decoded").arg(path);
    if (frames.isEmpty() || (cancel && cancel->load()))
        return choice;
    choice.found = true;

    QVector<bool> silent(frames.size(), false);
    if (source.hasAudio()) {
        QString ignored; // without its sound the choice goes on without silence
        if (const auto sound = readAudio(path, kSilenceSampleRate, &ignored))
            silent = silentFrames(frames, *sound, kSilenceSampleRate, 1.0 / fps);
    }
    double sure = 0, widestEyes = 0;
    for (const TrackedFrame &f : std::as_const(frames)) {
        if (!f.lost) {
            sure = std::max(sure, f.confidence);
            widestEyes = std::max(widestEyes, eyesOpen(f));
        }
    }
    QVector<int> candidates;
    for (int i = 0; i < frames.size(); ++i) {
        const TrackedFrame &f = frames[i];
        if (!f.lost && f.confidence >= kSureShare * sure && eyesOpen(f) >= kEyesOpenShare * widestEyes
            && std::abs(f.motion.rotationDeg) <= kFrontalDeg)
            candidates.append(i);
    }
    if (candidates.isEmpty())
        candidates.append(0); // the first frame the face was found on
    if (std::any_of(candidates.cbegin(), candidates.cend(), [&](int i) { return silent[i]; }))
        candidates.removeIf([&](int i) { return !silent[i]; });
    double closest = outerParting(frames[candidates.first()]);
    for (int i : std::as_const(candidates))
        closest = std::min(closest, outerParting(frames[i]));
    for (int i : std::as_const(candidates)) {
        if (outerParting(frames[i]) <= closest + kClosedToleranceEs0) {
            choice.frame = frames[i].index;
            choice.silent = silent[i];
            break;
        }
    }
    return choice;
}

} // namespace toonface
