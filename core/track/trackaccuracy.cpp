#include "track/trackaccuracy.h"

#include "detect/landmarkfit.h"
#include "detect/landmarkmap.h"
#include "i18n/coretext.h"
#include "track/clipsilence.h"
#include "track/retarget.h"
#include "track/videofilesource.h"

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

void appendSignals(ClipSignals *s, double time, const std::array<QPointF, kPointCount> &p)
{
    auto at = [&](const char *id) { return p[pt::idx(id)]; };
    const double es0 = QLineF(at("3.6"), at("3.5")).length();
    s->times.append(time);
    s->mouthOpen.append(es0 > 0 ? std::max(0.0, at("2.3").y() - at("2.2").y()) / es0 : 0.0);
    s->eyeOpen.append(
        es0 > 0 ? (QLineF(at("3.2"), at("3.4")).length() + QLineF(at("3.1"), at("3.3")).length()) / 2 / es0 : 0.0);
}

} // namespace

std::optional<ClipSignals> referenceSignals(const QString &path, QString *error)
{
    const auto model = sharedLandmarkModel(error);
    if (!model)
        return std::nullopt;
    VideoFileSource source;
    if (!source.open(path, error))
        return std::nullopt;
    ClipSignals s;
    bool anyFace = false;
    while (std::optional<VideoFrame> f = source.next()) {
        const QImage gray = landmarkGray(f->image);
        const std::vector<FaceCandidate> faces = findFaceCandidates(gray);
        if (faces.empty()) {
            if (!s.times.isEmpty()) {
                s.times.append(f->time);
                s.mouthOpen.append(s.mouthOpen.last());
                s.eyeOpen.append(s.eyeOpen.last());
            }
            continue;
        }
        const FaceCandidate *best = &faces.front();
        for (const FaceCandidate &c : faces) {
            if (c.box.width() > best->box.width())
                best = &c;
        }
        const FaceModel face = faceFromLandmarks68(fitLandmarksInBox(*model, gray, best->box), f->image.size());
        appendSignals(&s, f->time, face.points());
        anyFace = true;
    }
    if (!anyFace) {
        if (error)
            *error = source.error().isEmpty() ? VideoText::tr("%1: no face in any frame").arg(path) : source.error();
        return std::nullopt;
    }
    return s;
}

ClipSignals trackedSignals(const TrackResult &track)
{
    ClipSignals s;
    // The neutral's lid apertures in ES0, as the tracking measured them.
    double neutralEye = 0;
    {
        ClipSignals n;
        appendSignals(&n, 0, track.neutral.face.points());
        neutralEye = n.eyeOpen.value(0);
    }
    for (const TrackedFrame &f : track.frames) {
        s.times.append(f.time);
        s.mouthOpen.append(f.motion.mouthOpenEs0);
        s.eyeOpen.append((f.motion.leftEyeOpen + f.motion.rightEyeOpen) / 2 * neutralEye);
    }
    return s;
}

double pearson(const QVector<double> &a, const QVector<double> &b)
{
    const qsizetype n = std::min(a.size(), b.size());
    if (n < 2)
        return 0;
    double ma = 0, mb = 0;
    for (qsizetype i = 0; i < n; ++i) {
        ma += a[i] / n;
        mb += b[i] / n;
    }
    double sab = 0, saa = 0, sbb = 0;
    for (qsizetype i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

TrackAccuracy compareSignals(const ClipSignals &tracked, const ClipSignals &reference, double fps)
{
    TrackAccuracy a;
    a.mouthCorrelation = pearson(tracked.mouthOpen, reference.mouthOpen);
    a.eyeCorrelation = pearson(tracked.eyeOpen, reference.eyeOpen);
    const QVector<BlinkEvent> ref = detectBlinks(reference.times, reference.eyeOpen, fps);
    const QVector<BlinkEvent> got = detectBlinks(tracked.times, tracked.eyeOpen, fps);
    const double near = 2.0 / (fps > 0 ? fps : 25.0);
    a.referenceBlinks = int(ref.size());
    auto matches = [&](const BlinkEvent &x, const QVector<BlinkEvent> &in) {
        return std::any_of(in.cbegin(), in.cend(),
            [&](const BlinkEvent &y) { return std::abs(blinkMiddle(x) - blinkMiddle(y)) <= near; });
    };
    for (const BlinkEvent &r : ref)
        a.blinksFound += matches(r, got);
    for (const BlinkEvent &g : got)
        a.extraBlinks += !matches(g, ref);
    return a;
}

SoundAgreement mouthSoundAgreement(const QVector<TrackedFrame> &frames, const QVector<float> &samples, int sampleRate,
    double period, int maxLeadFrames)
{
    QVector<double> parting, loudness;
    for (const TrackedFrame &f : frames) {
        const auto &d = f.motion.displacementEs0;
        parting.append(d[pt::idx("8.2")].y() - d[pt::idx("8.9")].y());
    }
    for (double db : frameLevelsDb(frames, samples, sampleRate, period))
        loudness.append(db > -120.0 ? std::pow(10.0, db / 20.0) : 0.0); // the RMS
    SoundAgreement a;
    a.correlationInSync = pearson(parting, loudness);
    a.correlation = a.correlationInSync;
    for (int lead = 1; lead <= maxLeadFrames && lead < parting.size() - 1; ++lead) {
        // The mouth of frame i against the sound of frame i + lead.
        const double r = pearson(parting.mid(0, parting.size() - lead), loudness.mid(lead));
        if (r > a.correlation) {
            a.correlation = r;
            a.leadFrames = lead;
        }
    }
    return a;
}

} // namespace toonface
