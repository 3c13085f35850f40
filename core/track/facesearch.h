#pragma once

// Finding a face again by how it looked: the classic tracking method follows the eyes from frame
// to frame, so a face that left and comes back elsewhere (the person stepped aside, the camera
// panned) must be searched for over the whole frame. The neutral frame's look of the face (a
// small grey picture of the eyes and the mouth) is matched at every place and at a few sizes.

#include <QImage>
#include <QRectF>

#include <memory>
#include <vector>

namespace toonface {

struct FaceSearchHit
{
    QRectF box; // where the neutral box is now, frame pixels
    double likeness = 0; // normalised cross-correlation, -1..1
};

class FaceSearch
{
public:
    // The face's look: `box` (frame pixels) of the neutral frame.
    FaceSearch(const QImage &neutralFrame, const QRectF &box);
    ~FaceSearch();
    FaceSearch(const FaceSearch &) = delete;
    FaceSearch &operator=(const FaceSearch &) = delete;

    bool isValid() const;
    // The best place of the face in `frame`, at sizes from 0.8 to 1.25 of the neutral's; an empty
    // box when the frame is smaller than the face.
    FaceSearchHit find(const QImage &frame) const;
    // The best place at each of those sizes, smallest first (sizes the frame cannot hold left
    // out): the look alone may prefer a wrong size by a little (a mouth opened since the neutral
    // frame stretches the face), the caller may check each.
    std::vector<FaceSearchHit> findEachSize(const QImage &frame) const;

private:
    struct Look;
    std::unique_ptr<Look> m_look;
};

} // namespace toonface
