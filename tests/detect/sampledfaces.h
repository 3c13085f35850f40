#pragma once

#include "detect/appearance.h"
#include "detect/detector.h"
#include "detect/photocolours.h"
#include "render/style.h"
#include "shareddata.h"

#include <QImage>
#include <QStringList>

#include <vector>

namespace toonface::testing {

// A labelled face as the drawing sees it: the landmark detector's face on its photo, the
// "normal" style with the colours sampled from the photo, and what the appearance analysis
// found there.
struct SampledFace
{
    LabelledFace row;
    DetectionResult detection;
    Style style;
    AppearanceFindings found;
};

// The labelled faces the detector finds (the faces it misses are left out), each detected and
// sampled once in a process: several tests of a suite read the same faces. `skip` says why
// there are none (the set or the landmark model is absent); `unreadable`, the photos that could
// not be read (a test fails on them).
struct SampledFaces
{
    std::vector<SampledFace> faces;
    QString skip;
    QStringList unreadable;
};

inline const SampledFaces &sampledLabelledFaces()
{
    static const SampledFaces sampled = [] {
        SampledFaces out;
        const QList<LabelledFace> labelled = labelledFaces();
        if (labelled.isEmpty()) {
            out.skip = QString::fromLatin1(kNoLabelledFaces);
            return out;
        }
        for (const LabelledFace &row : labelled) {
            const QImage photo(row.photoPath);
            if (photo.isNull()) {
                out.unreadable << row.photoPath;
                continue;
            }
            SampledFace face {row, detectFace(photo), Style::preset(QStringLiteral("normal")), {}};
            if (face.detection.status == DetectStatus::ModelMissing) {
                out.faces.clear();
                out.skip = QStringLiteral("the landmark model is not installed");
                return out;
            }
            if (face.detection.status != DetectStatus::Ok)
                continue;
            sampleColours(photo, face.detection.face, &face.style, &face.found);
            out.faces.push_back(std::move(face));
        }
        return out;
    }();
    return sampled;
}

} // namespace toonface::testing

// Opens a test over the sampled labelled faces: skips when there are none, fails on a photo that
// could not be read.
#define TOONFACE_SAMPLED_FACES(name)                                                                                   \
    const toonface::testing::SampledFaces &name = toonface::testing::sampledLabelledFaces();                           \
    if (!name.skip.isEmpty())                                                                                          \
        QSKIP(qPrintable(name.skip));                                                                                  \
    QVERIFY2(name.unreadable.isEmpty(), qPrintable(name.unreadable.join(QLatin1String(", "))))
