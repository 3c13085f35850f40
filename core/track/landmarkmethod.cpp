#include "detect/landmarkfit.h"
#include "detect/landmarkmap.h"
#include "track/trackingmethod.h"

#include <QLineF>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace toonface {

namespace {

// A fit whose points lie farther than this from the model's mean shape (in box sides, after the
// best similarity) is no face: faces give 0.03-0.06.
constexpr double kMaxResidual = 0.12;
// Missed checks in a row after which the face counts as gone and is searched for anew.
constexpr int kMissesToForget = 2;

double logistic(double x)
{
    return 1.0 / (1.0 + std::exp(-x));
}

// The face's look at a glance: the grey levels of a kPatch x kPatch grid over `box`, less their
// mean, divided by their spread (all 0 for a flat patch).
constexpr int kPatch = 16;
using Patch = std::array<float, kPatch * kPatch>;

Patch facePatch(const QImage &gray, const QRectF &box)
{
    Patch p {};
    double sum = 0;
    for (int j = 0; j < kPatch; ++j) {
        const int y = std::clamp(int(box.top() + (j + 0.5) * box.height() / kPatch), 0, gray.height() - 1);
        const uchar *row = gray.constScanLine(y);
        for (int i = 0; i < kPatch; ++i) {
            const int x = std::clamp(int(box.left() + (i + 0.5) * box.width() / kPatch), 0, gray.width() - 1);
            p[j * kPatch + i] = row[x];
            sum += row[x];
        }
    }
    const float mean = float(sum / p.size());
    double sq = 0;
    for (float &v : p) {
        v -= mean;
        sq += double(v) * v;
    }
    const float spread = float(std::sqrt(sq / p.size()));
    for (float &v : p)
        v = spread > 2.0f ? v / spread : 0.0f;
    return p;
}

// Normalised cross-correlation of two patches: 1 alike, 0 unrelated.
double similarity(const Patch &a, const Patch &b)
{
    double s = 0;
    for (size_t i = 0; i < a.size(); ++i)
        s += double(a[i]) * b[i];
    return s / a.size();
}

// Below this the face region looks different from the frame before (a face gone, covered or
// swapped): the detector checks at once instead of waiting for its turn.
constexpr double kMinSimilarity = 0.7;

class LandmarkMethod : public TrackingMethod
{
public:
    LandmarkMethod(std::shared_ptr<const LandmarkPredictor> model, QRectF neutralBox, int verifyInterval)
        : m_model(std::move(model))
        , m_lastBox(neutralBox)
        , m_verifyInterval(std::max(1, verifyInterval))
    {
        for (const char *id : {"3.12", "3.8", "3.11", "3.7", "9.15", "9.4", "9.5"})
            m_stable.append(pt::idx(id));
    }

    QString name() const override { return detectionMethodName(DetectionMethod::Landmarks); }

    void forget() override
    {
        m_previous.reset();
        m_lastPatch.reset();
        m_misses = 0;
    }

    FaceMeasurement measure(const QImage &frame) override
    {
        FaceMeasurement m;
        m.stable = m_stable;
        const QImage gray = landmarkGray(frame);
        Landmarks68 shape;
        double score = 0;
        bool verified = false;
        if (!m_previous) {
            const std::vector<FaceCandidate> faces = findFaceCandidates(gray);
            if (faces.empty())
                return m;
            // The face nearest to where it was last seen.
            const FaceCandidate *best = &faces.front();
            for (const FaceCandidate &f : faces) {
                if (QLineF(f.box.center(), m_lastBox.center()).length()
                    < QLineF(best->box.center(), m_lastBox.center()).length())
                    best = &f;
            }
            shape = fitLandmarksInBox(*m_model, gray, best->box);
            score = best->score;
            verified = true;
            m_sinceCheck = 0;
        } else {
            shape = fitLandmarksFrom(*m_model, gray, *m_previous);
        }
        const ImpliedBox implied = impliedBox(*m_model, shape);
        const QRectF inFrame = implied.box.intersected(QRectF(frame.rect()));
        const bool plausible = implied.residual < kMaxResidual && implied.box.width() > 16
            && inFrame.width() * inFrame.height() > 0.5 * implied.box.width() * implied.box.height();
        const Patch patch = plausible ? facePatch(gray, implied.box) : Patch {};
        const bool changed = !m_lastPatch || similarity(patch, *m_lastPatch) < kMinSimilarity;
        if (plausible && !verified && (++m_sinceCheck >= m_verifyInterval || m_misses > 0 || changed)) {
            m_sinceCheck = 0;
            const double side = implied.box.width();
            const FaceCandidate check
                = verifyFace(gray, implied.box.adjusted(-0.5 * side, -0.5 * side, 0.5 * side, 0.5 * side), side);
            if (check.box.isEmpty()) {
                ++m_misses;
            } else {
                verified = true;
                score = check.score;
            }
        } else if (plausible && !verified) {
            verified = m_misses == 0; // between checks the last check stands
            score = m_lastScore;
        }
        if (!plausible || !verified) {
            if (!plausible || m_misses >= kMissesToForget)
                forget();
            return m; // not found this frame; the fit still seeds the next one unless forgotten
        }
        m_misses = 0;
        m_lastScore = score;
        m_previous = shape;
        m_lastPatch = patch;
        m_lastBox = implied.box;

        const FaceModel face = faceFromLandmarks68(shape, frame.size());
        m.points = face.points();
        auto outline = [&](int first) {
            QVector<QPointF> p;
            for (int i = first; i < first + 6; ++i)
                p.append(shape[i]);
            return p;
        };
        m.points[pt::idx("3.6")] = locatePupil(gray, outline(36));
        m.points[pt::idx("3.5")] = locatePupil(gray, outline(42));
        m.found = true;
        // The detector's margin (0 at its threshold), lowered as the fit strays from a face's shape.
        m.confidence = (0.5 + 0.5 * logistic(2.0 * score)) * std::clamp(1.5 - implied.residual / 0.08, 0.0, 1.0);
        return m;
    }

private:
    std::shared_ptr<const LandmarkPredictor> m_model;
    QVector<int> m_stable;
    std::optional<Landmarks68> m_previous;
    std::optional<Patch> m_lastPatch;
    QRectF m_lastBox;
    int m_verifyInterval = 1;
    int m_sinceCheck = 0;
    int m_misses = 0;
    double m_lastScore = 0;
};

} // namespace

std::unique_ptr<TrackingMethod> makeLandmarkMethod(const DetectionResult &neutral, int verifyInterval, QString *error)
{
    auto model = sharedLandmarkModel(error);
    if (!model)
        return nullptr;
    return std::make_unique<LandmarkMethod>(std::move(model), QRectF(neutral.faceBox), verifyInterval);
}

} // namespace toonface
