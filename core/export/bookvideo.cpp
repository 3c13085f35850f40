#include "export/bookvideo.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/videoencoder.h"
#include "face/pose.h"
#include "i18n/coretext.h"
#include "media/audiofeed.h"
#include "render/svgface.h"

#include <QCryptographicHash>
#include <QDir>
#include <QHash>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <cmath>
#include <list>

namespace toonface {

namespace {

// The pages' sound: speech keeps its sound below 12 kHz (the book's MP3 is at this rate too).
constexpr int kSoundRate = 24000;
// 320 pixels show the mouth's shapes clearly in a page's column; larger frames cost their
// area in drawing time on every frame of the book.
constexpr int kFrameSide = 320;
// Half the film rate: a syllable (a quarter of a second) still shows its mouth shapes in three
// frames, as animation drawn "on twos" does, and a book draws half the frames.
constexpr double kFrameRate = 12.5;
// Poses closer than half a pixel of the frame draw the same picture (antialiasing hides less).
constexpr double kPoseStepPixels = 0.5;
// Pictures of recent poses kept for reuse: a sentence's mouth shapes and the rest between
// sentences come back within a few seconds (64 frames of 320 pixels hold 26 MB).
constexpr int kKeptPictures = 64;
// Frames whose poses are found, drawn (distinct ones in parallel) and encoded together.
constexpr int kBatchFrames = 25;
// x264's speed preset for the pages: the faces' flat colours and still backgrounds compress
// well even with the fastest analysis ("superfast" keeps CABAC, which "ultrafast" drops).
const char *const kPreset = "superfast";

QByteArray keyOf(const Pose &pose)
{
    // The rounded values are exact multiples of the step: their bytes name the pose.
    QCryptographicHash hash(QCryptographicHash::Md5);
    hash.addData(QByteArrayView(reinterpret_cast<const char *>(pose.offset.data()), qsizetype(sizeof(pose.offset))));
    const double rest[] = {pose.leftEyeOpen, pose.rightEyeOpen, pose.head.rotationDeg, pose.head.translation.x(),
        pose.head.translation.y(), pose.head.scale};
    hash.addData(QByteArrayView(reinterpret_cast<const char *>(rest), qsizetype(sizeof(rest))));
    return hash.result();
}

double roundTo(double v, double step)
{
    return std::round(v / step) * step;
}

} // namespace

Pose roundedPose(const Pose &pose, double step)
{
    Pose r = pose;
    for (QPointF &p : r.offset)
        p = QPointF(roundTo(p.x(), step), roundTo(p.y(), step));
    // A lid travels about ten pixels of the face, a head turns about a hundred pixels from its
    // centre: their steps move an edge by about `step` as well.
    r.leftEyeOpen = roundTo(pose.leftEyeOpen, step / 10);
    r.rightEyeOpen = roundTo(pose.rightEyeOpen, step / 10);
    r.head.rotationDeg = roundTo(pose.head.rotationDeg, step * 0.5);
    r.head.translation = QPointF(roundTo(pose.head.translation.x(), step), roundTo(pose.head.translation.y(), step));
    r.head.scale = roundTo(pose.head.scale, step / 100);
    return r;
}

// The last kKeptPictures pictures drawn, by pose; the least recently used goes first.
struct PageVideoWriter::Pictures
{
    std::list<std::pair<QByteArray, QImage>> order; // most recent first
    QHash<QByteArray, std::list<std::pair<QByteArray, QImage>>::iterator> byKey;

