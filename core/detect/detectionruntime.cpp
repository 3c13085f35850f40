#include "detect/detectionruntime.h"

#include "detect/detector.h"
#include "detect/facescan.h"

#include <QCoreApplication>

#include <opencv2/core/utility.hpp>

#include <future>
#include <mutex>
#include <thread>

namespace toonface {

namespace {

// The first pass of a detection scans a copy of the photo whose shorter side is 240 pixels
// (detector.cpp): a 4:3 frame of that height is what the warm-up scans.
constexpr QSize kFirstPassSize(320, 240);

// OpenCV's first parallel loop starts its pool of threads (TBB's here: a library loaded,
// workers started; 10-30 ms, more than the detection's whole regions stage), and the
// regions' connected components run the first of a detection: started here instead, beside
// the other one-time work.
void startParallelLoops()
{
    cv::parallel_for_(cv::Range(0, 2), [](const cv::Range &) {});
}

struct SharedModel
{
    std::mutex mutex;
    QString path;
    std::shared_ptr<const LandmarkPredictor> model;
    LandmarkModelLoad load;
};

SharedModel &sharedModel()
{
    static SharedModel shared;
    return shared;
}

// The warm-up's two threads: one makes the face detector ready (decoding it takes 0.4 s when
// its cache is not made yet), scans a blank frame, then runs the stages after the landmarks
// once; the other loads the landmark model (0.2 s to read dlib's file when its cache is not
// made yet), writes its cache and starts OpenCV's threads. With the caller's thread going on with its own start-up,
// the two cores of a small machine are both at work, and a first run that makes both caches
// pays for the longer of the two, not their sum.
class WarmUp
{
public:
    static WarmUp &instance()
    {
        static WarmUp warmUp;
        return warmUp;
    }

    void start(bool refinement)
    {
        std::call_once(m_started, [this, refinement] {
            // The application waits for the threads before it tears down what they use.
            qAddPostRoutine(&waitForDetectionWarmUp);
            std::lock_guard lock(m_mutex);
            if (refinement)
                m_refinementReady = m_refinementDone.get_future().share();
            m_stages = std::thread([this, refinement] {
                warmUpFaceScan(kFirstPassSize);
                if (refinement) {
                    warmUpFaceRefinement();
                    m_refinementDone.set_value();
                }
            });
            m_model = std::thread([] {
                sharedLandmarkModel(nullptr);
                startParallelLoops();
            });
        });
    }

    void awaitRefinement()
    {
        std::shared_future<void> ready;
        {
            std::lock_guard lock(m_mutex);
            ready = m_refinementReady;
        }
        if (ready.valid())
            ready.wait();
    }

    void wait()
    {
        std::lock_guard lock(m_mutex);
        if (m_model.joinable())
            m_model.join();
        if (m_stages.joinable())
            m_stages.join();
    }

    ~WarmUp() { wait(); }

private:
    WarmUp()
    {
        // Made before the threads start, so destroyed after they have been waited for.
        sharedModel();
    }

    std::once_flag m_started;
    std::mutex m_mutex;
    std::promise<void> m_refinementDone;
    std::shared_future<void> m_refinementReady; // valid once a warm-up with the refinement started
    std::thread m_model;
    std::thread m_stages;
};

} // namespace

std::shared_ptr<const LandmarkPredictor> sharedLandmarkModel(QString *error, LandmarkModelLoad *load)
{
    const QString path = landmarkModelPath();
    SharedModel &shared = sharedModel();
    std::unique_lock lock(shared.mutex);
    if (shared.model && shared.path == path) {
        if (load) {
            *load = shared.load;
            load->ms = 0;
        }
        return shared.model;
    }
    LandmarkModelLoad loaded = loadLandmarkModel(path, detectionCacheDir(), CacheWrite::Later);
    const auto writeCache = std::move(loaded.writeCache);
    loaded.writeCache = nullptr;
    if (!loaded.model) {
        if (load)
            *load = loaded;
        if (error)
            *error = loaded.error;
        return {};
    }
    shared.path = path;
    shared.model = loaded.model;
    shared.load = loaded;
    if (writeCache) {
        // The model is handed on first: a detection waiting for it goes on while its cache is
        // written (on the warm-up's thread, when the warm-up loaded it).
        lock.unlock();
        writeCache(&loaded);
        lock.lock();
        if (shared.model == loaded.model) {
            shared.load.cache = loaded.cache;
            shared.load.cacheNote = loaded.cacheNote;
        }
    }
    if (load)
        *load = loaded;
    return loaded.model;
}

bool preloadLandmarkModel(QString *error, double *loadMs)
{
    LandmarkModelLoad load;
    const bool ok = bool(sharedLandmarkModel(error, &load));
    if (loadMs)
        *loadMs = load.ms;
    return ok;
}

LandmarkModelLoad landmarkModelLoad()
{
    SharedModel &shared = sharedModel();
    std::lock_guard lock(shared.mutex);
    return shared.load;
}

void warmUpDetection()
{
    WarmUp::instance().start(true);
}

void warmUpDetectionModels()
{
    WarmUp::instance().start(false);
}

void awaitFaceRefinementWarmUp()
{
    WarmUp::instance().awaitRefinement();
}

void waitForDetectionWarmUp()
{
    WarmUp::instance().wait();
}

} // namespace toonface
