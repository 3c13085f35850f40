#include "window/applydetection.h"

#include "document/document.h"
#include "document/undomacro.h"

#include <QCoreApplication>

namespace toonface {

namespace {

QString tr(const char *text, int n = -1)
{
    return QCoreApplication::translate("MainWindow", text, nullptr, n);
}

} // namespace

void applyDetection(Document *document, const DetectionResult &result, DetectionUse use, bool choseFace)
{
    if (use == DetectionUse::NewFace) {
        const QString text = choseFace ? tr("Use another face") : tr("Detect face");
        Style style = document->style();
        style.sampleColours(document->photo(), result.face);
        const UndoMacro step(document->undoStack(), text);
        document->replaceFace(result.face, false, text);
        document->changeStyle(style, tr("Sample colours"));
    } else {
        const bool keep = use == DetectionUse::KeepHandPlaced;
        document->replaceFace(result.face, keep, keep ? tr("Re-detect keeping my points") : tr("Re-detect points"));
    }
}

QString detectionSummary(const DetectionResult &result, bool choseFace)
{
    const int ms = qRound(result.timingMs.value(QStringLiteral("total")));
    QString found;
    if (result.faceCount <= 1)
        found = tr("Face found by the %1 method in %2 ms.").arg(result.method).arg(ms);
    else if (choseFace)
        found = tr("%n faces found: using the one you chose (%1, %2 ms).", result.faceCount).arg(result.method).arg(ms);
    else
        found = tr("%n faces found: using the largest, most central one (%1, %2 ms). Click another face's box "
                   "to switch.",
            result.faceCount)
                    .arg(result.method)
                    .arg(ms);
    if (!result.note.isEmpty())
        found += QLatin1Char(' ') + tr("The landmark method could not serve: %1").arg(result.note);
    return found;
}

} // namespace toonface
