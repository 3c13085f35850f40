// Every emotion preset reads as itself on every shared face (research data, read only here): the
// geometric signature of emotionsignature.h holds on the faces the landmark method finds in the
// shared photos and in the labelled set, whatever expression each photo has of its own (about
// half of the labelled faces smile; some frown or raise their brows).

#include "detect/detector.h"
#include "emotionsignature.h"
#include "shareddata.h"
#include "testmain.h"

#include <QDir>
#include <QFileInfo>
#include <QTest>

using namespace toonface;

class TestEmotionFaces : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void sharedFaces()
    {
        QStringList photos;
        const QDir faces(testing::sharedFacesDir());
        for (const QFileInfo &f : faces.entryInfoList({QStringLiteral("*.jpg"), QStringLiteral("*.png")}, QDir::Files))
            photos << f.filePath();
        const QDir labelled(QDir(testing::sharedDataDir()).filePath(QStringLiteral("faces-attributes/images")));
        for (const QFileInfo &f : labelled.entryInfoList({QStringLiteral("*.jpg")}, QDir::Files))
            photos << f.filePath();
        if (photos.isEmpty())
            QSKIP("no research photos (set TOONFACE_DATA_DIR to the shared data folder)");
        int checked = 0;
        QStringList failures;
        for (const QString &path : photos) {
            const DetectionResult r = detectFace(QImage(path));
            if (r.status == DetectStatus::ModelMissing)
                QSKIP("the landmark model (libdlib-data) is not installed");
            if (r.status != DetectStatus::Ok)
                continue;
            ++checked;
            const QStringList failed = testing::emotionSignatureFailures(r.face);
            if (!failed.isEmpty())
                failures << QFileInfo(path).fileName() + QStringLiteral(": ") + failed.join(QStringLiteral("; "));
        }
        QVERIFY2(
            checked >= photos.size() * 9 / 10, qPrintable(QStringLiteral("%1 of %2").arg(checked).arg(photos.size())));
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestEmotionFaces)
#include "tst_emotionfaces.moc"
