#include "capture/framedecoder.h"

#include "track/videofilesource.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <cmath>
#include <deque>
#include <utility>

namespace toonface {

namespace {

// Frames kept for going back a little (a step back, a repaint) without reopening the file.
constexpr qsizetype kCacheBytes = 48 * 1024 * 1024;
constexpr int kCacheFramesMax = 32;
// Further ahead than this, a jump seeks (through the file's index) rather than reading on.
constexpr double kReadOnSeconds = 3.0;

} // namespace

// The file being read, its position and the frames kept. Used by one pool thread at a time
// (FrameDecoder never starts a decode while one runs).
struct FrameDecoder::Reader
{
    QString path;
    std::unique_ptr<VideoFileSource> source;
    int next = 0; // the index the source delivers next
    std::deque<std::pair<int, QImage>> cache; // most recent last
    std::atomic_int decoded {0}; // frames decoded, for the tests and the bench

    bool reopen(QString *error)
    {
        source = std::make_unique<VideoFileSource>();
        next = 0;
        if (source->open(path, error))
            return true;
        source.reset();
        return false;
    }

    void keep(int index, const QImage &image)
    {
        cache.emplace_back(index, image);
        qsizetype bytes = 0;
        for (const auto &kept : cache)
            bytes += kept.second.sizeInBytes();
        while (cache.size() > 1 && (int(cache.size()) > kCacheFramesMax || bytes > kCacheBytes)) {
            bytes -= cache.front().second.sizeInBytes();
            cache.pop_front();
        }
    }

    QImage frame(int index, QString *error)
    {
        for (const auto &kept : cache) {
            if (kept.first == index)
                return kept.second;
        }
        if (!source && !reopen(error))
            return {};
        const int readOn = int(std::lround(kReadOnSeconds * (source->frameRate() > 0 ? source->frameRate() : 25.0)));
        if (index < next || index > next + readOn) {
            // A jump: back, or far ahead. A file that cannot seek is read from its start.
            if (!source->seek(index) && !reopen(error))
                return {};
        }
        while (std::optional<VideoFrame> f = source->next()) {
            ++decoded;
            next = f->index + 1;
            if (f->index == index) {
                keep(index, f->image);
                return f->image;
            }
            if (f->index > index)
                break;
        }
        const QString problem = source->error();
        *error = !problem.isEmpty()
            ? problem
            : QCoreApplication::translate("toonface::FrameDecoder", "%1: has no frame %2 (it has %3)")
                  .arg(path)
                  .arg(index)
                  .arg(next);
        source.reset(); // at its end or broken: the next request starts over
        return {};
    }
};

struct FrameDecoder::Outcome
{
    int generation = 0;
    int index = 0;
    QImage image;
    QString error;
};

FrameDecoder::FrameDecoder(QObject *parent)
    : QObject(parent)
{ }

FrameDecoder::~FrameDecoder() = default;

bool FrameDecoder::open(const QString &path, QString *error)
{
    close();
    VideoFileSource probe;
    if (!probe.open(path, error))
        return false;
    m_path = path;
    m_fps = probe.frameRate();
    m_frameCount = probe.frameCount();
    m_size = probe.frameSize();
    m_hasAudio = probe.hasAudio();
    m_duration = probe.duration();
    m_reader = std::make_shared<Reader>();
    m_reader->path = path;
    return true;
}

void FrameDecoder::close()
{
    ++m_generation;
    m_path.clear();
    m_fps = 0;
    m_frameCount = -1;
    m_size = {};
    m_hasAudio = false;
    m_duration = 0;
    m_reader.reset();
    m_running = -1;
    m_pending = -1;
    m_shown = -1;
}

int FrameDecoder::framesDecoded() const
{
    return m_reader ? m_reader->decoded.load() : 0;
}

void FrameDecoder::request(int index)
{
    if (!m_reader || index < 0)
        return;
    if (m_running >= 0) {
        if (index == m_running) {
            if (m_pending >= 0)
                ++m_dropped;
            m_pending = -1;
            return;
        }
        if (m_pending >= 0 && m_pending != index)
            ++m_dropped;
        m_pending = index;
        return;
    }
    if (index == m_shown)
        return;
    m_pending = index;
    startNext();
}

void FrameDecoder::startNext()
{
    if (m_pending < 0 || !m_reader)
        return;
    m_running = std::exchange(m_pending, -1);
    const int generation = m_generation;
    const int index = m_running;
    auto *watcher = new QFutureWatcher<Outcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        watcher->deleteLater();
        const Outcome o = watcher->future().result();
        onDecoded(o.generation, o.index, o.image, o.error);
    });
    watcher->setFuture(QtConcurrent::run([reader = m_reader, generation, index] {
        Outcome o {generation, index, {}, {}};
        o.image = reader->frame(index, &o.error);
        return o;
    }));
}

void FrameDecoder::onDecoded(int generation, int index, const QImage &image, const QString &error)
{
    if (generation != m_generation)
        return; // a file closed since
    m_running = -1;
    if (image.isNull()) {
        Q_EMIT failed(index, error);
    } else {
        m_shown = index;
        Q_EMIT frameReady(index, image);
    }
    if (m_pending == m_shown)
        m_pending = -1;
    startNext();
}

} // namespace toonface
