// Hair and hairline on faces found by the classic method (detectFace with DetectionMethod::Classic):
// the forehead 11.1 where the hair starts, the outline around the hair, bald heads bald.

#include "detect/appearance.h"
#include "detect/detector.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "media/mediareader.h"
#include "render/style.h"
#include "shareddata.h"
#include "testmain.h"

#include <QDir>
#include <QFileInfo>
#include <QLineF>
#include <QPainter>
#include <QTest>

#include <cmath>

using namespace toonface;
using testing::DrawnFaceOptions;

namespace {

struct Looked
{
    DetectionResult result;
    AppearanceFindings findings;
    Style style;
};

Looked classicLook(const QImage &photo)
{
    Looked out;
    DetectOptions options;
    options.method = DetectionMethod::Classic;
    out.result = detectFace(photo, options);
    if (out.result.status == DetectStatus::Ok)
        sampleColours(photo, out.result.face, &out.style, &out.findings);
    return out;
}

double es0(const FaceModel &face)
{
    return QLineF(face.point("3.6"), face.point("3.5")).length();
}

} // namespace

class TestClassicHair : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A drawn face with hair: the classic method's face has its hairline 11.1 at the drawn
    // hairline (the top of the skin on the midline), within a tenth of the eye distance, the
    // hair outline's top h.10 at the drawn hair's top within a fifth, and is drawn with hair.
    void drawnHairline()
    {
        const FaceModel truth = testing::drawnFaceModel();
        const QImage photo = testing::drawnFace(DrawnFaceOptions {});
        const Looked look = classicLook(photo);
        QCOMPARE(look.result.status, DetectStatus::Ok);
        QCOMPARE(look.result.method, QStringLiteral("classic"));
        const FaceModel &face = look.result.face;
        const double d = es0(truth);
        qInfo("11.1 (%.1f, %.1f), drawn (%.1f, %.1f); h.10 (%.1f, %.1f), drawn (%.1f, %.1f); bald score %.2f, skin "
              "reach %.2f",
            face.point("11.1").x(), face.point("11.1").y(), truth.point("11.1").x(), truth.point("11.1").y(),
            face.point("h.10").x(), face.point("h.10").y(), truth.point("h.10").x(), truth.point("h.10").y(),
            look.findings.baldScore, look.findings.skinReach);
        QVERIFY(QLineF(face.point("11.1"), truth.point("11.1")).length() < 0.1 * d);
        QVERIFY(QLineF(face.point("h.10"), truth.point("h.10")).length() < 0.2 * d);
        // The temples under the hair, not above it: below the hairline, above the brows.
        for (const char *id : {"11.2", "11.3"})
            QVERIFY2(face.point(id).y() > face.point("11.1").y() && face.point(id).y() < face.point("4.4").y(), id);
        QVERIFY(!look.style.appearance.bald);
        QVERIFY(!look.style.appearance.hat);
        // The photo's hair search and the regions are timed with the pipeline's stages.
        for (const char *stage : {"hair", "regions", "total"})
            QVERIFY2(look.result.timingMs.contains(QLatin1StringView(stage)), stage);
        QVERIFY(
            look.result.timingMs.value(QStringLiteral("total")) >= look.result.timingMs.value(QStringLiteral("hair"))
                + look.result.timingMs.value(QStringLiteral("regions")));
    }

    // The same face over a neck of its skin's colour, joined to the jaw, and a dark shirt: the
    // classic method's face region runs on down the neck and its chin with it, but the hair is still the drawn hair's
    // (the hair's estimate holds the chin within a face's proportions), and the measured chin is
    // kept.
    void drawnHairOverANeck()
    {
        const FaceModel truth = testing::drawnFaceModel();
        const DrawnFaceOptions o;
        QImage photo = testing::drawnFace(o);
        const double d = es0(truth);
        {
            QPainter p(&photo);
            p.setPen(Qt::NoPen);
            p.setBrush(o.skin);
            const QPointF chin = truth.point("2.1");
            p.drawRect(QRectF(chin.x() - 0.6 * d, chin.y() - 0.3 * d, 1.2 * d, 1.1 * d));
            // A dark shirt below it.
            p.setBrush(QColor(40, 45, 60));
            p.drawRect(QRectF(0, chin.y() + 0.8 * d, photo.width(), photo.height()));
        }
        const DetectionResult plain = classicLook(testing::drawnFace(o)).result;
        const Looked look = classicLook(photo);
        QCOMPARE(look.result.status, DetectStatus::Ok);
        const FaceModel &face = look.result.face;
        const double eyeY = (face.point("3.6").y() + face.point("3.5").y()) / 2;
        qInfo("over a neck: chin drop %.2f ES0 (%.2f without the neck); h.10 (%.1f, %.1f), drawn (%.1f, %.1f)",
            (face.point("2.1").y() - eyeY) / d, (plain.face.point("2.1").y() - eyeY) / d, face.point("h.10").x(),
            face.point("h.10").y(), truth.point("h.10").x(), truth.point("h.10").y());
        // The neck did lengthen the measured face (else this test tests nothing) ...
        QVERIFY(face.point("2.1").y() - eyeY > 2.5 * d);
        QVERIFY(face.point("2.1").y() > plain.face.point("2.1").y() + 0.3 * d);
        // ... but not the hair: the hairline within a tenth of the eye distance, the crown within a
        // quarter (believed chin or not, a longer face draws the search's estimate a little higher).
        QVERIFY(QLineF(face.point("11.1"), truth.point("11.1")).length() < 0.1 * d);
        QVERIFY(QLineF(face.point("h.10"), truth.point("h.10")).length() < 0.25 * d);
        QVERIFY(!look.style.appearance.bald);
    }

    // The same face drawn bald stays bald: the skin goes up to the head's top.
    void drawnBald()
    {
        DrawnFaceOptions o;
        o.bald = true;
        const Looked look = classicLook(testing::drawnFace(o));
        QCOMPARE(look.result.status, DetectStatus::Ok);
        qInfo("bald: 11.1 y %.1f, h.10 y %.1f, bald score %.2f, skin reach %.2f", look.result.face.point("11.1").y(),
            look.result.face.point("h.10").y(), look.findings.baldScore, look.findings.skinReach);
        QVERIFY(look.style.appearance.bald);
        QVERIFY(!look.style.appearance.hat);
    }

    // Two drawn faces side by side, the left with hair, the right bald: the face asked for by a
    // point is the one found (the classic method looks in the face detector's box that holds the
    // point), with its own hair or scalp.
    void faceAsked()
    {
        DrawnFaceOptions bald;
        bald.bald = true;
        const QImage left = testing::drawnFace(DrawnFaceOptions {}), right = testing::drawnFace(bald);
        QImage both(2 * left.width(), left.height(), QImage::Format_RGB32);
        {
            QPainter p(&both);
            p.drawImage(0, 0, left);
            p.drawImage(left.width(), 0, right);
        }
        const FaceModel truth = testing::drawnFaceModel();
        const double d = es0(truth);
        for (const bool onRight : {false, true}) {
            const QPointF shift(onRight ? left.width() : 0, 0);
            DetectOptions options;
            options.method = DetectionMethod::Classic;
            options.faceAt = truth.point("9.15") + shift;
            const DetectionResult r = detectFace(both, options);
            QVERIFY2(r.status == DetectStatus::Ok, qPrintable(r.error));
            Style style;
            sampleColours(both, r.face, &style);
            qInfo("asked for the %s face: eyes at (%.0f, %.0f) and (%.0f, %.0f), bald %d", onRight ? "right" : "left",
                r.face.point("3.6").x(), r.face.point("3.6").y(), r.face.point("3.5").x(), r.face.point("3.5").y(),
                style.appearance.bald);
            QVERIFY(QLineF(r.face.point("3.6"), truth.point("3.6") + shift).length() < 0.1 * d);
            QVERIFY(QLineF(r.face.point("3.5"), truth.point("3.5") + shift).length() < 0.1 * d);
            QCOMPARE(style.appearance.bald, onRight);
        }
    }

    // The first frame of the GRID clip bbaf2n (a man with short dark hair on a blue wall): the
    // classic method's hairline and hair outline agree with the landmark method's, within a
    // quarter and a third of the eye distance; his hair is hair.
    void gridFrame()
    {
        const QString clip = QDir(testing::sharedDataDir()).filePath(QStringLiteral("video/bbaf2n.mpg"));
        if (!QFileInfo::exists(clip))
            QSKIP("the GRID clips of shared/data/video are absent");
        QString error;
        const std::optional<QImage> frame = readVideoFrame(clip, 0, &error);
        QVERIFY2(frame, qPrintable(error));
        const Looked look = classicLook(*frame);
        QVERIFY2(look.result.status == DetectStatus::Ok, qPrintable(look.result.error));
        const FaceModel &face = look.result.face;
        qInfo("bbaf2n: classic 11.1 (%.0f, %.0f), h.10 (%.0f, %.0f), bald %d, hat %d", face.point("11.1").x(),
            face.point("11.1").y(), face.point("h.10").x(), face.point("h.10").y(), look.style.appearance.bald,
            look.style.appearance.hat);
        QVERIFY(!look.style.appearance.bald);
        QVERIFY(!look.style.appearance.hat);
        const DetectionResult ref = detectFace(*frame, {});
        if (ref.status == DetectStatus::ModelMissing)
            QSKIP("the landmark model is not installed: no reference hairline");
        QCOMPARE(ref.status, DetectStatus::Ok);
        const double d = es0(ref.face);
        qInfo("bbaf2n: landmarks 11.1 (%.0f, %.0f), h.10 (%.0f, %.0f), ES0 %.1f", ref.face.point("11.1").x(),
            ref.face.point("11.1").y(), ref.face.point("h.10").x(), ref.face.point("h.10").y(), d);
        QVERIFY(QLineF(face.point("11.1"), ref.face.point("11.1")).length() < 0.25 * d);
        QVERIFY(QLineF(face.point("h.10"), ref.face.point("h.10")).length() < 0.33 * d);
    }
};

TOONFACE_TEST_MAIN(TestClassicHair)
#include "tst_classichair.moc"
