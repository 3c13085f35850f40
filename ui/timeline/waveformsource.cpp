#include "timeline/waveformsource.h"

#include <QDateTime>
#include <QFileInfo>
#include <QHash>
#include <QMutex>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toonface {

namespace {

constexpr int kCacheEntries = 4;
// The share of millisecond peaks allowed above the loudness: a few clicks or a cough in a
// long quiet take must not shrink the speech back to a flat line.
constexpr double kLoudnessQuantile = 0.999;

double loudnessOf(const WaveformPeaks &peaks)
{
    if (peaks.isEmpty())
        return 0;
    const WaveformPeaks::Level &level = peaks.levels().first();
    std::vector<float> magnitudes(size_t(level.max.size()));
    for (qsizetype i = 0; i < level.max.size(); ++i)
        magnitudes[size_t(i)] = std::max(std::abs(level.min[i]), std::abs(level.max[i]));
    if (magnitudes.empty())
        return 0;
    const auto nth = magnitudes.begin() + qsizetype(double(magnitudes.size() - 1) * kLoudnessQuantile);
    std::nth_element(magnitudes.begin(), nth, magnitudes.end());
    return *nth;
}

struct PeakCache
{
    QMutex mutex;
    QHash<QString, std::shared_ptr<const WaveformSource::Shown>> entries;
    QStringList order; // least recently used first
};

PeakCache &cache()
{
    static PeakCache c;
    return c;
}

QString cacheKey(const QString &path)
{
    const QFileInfo info(path);
    return QStringLiteral("%1|%2|%3")
        .arg(info.absoluteFilePath())
        .arg(info.size())
        .arg(info.lastModified().toMSecsSinceEpoch());
}

std::shared_ptr<const WaveformSource::Shown> cached(const QString &key)
{
    PeakCache &c = cache();
    QMutexLocker lock(&c.mutex);
    const auto it = c.entries.constFind(key);
    if (it == c.entries.constEnd())
        return {};
    c.order.removeAll(key);
    c.order.append(key);
    return *it;
}

void store(const QString &key, std::shared_ptr<const WaveformSource::Shown> peaks)
{
    PeakCache &c = cache();
    QMutexLocker lock(&c.mutex);
    c.entries.insert(key, std::move(peaks));
    c.order.removeAll(key);
    c.order.append(key);
    while (c.order.size() > kCacheEntries)
        c.entries.remove(c.order.takeFirst());
}

const std::shared_ptr<const WaveformSource::Shown> &noPeaks()
{
    static const std::shared_ptr<const WaveformSource::Shown> none = std::make_shared<WaveformSource::Shown>();
    return none;
}

} // namespace

WaveformSource::WaveformSource(QObject *parent)
    : QObject(parent)
    , m_peaks(noPeaks())
{
    connect(&m_watcher, &QFutureWatcher<std::pair<WaveformPeaksResult, double>>::finished, this,
        &WaveformSource::onFinished);
}

WaveformSource::~WaveformSource()
{
    if (m_cancel)
        m_cancel->store(true);
    m_watcher.waitForFinished();
}

void WaveformSource::clearCache()
{
    PeakCache &c = cache();
    QMutexLocker lock(&c.mutex);
    c.entries.clear();
    c.order.clear();
}

void WaveformSource::setPath(const QString &path)
{
    if (path == m_path && (isLoading() || !m_peaks->peaks.isEmpty() || !m_error.isEmpty()))
        return;
    m_path = path;
    m_error.clear();
    m_peaks = noPeaks();
    if (m_cancel)
        m_cancel->store(true);
    m_loadingKey.clear();
    if (path.isEmpty()) {
        Q_EMIT ready();
        return;
    }
    const QString key = cacheKey(path);
    if (auto peaks = cached(key)) {
        m_peaks = std::move(peaks);
        Q_EMIT ready();
        return;
    }
    // A load of another file still running finishes cancelled; its result is dropped.
    m_watcher.waitForFinished();
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_loadingKey = key;
    auto cancel = m_cancel;
    m_watcher.setFuture(QtConcurrent::run([path, cancel]() {
        WaveformPeaksResult result = loadWaveformPeaks(path, {}, cancel.get());
        const double loudness = loudnessOf(result.peaks);
        return std::pair(std::move(result), loudness);
    }));
}

void WaveformSource::waitForFinished()
{
    if (!m_watcher.isRunning() && m_loadingKey.isEmpty())
        return;
    m_watcher.waitForFinished();
    onFinished();
}

void WaveformSource::onFinished()
{
    if (m_loadingKey.isEmpty() || !m_watcher.isFinished())
        return;
    const auto [result, loudness] = m_watcher.result();
    const QString key = m_loadingKey;
    m_loadingKey.clear();
    if (result.status == AudioStatus::Cancelled)
        return;
    if (!result.ok()) {
        m_error = result.error;
    } else {
        auto peaks = std::make_shared<const Shown>(Shown {result.peaks, loudness});
        store(key, peaks);
        m_peaks = std::move(peaks);
    }
    Q_EMIT ready();
}

} // namespace toonface
