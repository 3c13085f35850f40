#include "track/tracker.h"

#include "face/fapu.h"
#include "i18n/coretext.h"
#include "track/trackingmethod.h"

#include <QLineF>

#include <cmath>
#include <limits>
#include <numbers>

namespace toonface {

namespace {

QPointF at(const std::array<QPointF, kPointCount> &p, const char *id)
{
    return p[pt::idx(id)];
}

} // namespace

// One filter per quantity of FaceMotion.
struct Tracker::Filters
{
    std::array<OneEuroFilter, 2 * kPointCount> points;
    std::array<OneEuroFilter, 4> head; // rotation, translation x, y, scale
    std::array<OneEuroFilter, 2> lids;
    std::array<OneEuroFilter, 2> gaze;
    double lastTime = 0;
    bool started = false;

    explicit Filters(const TrackerOptions &o)
    {
        for (auto &f : points)
            f = OneEuroFilter(o.points);
        // Degrees: a still head jitters by tenths of a degree, a turn runs at tens a second.
        head[0] = OneEuroFilter({o.points.minCutoff, o.points.beta / 20.0, o.points.derivativeCutoff});
        head[1] = head[2] = head[3] = OneEuroFilter(o.points);
        for (auto &f : lids)
            f = OneEuroFilter(o.lids);
        for (auto &f : gaze)
            f = OneEuroFilter(o.points);
    }
    void reset()
    {
        for (auto &f : points)
            f.reset();
        for (auto &f : head)
            f.reset();
        for (auto &f : lids)
            f.reset();
        for (auto &f : gaze)
            f.reset();
        started = false;
    }
};

Tracker::Tracker(TrackerOptions options)
    : m_options(std::move(options))
    , m_filters(std::make_unique<Filters>(m_options))
{ }

Tracker::~Tracker() = default;
Tracker::Tracker(Tracker &&) noexcept = default;
Tracker &Tracker::operator=(Tracker &&) noexcept = default;

bool Tracker::setNeutral(const QImage &frame, QString *error, DetectStatus *status)
{
    auto failWith = [&](DetectStatus s, const QString &message) {
        m_method.reset();
        if (error)
            *error = message;
        if (status)
            *status = s;
        return false;
    };
    if (frame.isNull())
        return failWith(DetectStatus::BadImage, VideoText::tr("the neutral frame is empty"));
    DetectOptions detect;
    detect.method = m_options.method;
    m_neutral = detectFace(frame, detect);
    if (m_neutral.status != DetectStatus::Ok)
        return failWith(m_neutral.status, m_neutral.error);

    QString problem;
    m_method.reset();
    if (m_neutral.method != detectionMethodName(DetectionMethod::Classic))
        m_method = makeLandmarkMethod(m_neutral, m_options.verifyInterval, &problem);
    if (!m_method && m_options.method != DetectionMethod::Landmarks)
        m_method = makeClassicMethod(m_neutral, &problem);
    if (!m_method)
        return failWith(DetectStatus::ModelMissing, problem);
    m_neutralMeasure = m_method->measure(frame);
    if (!m_neutralMeasure.found || !(neutralEs0() > 0))
        return failWith(DetectStatus::NoFace,
            VideoText::tr("the %1 tracking cannot follow the face it detected on the neutral frame").arg(methodName()));

    const FaceModel &face = m_neutral.face;
    const double es0 = face.fapu().es0;
    const std::array<QPointF, 4> shut = m_options.shapes.displacements(MouthShape::M, face);
    for (MouthShape s : kAllMouthShapes) {
        const std::array<QPointF, 4> d = m_options.shapes.displacements(s, face, &shut);
        for (int k = 0; k < 4; ++k)
            m_shapesEs0[int(s)][k] = es0 > 0 ? (d[k] - shut[k]) / es0 : QPointF();
    }
    restart();
    return true;
}

double Tracker::neutralEs0() const
{
    return QLineF(at(m_neutralMeasure.points, "3.6"), at(m_neutralMeasure.points, "3.5")).length();
}

QString Tracker::methodName() const
{
    return m_method ? m_method->name() : QString();
}

void Tracker::restart()
{
    m_filters->reset();
    m_last.reset();
}

MouthShape Tracker::nearestMouthShape(const std::array<QPointF, 4> &mouthEs0) const
{
    MouthShape best = MouthShape::M;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (MouthShape s : kAllMouthShapes) {
        if (s == MouthShape::N)
            continue;
        double sum = 0;
        for (int k = 0; k < 4; ++k) {
            const QPointF diff = mouthEs0[k] - m_shapesEs0[int(s)][k];
            sum += QPointF::dotProduct(diff, diff);
        }
        if (sum < bestDistance) {
            bestDistance = sum;
            best = s;
        }
    }
    return best;
}

TrackedFrame Tracker::track(const VideoFrame &frame)
{
    TrackedFrame out;
    out.index = frame.index;
    out.time = frame.time;
    const FaceMeasurement measured = m_method->measure(frame.image);
    if (!measured.found) {
        // Lost: hold the last pose (the neutral one when none was seen yet).
        if (m_last) {
            out.points = m_last->points;
            out.motion = m_last->motion;
            out.mouthShape = m_last->mouthShape;
        } else {
            out.points = m_neutralMeasure.points;
        }
        out.lost = true;
        out.confidence = 0;
        m_filters->reset();
        return out;
    }

    FaceMotion motion = measureMotion(m_neutralMeasure, measured);
    Filters &f = *m_filters;
    if (m_options.smooth) {
        const double dt = f.started ? frame.time - f.lastTime : 0.0;
        for (int i = 0; i < kPointCount; ++i) {
            QPointF &d = motion.displacementEs0[i];
            d = QPointF(f.points[2 * i].filter(d.x(), dt), f.points[2 * i + 1].filter(d.y(), dt));
        }
        motion.rotationDeg = f.head[0].filter(motion.rotationDeg, dt);
        motion.translationEs0
            = QPointF(f.head[1].filter(motion.translationEs0.x(), dt), f.head[2].filter(motion.translationEs0.y(), dt));
        motion.scale = f.head[3].filter(motion.scale, dt);
        motion.leftEyeOpen = f.lids[0].filter(motion.leftEyeOpen, dt);
        motion.rightEyeOpen = f.lids[1].filter(motion.rightEyeOpen, dt);
        motion.gazeEs0 = QPointF(f.gaze[0].filter(motion.gazeEs0.x(), dt), f.gaze[1].filter(motion.gazeEs0.y(), dt));
        f.started = true;
        f.lastTime = frame.time;
    }

    const double es0 = neutralEs0();
    if (m_options.snapMouth) {
        std::array<QPointF, 4> mouth;
        for (int k = 0; k < 4; ++k)
            mouth[k] = motion.displacementEs0[pt::idx(kMouthControlIds[k])];
        const MouthShape s = nearestMouthShape(mouth);
        out.mouthShape = s;
        for (int k = 0; k < 4; ++k)
            motion.displacementEs0[pt::idx(kMouthControlIds[k])] = m_shapesEs0[int(s)][k];
    }
    const auto &n = m_neutralMeasure.points;
    motion.mouthOpenEs0 = std::max(0.0,
                              (at(n, "2.3").y() + motion.displacementEs0[pt::idx("2.3")].y() * es0)
                                  - (at(n, "2.2").y() + motion.displacementEs0[pt::idx("2.2")].y() * es0))
        / es0;

    // The points in the frame: the neutral ones displaced, carried by the (filtered) head.
    const double angle = motion.rotationDeg * std::numbers::pi / 180.0;
    HeadMotion head;
    head.a = motion.scale * std::cos(angle);
    head.b = motion.scale * std::sin(angle);
    const QPointF eyeMid = (at(n, "3.6") + at(n, "3.5")) / 2.0;
    head.t = eyeMid + motion.translationEs0 * es0
        - QPointF(head.a * eyeMid.x() - head.b * eyeMid.y(), head.b * eyeMid.x() + head.a * eyeMid.y());
    for (int i = 0; i < kPointCount; ++i)
        out.points[i] = head.map(n[i] + motion.displacementEs0[i] * es0);
    out.motion = motion;
    out.confidence = measured.confidence;
    m_last = out;
    return out;
}

} // namespace toonface
