#include "detect/facescan.h"

#include "detect/grayview.h"
#include "i18n/coretext.h"

#include <QDir>
#include <QElapsedTimer>

#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/revision.h>
#include <dlib/serialize.h>

#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace toonface {

namespace {

constexpr char kKind[5] = "HOGD";

// The detector's cache belongs to the dlib that made it: its version is the key.
CacheKey detectorKey()
{
    return {quint64(DLIB_MAJOR_VERSION) * 1000000 + DLIB_MINOR_VERSION * 1000 + DLIB_PATCH_VERSION, 0, 0};
}

QString detectorCachePath(const QString &cacheDir)
{
    return QDir(cacheDir).filePath(QStringLiteral("frontal_face_detector-dlib%1.%2.%3.detector-cache")
                                       .arg(DLIB_MAJOR_VERSION)
                                       .arg(DLIB_MINOR_VERSION)
                                       .arg(DLIB_PATCH_VERSION));
}

std::span<const std::byte> bytesOf(const std::string &s)
{
    return std::as_bytes(std::span(s.data(), s.size()));
}

// dlib's frontal face detector, from its cache in `cacheDir` or decoded (and the cache written).
FaceDetectorLoad loadDetector(const QString &cacheDir, dlib::frontal_face_detector *out)
{
    QElapsedTimer timer;
    timer.start();
    FaceDetectorLoad load;
    if (!cacheDir.isEmpty()) {
        load.cachePath = detectorCachePath(cacheDir);
        CachedBlock cached;
        if (readCacheFile(load.cachePath, kKind, detectorKey(), &cached, &load.cacheNote)) {
            try {
                std::istringstream in(
                    std::string(reinterpret_cast<const char *>(cached.bytes.data()), cached.bytes.size()));
                dlib::deserialize(*out, in);
                if (out->num_detectors() > 0) {
                    load.cache = CacheUse::Used;
                    load.fingerprint = cacheChecksum(cached.bytes);
                    load.ms = timer.nsecsElapsed() / 1e6;
                    return load;
                }
                load.cacheNote = DetectText::tr("the cache is damaged (it holds no detector)");
            } catch (const std::exception &e) {
                load.cacheNote
                    = DetectText::tr("the cache is damaged (%1)").arg(QString::fromLocal8Bit(e.what()).trimmed());
            }
        }
    }
    *out = dlib::get_frontal_face_detector();
    std::ostringstream serialised;
    dlib::serialize(*out, serialised);
    const std::string bytes = serialised.str();
    load.fingerprint = cacheChecksum(bytesOf(bytes));
    if (!cacheDir.isEmpty()) {
        QString error;
        if (writeCacheFile(load.cachePath, kKind, detectorKey(), bytesOf(bytes), &error)) {
            load.cache = CacheUse::Built;
        } else {
            load.cache = CacheUse::NotWritten;
            load.cacheNote += QStringLiteral("; ") + error;
        }
    }
    load.ms = timer.nsecsElapsed() / 1e6;
    return load;
}

// dlib's face detector allocates a hundred or so arrays per scan (the HOG planes of every
// pyramid level and their filtered copies), and its speed depends on where they fall: on
// this project's machines the same 320 x 240 scan took 5.6 ms or 19 ms from one detection to
// the next, following what the rest of the detection had allocated and freed on the thread's
// heap. Scanning on a thread of its own, whose heap (glibc's per-thread arena) holds only the
// scanner's arrays, gives the same layout every time: 5.6-6.3 ms. The scan threads live as
// long as the process, one for each detection running at once, so that detections on several
// threads still run side by side, and a thread warmed up at launch serves the first detection
// whichever thread it runs on.
class ScanThread
{
public:
    ScanThread()
        : m_thread([this] { loop(); })
    { }
    ~ScanThread()
    {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }

    // Runs `job` on the scan thread and waits for it; an exception it throws is rethrown here.
    void run(const std::function<void()> &job)
    {
        std::unique_lock lock(m_mutex);
        m_job = &job;
        m_error = nullptr;
        m_wake.notify_all();
        m_wake.wait(lock, [this] { return m_job == nullptr; });
        if (m_error)
            std::rethrow_exception(m_error);
    }

