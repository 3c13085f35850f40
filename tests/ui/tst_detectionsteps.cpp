#include "testmain.h"
#include "window/detectionsteps.h"
#include "window/detectiontask.h"

#include <QSignalSpy>
#include <QTest>

using namespace toonface;

namespace {

QImage filled(QSize size)
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    return image;
}

} // namespace

class TestDetectionSteps : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void namesFollowThePipelineThenTheAlphabet()
    {
        DetectionSteps steps;
        QMap<QString, QImage> images;
        for (const char *name : {"detect-landmarks", "zeta-extra", "classic-edges", "classic-b1", "alpha-extra",
                 "classic-eye-pairs", "detect-points-crop"})
            images.insert(QLatin1StringView(name), filled(QSize(8, 8)));
        steps.setImages(images);
        QCOMPARE(steps.names(),
            QStringList({QStringLiteral("classic-b1"), QStringLiteral("classic-eye-pairs"),
                QStringLiteral("classic-edges"), QStringLiteral("detect-landmarks"),
                QStringLiteral("detect-points-crop"), QStringLiteral("alpha-extra"), QStringLiteral("zeta-extra")}));
    }

    void nullImagesAreLeftOut()
    {
        DetectionSteps steps;
        steps.setImages({{QStringLiteral("classic-b1"), QImage()}, {QStringLiteral("classic-b2"), filled({4, 4})}});
        QCOMPARE(steps.names(), QStringList({QStringLiteral("classic-b2")}));
        QVERIFY(steps.image(QStringLiteral("classic-b1")).isNull());
        QCOMPARE(steps.image(QStringLiteral("classic-b2")).size(), QSize(4, 4));
    }

    void changesAreSignalledOnce()
    {
        DetectionSteps steps;
        QSignalSpy changed(&steps, &DetectionSteps::changed);
        steps.clear(); // nothing to clear
        QCOMPARE(changed.size(), 0);
        steps.setImages({{QStringLiteral("classic-b1"), filled({4, 4})}});
        QCOMPARE(changed.size(), 1);
        QVERIFY(!steps.isEmpty());
        steps.clear();
        QCOMPARE(changed.size(), 2);
        QVERIFY(steps.isEmpty());
        QVERIFY(steps.names().isEmpty());
    }

    void closeUpsAreNamedByTheirSuffix_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("closeUp");
        QTest::newRow("points crop") << QStringLiteral("detect-points-crop") << true;
        QTest::newRow("any crop") << QStringLiteral("classic-mouth-crop") << true;
        QTest::newRow("landmarks") << QStringLiteral("detect-landmarks") << false;
        QTest::newRow("crop inside") << QStringLiteral("classic-crop-lines") << false;
    }

    void closeUpsAreNamedByTheirSuffix()
    {
        QFETCH(QString, name);
        QFETCH(bool, closeUp);
        QCOMPARE(DetectionSteps::isCloseUp(name), closeUp);
    }

    void largeStepImagesAreReduced()
    {
        QImage big(3000, 2000, QImage::Format_Grayscale8); // 6 MP, as a mask of a large photo
        big.fill(200);
        QImage withAlpha(400, 300, QImage::Format_ARGB32);
        withAlpha.fill(QColor(255, 0, 0, 128));
        QMap<QString, QImage> images {{QStringLiteral("classic-b1"), big},
            {QStringLiteral("detect-landmarks"), filled(QSize(640, 480))},
            {QStringLiteral("detect-points-crop"), withAlpha}};
        DetectionTask::reduceStepImages(&images);

        const QImage reduced = images.value(QStringLiteral("classic-b1"));
        QVERIFY(qint64(reduced.width()) * reduced.height() <= DetectionTask::kMaxStepImagePixels);
        QVERIFY(qint64(reduced.width()) * reduced.height() > DetectionTask::kMaxStepImagePixels * 0.99);
        QVERIFY(std::abs(reduced.width() * 2000.0 / 3000.0 - reduced.height()) <= 1.0); // aspect kept
        QCOMPARE(reduced.format(), QImage::Format_RGB32);
        QCOMPARE(qGray(reduced.pixel(10, 10)), 200);

        QCOMPARE(images.value(QStringLiteral("detect-landmarks")).size(), QSize(640, 480)); // small: as it was
        QCOMPARE(images.value(QStringLiteral("detect-landmarks")).format(), QImage::Format_RGB32);
        const QImage alpha = images.value(QStringLiteral("detect-points-crop"));
        QCOMPARE(alpha.size(), QSize(400, 300));
        QCOMPARE(alpha.format(), QImage::Format_ARGB32_Premultiplied);
        QVERIFY(std::abs(qAlpha(alpha.pixel(5, 5)) - 128) <= 1);
    }

    void displayNamesAreForPeople_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("shown");
        QTest::newRow("b1") << QStringLiteral("classic-b1")
                            << QStringLiteral("B1 – dark regions (1st level, intensity)");
        QTest::newRow("eye pairs") << QStringLiteral("classic-eye-pairs")
                                   << QStringLiteral("Eye-pair candidates and the chosen pair");
        QTest::newRow("edges") << QStringLiteral("classic-edges") << QStringLiteral("Edges and division lines");
        QTest::newRow("landmarks") << QStringLiteral("detect-landmarks") << QStringLiteral("Landmarks");
        QTest::newRow("points crop") << QStringLiteral("detect-points-crop") << QStringLiteral("Points, close-up");
        // Names the detectors may add later still read as words.
        QTest::newRow("unknown classic") << QStringLiteral("classic-mouth-cut")
                                         << QStringLiteral("Mouth cut (thesis pipeline)");
        QTest::newRow("unknown detect crop") << QStringLiteral("detect-ears-crop") << QStringLiteral("Ears, close-up");
        QTest::newRow("other prefix") << QStringLiteral("track-optical_flow") << QStringLiteral("Optical flow (track)");
        QTest::newRow("no prefix") << QStringLiteral("heatmap") << QStringLiteral("Heatmap");
        QTest::newRow("only a suffix") << QStringLiteral("-crop") << QStringLiteral("-crop");
    }

    void displayNamesAreForPeople()
    {
        QFETCH(QString, name);
        QFETCH(QString, shown);
        QCOMPARE(DetectionSteps::displayName(name), shown);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestDetectionSteps)
#include "tst_detectionsteps.moc"
