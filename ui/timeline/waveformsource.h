#pragma once

#include "speech/waveformpeaks.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

namespace toonface {

// The waveform of the project's sound for the timeline: decodes the file and computes its
// peaks off the GUI thread (QtConcurrent), then says ready(). Peaks are kept in a small
// process-wide cache keyed by the file's path, size and modification time, so an undo that
// brings a sound back, or a project opened again, shows it at once.
//
// Lives on the GUI thread.
class WaveformSource : public QObject
{
    Q_OBJECT

public:
    // What is shown of one file (cached).
    struct Shown
    {
        WaveformPeaks peaks;
        double loudness = 0;
    };

    explicit WaveformSource(QObject *parent = nullptr);
    // Cancels a load under way and waits for it.
    ~WaveformSource() override;

    // Shows `path` (empty: none). Loading starts unless the path is the one shown or loading;
    // a cached file is shown at once.
    void setPath(const QString &path);
    QString path() const { return m_path; }

    const WaveformPeaks &peaks() const { return m_peaks->peaks; }
    // How loud the sound is for drawing: a high percentile of its millisecond peaks (0..1), so
    // that a quiet recording can be drawn as tall as a loud one and one click does not set the
    // scale. 0 when there is no sound or it is silent.
    double loudness() const { return m_peaks->loudness; }
    // Why the sound cannot be shown (names the file), empty when it can or is loading.
    QString error() const { return m_error; }
    bool isLoading() const { return m_watcher.isRunning(); }
    // Blocks until a load under way has finished and been taken (tests, benchmarks).
    void waitForFinished();

    // Empties the process-wide cache (tests).
    static void clearCache();

Q_SIGNALS:
    // The peaks (or the error) of path() are there.
    void ready();

private:
    void onFinished();

    QString m_path;
    QString m_error;
    std::shared_ptr<const Shown> m_peaks;
    QFutureWatcher<std::pair<WaveformPeaksResult, double>> m_watcher;
    std::shared_ptr<std::atomic_bool> m_cancel;
    QString m_loadingKey;
};

} // namespace toonface
