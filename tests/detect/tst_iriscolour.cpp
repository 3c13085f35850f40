#include "detect/labcolour.h"
#include "detect/photocolours.h"
#include "drawnface.h"
#include "render/style.h"
#include "testmain.h"

#include <QPainter>
#include <QTest>

using namespace toonface;

// The iris's colour as sampleColours() draws it (detect/photocolours.cpp, irisColour and
// drawnIris): drawn eyes of a known colour, looking aside (the eyeball point is the eye's middle,
// not the iris's), in white and in warm or pink light.

namespace {

// A drawn face whose eyes are painted again: whites, an iris of `iris` shifted `gaze` (ES0) along
// the eye line with a dark rim, a pupil and a glint; then the whole photo lit by `light` (each
// channel scaled by it / 255), as a lamp or a room's colour does.
QImage eyesOf(QColor iris, double gaze, QColor light)
{
    const FaceModel face = testing::drawnFaceModel();
    QImage img = testing::drawnFace({});
    auto P = [&](const char *id) { return face.point(id); };
    const double es0 = QLineF(P("3.6"), P("3.5")).length();
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    for (bool left : {true, false}) {
        const QPointF a = P(left ? "3.12" : "3.11"), b = P(left ? "3.8" : "3.7");
        const double h = 1.6 * (P(left ? "3.4" : "3.3").y() - P(left ? "3.2" : "3.1").y());
        QPainterPath opening;
        opening.addEllipse((a + b) / 2.0, QLineF(a, b).length() / 2.0, h / 2.0);
        p.save();
        p.setClipPath(opening);
        p.fillPath(opening, QColor(236, 232, 226));
        const QPointF centre = P(left ? "3.6" : "3.5") + QPointF(gaze * es0, 0);
        const double r = 0.095 * es0;
        p.setBrush(iris.darker(170));
        p.drawEllipse(centre, r, r);
        p.setBrush(iris);
        p.drawEllipse(centre, 0.85 * r, 0.85 * r);
        p.setBrush(QColor(15, 12, 10));
        p.drawEllipse(centre, 0.35 * r, 0.35 * r);
        p.setBrush(QColor(255, 255, 255));
        p.drawEllipse(centre + QPointF(0.3 * r, -0.3 * r), 0.12 * r, 0.12 * r);
        p.restore();
        // The upper lid's lashes: a dark line along the opening's top.
        p.save();
        p.setClipRect(QRectF(a.x() - 5, 0, b.x() - a.x() + 10, (a.y() + b.y()) / 2.0 - 0.3 * h));
        p.setPen(QPen(QColor(40, 30, 25), 0.02 * es0));
        p.setBrush(Qt::NoBrush);
        p.drawPath(opening);
        p.restore();
    }
    p.end();
    for (int y = 0; y < img.height(); ++y) {
        auto *line = reinterpret_cast<QRgb *>(img.scanLine(y));
        for (int x = 0; x < img.width(); ++x)
            line[x] = qRgb(qRed(line[x]) * light.red() / 255, qGreen(line[x]) * light.green() / 255,
                qBlue(line[x]) * light.blue() / 255);
    }
    return img;
}

QColor drawnIris(const QImage &photo)
{
    Style style = Style::preset(QStringLiteral("normal"));
    sampleColours(photo, testing::drawnFaceModel(), &style);
    return style.components.value(QStringLiteral("eyeballs")).fill;
}

// A Lab hue angle in degrees, 0..360.
double hueOf(const QColor &c)
{
    const LabColour lab = labOf(c);
    return std::fmod(std::atan2(lab.b, lab.a) * 180.0 / M_PI + 360.0, 360.0);
}

} // namespace

class TestIrisColour : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void irisHueKept_data()
    {
        QTest::addColumn<QColor>("iris");
        QTest::addColumn<double>("gaze");
        QTest::addColumn<QColor>("light");
        QTest::addColumn<bool>("cool"); // blue, green or grey-blue: not brown
        const QColor white(255, 255, 255), warm(255, 225, 185), pink(255, 210, 210);
        const QColor blue(95, 135, 185), lightBlue(150, 180, 215), greyBlue(120, 135, 150), brown(110, 70, 40);
        for (const auto &[name, light] :
            {std::pair {"white light", white}, {"warm light", warm}, {"pink light", pink}}) {
            for (double gaze : {0.0, 0.12, -0.12}) {
                const QByteArray where = gaze == 0 ? "ahead" : gaze > 0 ? "aside" : "other side";
                QTest::addRow("blue, %s, %s", where.constData(), name) << blue << gaze << light << true;
                QTest::addRow("light blue, %s, %s", where.constData(), name) << lightBlue << gaze << light << true;
                QTest::addRow("grey-blue, %s, %s", where.constData(), name) << greyBlue << gaze << light << true;
                QTest::addRow("brown, %s, %s", where.constData(), name) << brown << gaze << light << false;
            }
        }
    }

    // A blue or grey iris is drawn cool and a brown one brown, wherever it looks and whatever the
    // light: a disc at the eye's middle read pupil and lashes, and a light blue iris was refused
    // as too light and drawn in the preset's brown.
    void irisHueKept()
    {
        QFETCH(QColor, iris);
        QFETCH(double, gaze);
        QFETCH(QColor, light);
        QFETCH(bool, cool);
        const QColor drawn = drawnIris(eyesOf(iris, gaze, light));
        QVERIFY(drawn.isValid());
        const LabColour lab = labOf(drawn);
        const double chroma = std::hypot(lab.a, lab.b);
        const bool brownish = chroma > 8 && hueOf(drawn) >= 20 && hueOf(drawn) <= 100;
        QVERIFY2(brownish != cool,
            qPrintable(QStringLiteral("drawn %1 (L* %2, chroma %3, hue %4)")
                           .arg(drawn.name())
                           .arg(lab.l, 0, 'f', 1)
                           .arg(chroma, 0, 'f', 1)
                           .arg(hueOf(drawn), 0, 'f', 0)));
        // Read from the iris, not the pupil: nearly as light as the painted iris.
        QVERIFY2(lab.l > labOf(iris).l - 20, qPrintable(drawn.name()));
        // A light iris is drawn light and clearly coloured, not the dull grey a photo shows.
        if (cool)
            QVERIFY2(lab.l >= 49.5 && chroma > 6, qPrintable(drawn.name()));
    }
};

TOONFACE_TEST_MAIN(TestIrisColour)
#include "tst_iriscolour.moc"
