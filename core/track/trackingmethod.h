#pragma once

#include "detect/detector.h"
#include "track/facemeasure.h"

#include <QImage>
#include <QString>

#include <memory>

namespace toonface {

// One way of measuring a face frame after frame (private to core/track: the Tracker drives it).
// A method keeps what it learnt from the frame before (where the face was); not thread-safe.
class TrackingMethod
{
public:
    virtual ~TrackingMethod() = default;
    virtual QString name() const = 0;
    // Measures the face in `frame`, starting from where it was in the frame before.
    virtual FaceMeasurement measure(const QImage &frame) = 0;
    // The face was lost: the next measure() searches the whole frame.
    virtual void forget() = 0;
};

// The landmark model seeded by the previous frame's face; the face detector re-finds the face
// only when it is lost, and checks every `verifyInterval`-th frame near the fitted face that a
// face is there. nullptr with *error when the model cannot be loaded.
std::unique_ptr<TrackingMethod> makeLandmarkMethod(const DetectionResult &neutral, int verifyInterval, QString *error);

// Thesis chapter 6 on the neutral detection's TrackingSeed: eyes by region growing from the
// reserved eyeballs on the t1-thresholded intensity, checked as an eye pair (the old pair stands
// in when none is found), each eye's aperture from the dark between its lids; the mouth region
// grown from the reserved one (carried by the head) on the Sobel image thresholded by the
// reserved edge threshold, its opening from the dark between the lips and the growth of the
// mouth's darkness and edges. The first frame measured must be the neutral one: later frames
// are compared with it. nullptr with *error when the seed is not valid.
std::unique_ptr<TrackingMethod> makeClassicMethod(const DetectionResult &neutral, QString *error);

} // namespace toonface
