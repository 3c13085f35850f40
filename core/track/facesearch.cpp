#include "track/facesearch.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// The look is compared this many pixels wide: the eyes, the brows and the mouth stay apart,
// and a search over a whole frame costs a millisecond or two.
constexpr int kLookWidth = 16;
constexpr double kSizes[] = {0.8, 0.9, 1.0, 1.12, 1.25};

cv::Mat greyOf(const QImage &image)
{
    const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
    return cv::Mat(
        grey.height(), grey.width(), CV_8UC1, const_cast<uchar *>(grey.constBits()), size_t(grey.bytesPerLine()))
        .clone();
}

} // namespace

struct FaceSearch::Look
{
    cv::Mat picture; // the neutral look, kLookWidth wide
    double factor = 1; // look pixels per frame pixel at the neutral size
};

FaceSearch::FaceSearch(const QImage &neutralFrame, const QRectF &box)
{
    const QRect r = box.toAlignedRect();
    if (neutralFrame.isNull() || r.width() < 8 || r.height() < 8 || !neutralFrame.rect().contains(r))
        return;
    auto look = std::make_unique<Look>();
    look->factor = kLookWidth / box.width();
    const int height = std::max(4, int(std::lround(box.height() * look->factor)));
    cv::resize(greyOf(neutralFrame.copy(r)), look->picture, cv::Size(kLookWidth, height), 0, 0, cv::INTER_AREA);
    m_look = std::move(look);
}

FaceSearch::~FaceSearch() = default;

bool FaceSearch::isValid() const
{
    return m_look != nullptr;
}

FaceSearchHit FaceSearch::find(const QImage &frame) const
{
    FaceSearchHit best;
    for (const FaceSearchHit &hit : findEachSize(frame))
        if (hit.likeness > best.likeness)
            best = hit;
    return best;
}

std::vector<FaceSearchHit> FaceSearch::findEachSize(const QImage &frame) const
{
    std::vector<FaceSearchHit> hits;
    if (!m_look || frame.isNull())
        return hits;
    // The frame shrunk once for the smallest size (the largest picture needed), then further
    // for the others.
    const double largest = std::min(1.0, m_look->factor / kSizes[0]);
    const QImage first = frame.convertToFormat(QImage::Format_Grayscale8)
                             .scaled(std::max(1, int(std::lround(frame.width() * largest))),
                                 std::max(1, int(std::lround(frame.height() * largest))), Qt::IgnoreAspectRatio,
                                 Qt::SmoothTransformation);
    const cv::Mat grey = greyOf(first);
    for (double size : kSizes) {
        // A face `size` times the neutral's looks like the look in the frame shrunk by factor / size.
        const double f = m_look->factor / size;
        const cv::Size small(int(std::lround(frame.width() * f)), int(std::lround(frame.height() * f)));
        if (small.width < m_look->picture.cols || small.height < m_look->picture.rows)
            continue;
        cv::Mat shrunk, scores;
        if (small == grey.size())
            shrunk = grey;
        else
            cv::resize(grey, shrunk, small, 0, 0, cv::INTER_AREA);
        cv::matchTemplate(shrunk, m_look->picture, scores, cv::TM_CCOEFF_NORMED);
        double top = 0;
        cv::Point at;
        cv::minMaxLoc(scores, nullptr, &top, nullptr, &at);
        if (std::isfinite(top))
            hits.push_back({QRectF(at.x / f, at.y / f, m_look->picture.cols / f, m_look->picture.rows / f), top});
    }
    return hits;
}

} // namespace toonface