    // The detector scanning at most `levels` pyramid levels, for jobs on this thread (it keeps
    // scratch buffers, so is not shared).
    dlib::frontal_face_detector &detector(const dlib::frontal_face_detector &all, unsigned long levels)
    {
        auto it = m_detectors.find(levels);
        if (it != m_detectors.end())
            return it->second;
        if (levels == 0)
            return m_detectors.emplace(levels, all).first->second;
        dlib::frontal_face_detector::image_scanner_type scanner;
        scanner.copy_configuration(all.get_scanner());
        scanner.set_max_pyramid_levels(levels);
        std::vector<dlib::frontal_face_detector::feature_vector_type> filters;
        for (unsigned long i = 0; i < all.num_detectors(); ++i)
            filters.push_back(all.get_w(i));
        return m_detectors.emplace(levels, dlib::frontal_face_detector(scanner, all.get_overlap_tester(), filters))
            .first->second;
    }

private:
    void loop()
    {
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_wake.wait(lock, [this] { return m_stop || m_job != nullptr; });
            if (m_stop)
                return;
            try {
                (*m_job)();
            } catch (...) {
                m_error = std::current_exception();
            }
            m_job = nullptr;
            m_wake.notify_all();
        }
    }

    std::map<unsigned long, dlib::frontal_face_detector> m_detectors; // used on the thread only
    std::mutex m_mutex;
    std::condition_variable m_wake;
    const std::function<void()> *m_job = nullptr;
    std::exception_ptr m_error;
    bool m_stop = false;
    std::thread m_thread; // last: started once the members it uses exist
};

// The detector as dlib decodes it (once per process, tens of milliseconds) and the scan
// threads not in use.
class FaceScanner
{
public:
    static FaceScanner &instance()
    {
        static FaceScanner scanner;
        return scanner;
    }

    const dlib::frontal_face_detector &all()
    {
        std::call_once(m_decoded, [this] {
            dlib::frontal_face_detector detector;
            const FaceDetectorLoad load = loadDetector(detectionCacheDir(), &detector);
            std::lock_guard lock(m_mutex);
            m_load = load;
            m_all.emplace(std::move(detector));
        });
        return *m_all;
    }

    FaceDetectorLoad load()
    {
        std::lock_guard lock(m_mutex);
        return m_load;
    }

    // A scan thread for one scan, back among the idle ones when the lease ends.
    struct Lease
    {
        FaceScanner *owner;
        std::unique_ptr<ScanThread> thread;
        bool warmUp;
        ~Lease() { owner->giveBack(std::move(thread), warmUp); }
    };

    // An idle scan thread, or a new one. While the warm-up scans its blank frame, a scan
    // waits for the thread it warms (a few milliseconds) instead of starting one whose heap
    // is cold: the first detection of a process is served by the warmed thread.
    Lease lease(bool warmUp)
    {
        std::unique_ptr<ScanThread> thread;
        {
            std::unique_lock lock(m_mutex);
            if (!warmUp)
                m_returned.wait(lock, [this] { return !m_idle.empty() || m_warming == 0; });
            if (!m_idle.empty()) {
                thread = std::move(m_idle.back());
                m_idle.pop_back();
            }
            if (warmUp)
                ++m_warming;
        }
        if (!thread)
            thread = std::make_unique<ScanThread>();
        return Lease {this, std::move(thread), warmUp};
    }

private:
    void giveBack(std::unique_ptr<ScanThread> thread, bool warmUp)
    {
        {
            std::lock_guard lock(m_mutex);
            m_idle.push_back(std::move(thread));
            if (warmUp)
                --m_warming;
        }
        m_returned.notify_all();
    }

    std::once_flag m_decoded;
    std::optional<dlib::frontal_face_detector> m_all;
    std::mutex m_mutex;
    FaceDetectorLoad m_load;
    std::vector<std::unique_ptr<ScanThread>> m_idle;
    std::condition_variable m_returned; // a thread back among the idle ones
    int m_warming = 0; // warm-up scans under way
};

std::vector<FaceBox> scan(const QImage &gray, unsigned long levels, bool warmUp)
{
    FaceScanner &scanner = FaceScanner::instance();
    const dlib::frontal_face_detector &all = scanner.all();
    std::vector<dlib::rect_detection> dets;
    {
        const FaceScanner::Lease lease = scanner.lease(warmUp);
        ScanThread *thread = lease.thread.get();
        thread->run([&] { thread->detector(all, levels)(viewOf(gray), dets); });
    }
    std::vector<FaceBox> out;
    for (const auto &d : dets)
        out.push_back({QRectF(d.rect.left(), d.rect.top(), d.rect.width(), d.rect.height()), d.detection_confidence});
    return out;
}

} // namespace

std::vector<FaceBox> scanFaces(const QImage &gray, unsigned long levels)
{
    return scan(gray, levels, false);
}

FaceDetectorLoad loadFaceDetector(const QString &cacheDir)
{
    dlib::frontal_face_detector detector;
    return loadDetector(cacheDir, &detector);
}

FaceDetectorLoad faceDetectorLoad()
{
    return FaceScanner::instance().load();
}

void warmUpFaceScan(QSize size)
{
    QImage blank(size.expandedTo(QSize(1, 1)), QImage::Format_Grayscale8);
    blank.fill(128);
    scan(blank, 0, true);
}

} // namespace toonface