    const QImage *find(const QByteArray &key)
    {
        const auto it = byKey.find(key);
        if (it == byKey.end())
            return nullptr;
        order.splice(order.begin(), order, *it);
        return &order.front().second;
    }
    void keep(const QByteArray &key, const QImage &picture)
    {
        if (byKey.contains(key))
            return;
        order.emplace_front(key, picture);
        byKey.insert(key, order.begin());
        if (order.size() > size_t(kKeptPictures)) {
            byKey.remove(order.back().first);
            order.pop_back();
        }
    }
};

PageVideoWriter::PageVideoWriter(const BookRequest &request, const QString &folder)
    : m_request(request)
    , m_folder(folder)
    , m_pictures(std::make_unique<Pictures>())
{ }

PageVideoWriter::~PageVideoWriter() = default;

QSize PageVideoWriter::frameSize()
{
    return {kFrameSide, kFrameSide};
}

double PageVideoWriter::frameRate()
{
    return kFrameRate;
}

bool PageVideoWriter::openSound(const QString &soundPath, QString *error)
{
    m_feed = std::make_unique<av::AudioFeed>();
    m_at = 0;
    return m_feed->open(AudioSource::fromFile(soundPath), error) && m_feed->start(kSoundRate, error);
}

bool PageVideoWriter::readSound(qint64 beginMs, qint64 endMs, QVector<float> *samples, QString *error)
{
    // The page's stretch of the sound, read forward from where the last page ended.
    const qint64 begin = std::max(m_at, qint64(std::llround(double(beginMs) * kSoundRate / 1000.0)));
    const qint64 end = std::max(begin, qint64(std::llround(double(endMs) * kSoundRate / 1000.0)));
    QVector<float> skipped;
    while (m_at < begin) {
        skipped.resize(std::min<qint64>(begin - m_at, 1 << 16));
        if (!m_feed->read(skipped.data(), int(skipped.size()), error))
            return false;
        m_at += skipped.size();
    }
    samples->resize(end - begin);
    if (!samples->isEmpty() && !m_feed->read(samples->data(), int(samples->size()), error))
        return false;
    m_at = end;
    return true;
}

QString PageVideoWriter::write(const Timeline &timeline, qint64 beginMs, qint64 endMs, const std::atomic_bool *cancel,
    ExportStatus *status, QString *error)
{
    *status = ExportStatus::Failed;
    if (!m_feed) {
        *error = withProblem(m_request.outputPath, ExportText::tr("no sound to cut the page's video from"));
        return {};
    }
    if (!m_face) {
        auto face = std::make_unique<SvgFace>(m_request.face, m_request.style);
        face->setFrame(headFrame(m_request.face));
        for (const QString &layer : m_request.layerFiles) {
            if (!face->addLayerFile(layer, error)) {
                *status = ExportStatus::BadInput;
                return {};
            }
        }
        m_face = std::move(face);
    }
    QVector<float> sound;
    if (!readSound(beginMs, endMs, &sound, error))
        return {};

    // The sound sets the video's length: a page ending in a pause keeps it.
    const double seconds = double(sound.size()) / kSoundRate;
    const int frames = std::max(1, int(std::ceil(seconds * kFrameRate - 1e-9)));
    const QSize size = frameSize();
    const QRectF frame = m_face->frame();
    const double step = kPoseStepPixels * std::max(frame.width(), frame.height()) / kFrameSide;
    const TimelineEvaluator evaluator(timeline, m_face->face(), m_request.mouthShapes);

    const QString path = QDir(m_folder).filePath(QStringLiteral("page.mp4"));
    VideoOptions options;
    options.preset = QString::fromLatin1(kPreset);
    options.mp4AudioRate = kSoundRate; // the speech as it was made, not resampled to 48 kHz
    VideoWriter writer;
    if (!writer.open(path, VideoFormat::Mp4, size, kFrameRate, AudioSource::fromSamples(std::move(sound), kSoundRate),
            error, options))
        return {};
    const SvgFace &face = *m_face;
    for (int from = 0; from < frames; from += kBatchFrames) {
        if (cancel && cancel->load()) {
            writer.cancel();
            *status = ExportStatus::Cancelled;
            *error = withProblem(m_request.outputPath, QStringLiteral("cancelled"));
            return {};
        }
        const int count = std::min(kBatchFrames, frames - from);
        QVector<QByteArray> keys(count);
        QVector<Pose> missing; // distinct poses of the batch not drawn recently
        QHash<QByteArray, QImage> batch;
        for (int i = 0; i < count; ++i) {
            const Pose pose = roundedPose(evaluator.evaluate((from + i) / kFrameRate), step);
            keys[i] = keyOf(pose);
            if (batch.contains(keys[i]))
                continue;
            if (const QImage *kept = m_pictures->find(keys[i]))
                batch.insert(keys[i], *kept);
            else {
                batch.insert(keys[i], QImage());
                missing.append(pose);
            }
        }
        const QList<QImage> drawn = QtConcurrent::blockingMapped(
            missing, [&face, size](const Pose &pose) { return rasterizeSvg(face.svg(pose), size, Qt::white); });
        for (qsizetype k = 0; k < missing.size(); ++k) {
            const QByteArray key = keyOf(missing[k]);
            batch[key] = drawn[k];
            m_pictures->keep(key, drawn[k]);
        }
        m_drawn += missing.size();
        for (int i = 0; i < count; ++i) {
            if (!writer.addFrame(batch.value(keys[i]), error)) {
                writer.cancel();
                return {};
            }
        }
        m_written += count;
    }
    if (!writer.finish(error))
        return {};
    *status = ExportStatus::Done;
    return path;
}

} // namespace toonface
