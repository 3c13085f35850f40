#include "face/averageface.h"
#include "face/caricature.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/pointtable.h"
#include "testmain.h"

#include <QLineF>
#include <QTest>

using namespace toonface;

// The caricature's eyes (face/caricature.h): measured against people's eyes, not the template's
// cartoon eyes, so an eye of people's median size is drawn its own size and a large round eye
// larger and rounder, a narrow one narrower.

namespace {

// The average face with each eye scaled about its centre to `width` (ES0) wide and open `opening`
// of that.
FaceModel withEyes(double width, double opening)
{
    FaceModel face = averageFace(QRectF(50, 40, 300, 300), QSize(400, 400));
    const double es0 = QLineF(face.point("3.6"), face.point("3.5")).length();
    for (const auto &eye :
        {std::array {"3.6", "3.12", "3.8", "3.2", "3.4"}, std::array {"3.5", "3.11", "3.7", "3.1", "3.3"}}) {
        const QPointF c = face.point(eye[0]);
        const double w = std::abs(face.point(eye[2]).x() - face.point(eye[1]).x());
        const double h = std::abs(face.point(eye[4]).y() - face.point(eye[3]).y());
        for (const char *id : eye) {
            const QPointF d = face.point(id) - c;
            face.setPoint(pt::idx(id), c + QPointF(d.x() * width * es0 / w, d.y() * opening * width * es0 / h));
        }
    }
    return face;
}

struct EyeSize
{
    double width = 0, opening = 0; // ES0, and the lids' distance over the width
};

// The left eye as the caricature draws it.
EyeSize drawnEye(const FaceModel &face, double factor)
{
    const auto off = caricatureOffsets(face, factor);
    auto at = [&](const char *id) { return face.point(id) + off[pt::idx(id)]; };
    const double es0 = QLineF(at("3.6"), at("3.5")).length();
    EyeSize e;
    const double w = QLineF(at("3.12"), at("3.8")).length();
    e.width = w / es0;
    e.opening = QLineF(at("3.2"), at("3.4")).length() / w;
    return e;
}

} // namespace

class TestCaricature : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // People's median eye is drawn as it is: the template's larger cartoon eye made every eye
    // smaller and narrower (a 0.395-wide eye drawn 0.358 wide at the default factor).
    void peoplesEyeKeepsItsSize()
    {
        const EyeSize e = drawnEye(withEyes(kPeoplesEyeWidth, kPeoplesEyeOpening), 0.35);
        QVERIFY2(std::abs(e.width - kPeoplesEyeWidth) < 0.01, qPrintable(QString::number(e.width)));
        QVERIFY2(std::abs(e.opening - kPeoplesEyeOpening) < 0.02, qPrintable(QString::number(e.opening)));
    }

    void eyesFollowThePerson_data()
    {
        QTest::addColumn<double>("width");
        QTest::addColumn<double>("opening");
        QTest::newRow("large round") << 0.46 << 0.42;
        QTest::newRow("small narrow") << 0.34 << 0.2;
        QTest::newRow("wide narrow") << 0.45 << 0.22;
        QTest::newRow("small round") << 0.35 << 0.4;
    }

    // An eye larger or rounder than people's is drawn larger or rounder still, a smaller or
    // narrower one smaller or narrower: the difference grows with the factor.
    void eyesFollowThePerson()
    {
        QFETCH(double, width);
        QFETCH(double, opening);
        const FaceModel face = withEyes(width, opening);
        const EyeSize none = drawnEye(face, 0.0), mild = drawnEye(face, 0.35), strong = drawnEye(face, 0.7);
        QVERIFY(std::abs(none.width - width) < 1e-6);
        auto further = [](double from, double a, double b) { return std::abs(b - from) > std::abs(a - from); };
        QVERIFY2(
            further(kPeoplesEyeWidth, none.width, mild.width) && further(kPeoplesEyeWidth, mild.width, strong.width),
            qPrintable(QStringLiteral("%1 %2 %3").arg(none.width).arg(mild.width).arg(strong.width)));
        QVERIFY2(further(kPeoplesEyeOpening, none.opening, mild.opening)
                && further(kPeoplesEyeOpening, mild.opening, strong.opening),
            qPrintable(QStringLiteral("%1 %2 %3").arg(none.opening).arg(mild.opening).arg(strong.opening)));
        QCOMPARE(mild.width > kPeoplesEyeWidth, width > kPeoplesEyeWidth);
        QCOMPARE(mild.opening > kPeoplesEyeOpening, opening > kPeoplesEyeOpening);
    }
};

TOONFACE_TEST_MAIN(TestCaricature)
#include "tst_caricature.moc"
