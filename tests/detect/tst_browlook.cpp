#include "detect/browlook.h"
#include "detect/labcolour.h"
#include "render/style.h"
#include "testmain.h"

#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

double chroma(const QColor &c)
{
    const LabColour lab = labOf(c);
    return std::hypot(lab.a, lab.b);
}

ComponentStyle brows(const QColor &colour, double width)
{
    ComponentStyle s;
    s.stroke = colour;
    s.strokeWidth = width;
    return s;
}

} // namespace

// How the brows measured in the photo are drawn (detect/browlook.h).
class TestBrowLook : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Faint brows on a light skin are drawn lighter than the near-black brown the style had, but
    // as colourful as it, not more: a brown brow stays brown (raised in RGB it turned orange).
    void lighterBrowsKeepTheirColourfulness_data()
    {
        QTest::addColumn<QColor>("base");
        QTest::newRow("near-black brown") << QColor(0x34, 0x16, 0x08);
        QTest::newRow("dark auburn") << QColor(0x4a, 0x1e, 0x10);
        QTest::newRow("black") << QColor(0x12, 0x10, 0x10);
    }
    void lighterBrowsKeepTheirColourfulness()
    {
        QFETCH(QColor, base);
        const QColor skin(0xfc, 0xaa, 0x7e);
        ComponentStyle s = brows(base, 6.0);
        applyBrowLook(BrowLook {kMedianBrowThickness, 10.0, true}, skin, &s);
        const double wantL = labOf(skin).l - kMinBrowContrast;
        QVERIFY2(std::abs(labOf(s.stroke).l - wantL) < 1.5,
            qPrintable(QStringLiteral("%1: L* %2, want %3").arg(s.stroke.name()).arg(labOf(s.stroke).l).arg(wantL)));
        QVERIFY2(chroma(s.stroke) <= chroma(base) + 2.0,
            qPrintable(QStringLiteral("%1 (chroma %2) from %3 (chroma %4)")
                           .arg(s.stroke.name())
                           .arg(chroma(s.stroke), 0, 'f', 1)
                           .arg(base.name())
                           .arg(chroma(base), 0, 'f', 1)));
    }

    // A brow twice as thick as the set's median is drawn wider than one of the median, within the
    // drawn range; brows not seen leave the style as it was.
    void widthFollowsThickness()
    {
        const QColor skin(0xe0, 0xb0, 0x90), base(0x30, 0x20, 0x18);
        ComponentStyle median = brows(base, 6.0), thick = brows(base, 6.0), unseen = brows(base, 6.0);
        applyBrowLook(BrowLook {kMedianBrowThickness, 30.0, true}, skin, &median);
        applyBrowLook(BrowLook {2.0 * kMedianBrowThickness, 30.0, true}, skin, &thick);
        applyBrowLook(BrowLook {2.0 * kMedianBrowThickness, 30.0, false}, skin, &unseen);
        QVERIFY(thick.strokeWidth > median.strokeWidth);
        QVERIFY(thick.strokeWidth <= kBrowWidths[1]);
        QCOMPARE(unseen.strokeWidth, 6.0);
        QCOMPARE(unseen.stroke, base);
    }
};

TOONFACE_TEST_MAIN(TestBrowLook)
#include "tst_browlook.moc"
