#include "window/applydetection.h"

#include "detect/photocolours.h"
#include "document/document.h"
#include "document/undomacro.h"
#include "face/headturn.h"
#include "views/displaynames.h"

#include <QCoreApplication>

#include <cmath>

namespace toonface {

namespace {

// The context of this file's strings in the translations.
struct ApplyDetection
{
    Q_DECLARE_TR_FUNCTIONS(toonface::ApplyDetection)
};

} // namespace

void applyDetection(Document *document, const DetectionResult &result, DetectionUse use, bool choseFace)
{
    if (use == DetectionUse::NewFace) {
        const QString text = choseFace ? ApplyDetection::tr("Use another face") : ApplyDetection::tr("Detect face");
        Style style = document->style();
        sampleColours(document->photo(), result.face, &style);
        const UndoMacro step(document->undoStack(), text);
        document->replaceFace(result.face, false, text);
        document->changeStyle(style, ApplyDetection::tr("Sample colours"));
    } else {
        const bool keep = use == DetectionUse::KeepHandPlaced;
        document->replaceFace(result.face, keep,
            keep ? ApplyDetection::tr("Re-detect keeping my points") : ApplyDetection::tr("Re-detect points"));
    }
}

QString turnedFaceWarning(const FaceModel &face)
{
    const HeadTurn turn = headTurn(face);
    if (!turnedTooFar(turn))
        return {};
    const QString how = std::abs(turn.yawDeg) >= std::abs(turn.rollDeg)
        ? ApplyDetection::tr("The face is turned about %1° to the side.").arg(qRound(std::abs(turn.yawDeg)))
        : ApplyDetection::tr("The head is tilted about %1°.").arg(qRound(std::abs(turn.rollDeg)));
    return how + QLatin1Char(' ')
        + ApplyDetection::tr("The cartoon is drawn from the front and will look twisted: a photo looking straight "
                             "into the camera works best.");
}

QString detectionSummary(const DetectionResult &result, bool choseFace)
{
    const int ms = qRound(result.timingMs.value(QStringLiteral("total")));
    QString found;
    if (result.faceCount <= 1)
        found = ApplyDetection::tr("Face found by the %1 method in %2 ms.").arg(variantTitle(result.method)).arg(ms);
    else if (choseFace)
        found = ApplyDetection::tr("%n faces found: using the one you chose (%1, %2 ms).", nullptr, result.faceCount)
                    .arg(variantTitle(result.method))
                    .arg(ms);
    else
        found = ApplyDetection::tr(
            "%n faces found: using the largest, most central one (%1, %2 ms). Click another face's box "
            "to switch.",
            nullptr, result.faceCount)
                    .arg(variantTitle(result.method))
                    .arg(ms);
    if (!result.note.isEmpty())
        found += QLatin1Char(' ') + ApplyDetection::tr("The landmark method could not serve: %1").arg(result.note);
    if (const QString turned = turnedFaceWarning(result.face); !turned.isEmpty())
        found += QLatin1Char(' ') + turned;
    return found;
}

} // namespace toonface
