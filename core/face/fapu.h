#pragma once

#include <QPointF>

namespace toonface {

class FaceModel;

// Facial animation parameter units of face-model.md, in pixels, measured once on the
// neutral face. Shapes and emotions are expressed in these units so that they do not
// depend on the photo's size.
struct Fapu
{
    double es0 = 0; // distance between eyeball centres 3.6 and 3.5 (the thesis' d)
    double ens0 = 0; // vertical distance EyeMid -> nose tip 9.15
    double mns0 = 0; // vertical distance nose tip 9.15 -> upper inner lip 2.2
    double mw0 = 0; // distance between mouth corners 8.4 and 8.3
    double leftEyeH = 0; // 3.2 - 3.4
    double rightEyeH = 0; // 3.1 - 3.3
    double upperLipH = 0; // 8.1 - 2.2
    double lowerLipH = 0; // 2.3 - 8.2
    double jawH = 0; // vertical distance 8.2 -> chin 2.1

    // The thesis' pixel constants ("1", "3") were measured at ES0 = 100 px.
    double pixel() const { return es0 / 100.0; }
    QPointF eyeMid; // midpoint of the eyeball centres

    static Fapu measure(const FaceModel &face);
};

} // namespace toonface
