#include "render/curves.h"
#include "testmain.h"

#include <QLineF>
#include <QTest>

#include <cmath>
#include <limits>

using namespace toonface;

Q_DECLARE_METATYPE(toonface::CubicBezier)

namespace {

double dist(QPointF a, QPointF b)
{
    return QLineF(a, b).length();
}

double cross(QPointF a, QPointF b)
{
    return a.x() * b.y() - a.y() * b.x();
}

double dot(QPointF a, QPointF b)
{
    return a.x() * b.x() + a.y() * b.y();
}

// Corner cutting with eqs. 4.1-4.3 is de Casteljau subdivision of the quadratic Bezier with
// control points p0, p1, p2: after `depth` levels the polygon is the control polygons of the
// 2^depth pieces [j/N, (j+1)/N]. Their points come from the quadratic's blossom
// b(s, t) = (1-s)(1-t) p0 + ((1-s) t + s (1-t)) p1 + s t p2: ends b(t, t), middles b(t_j, t_j+1).
// This computes them without recursion, as an independent check.
QPointF blossom(QPointF p0, QPointF p1, QPointF p2, double s, double t)
{
    return p0 * ((1 - s) * (1 - t)) + p1 * ((1 - s) * t + s * (1 - t)) + p2 * (s * t);
}

QVector<QPointF> expectedCornerCut(QPointF p0, QPointF p1, QPointF p2, int depth)
{
    if (depth <= 0)
        return {p0, p1, p2};
    const int n = 1 << depth;
    QVector<QPointF> out;
    for (int j = 0; j < n; ++j) {
        const double a = double(j) / n;
        const double b = double(j + 1) / n;
        out.append(blossom(p0, p1, p2, a, a));
        out.append(blossom(p0, p1, p2, a, b));
    }
    out.append(p2);
    return out;
}

// Curvature of a cubic at t (|B' x B''| / |B'|^3), from the polynomial's derivatives.
double curvatureAt(const CubicBezier &b, double t)
{
    const double s = 1 - t;
    const QPointF d1 = (b.q1 - b.q0) * (3 * s * s) + (b.q2 - b.q1) * (6 * s * t) + (b.q3 - b.q2) * (3 * t * t);
    const QPointF d2 = (b.q2 - b.q1 * 2 + b.q0) * (6 * s) + (b.q3 - b.q2 * 2 + b.q1) * (6 * t);
    const double speed = std::hypot(d1.x(), d1.y());
    return std::abs(cross(d1, d2)) / (speed * speed * speed);
}

} // namespace

class TestCurves : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cornerCut_data()
    {
        QTest::addColumn<QPointF>("p0");
        QTest::addColumn<QPointF>("p1");
        QTest::addColumn<QPointF>("p2");
        QTest::addColumn<int>("depth");
        const struct
        {
            const char *name;
            QPointF p0, p1, p2;
        } corners[] = {
            {"right angle", {0, 0}, {4, 0}, {4, 4}},
            {"brow arch", {10, 50}, {40, 20}, {90, 45}},
            {"sharp", {0, 0}, {100, 1}, {0, 2}},
            {"collinear", {0, 0}, {1, 1}, {2, 2}},
            {"coincident", {3, 3}, {3, 3}, {3, 3}},
            {"negative", {-20, -5}, {-7.5, 12.25}, {6, -30}},
        };
        for (const auto &c : corners) {
            for (int depth = 0; depth <= 3; ++depth)
                QTest::addRow("%s, depth %d", c.name, depth) << c.p0 << c.p1 << c.p2 << depth;
        }
    }

    void cornerCut()
    {
        QFETCH(QPointF, p0);
        QFETCH(QPointF, p1);
        QFETCH(QPointF, p2);
        QFETCH(int, depth);
        const QVector<QPointF> got = toonface::cornerCut(p0, p1, p2, depth);
        const QVector<QPointF> want = expectedCornerCut(p0, p1, p2, depth);
        QCOMPARE(got.size(), (1 << (depth + 1)) + 1);
        QCOMPARE(got.size(), want.size());
        QCOMPARE(got.first(), p0); // endpoints kept exactly
        QCOMPARE(got.last(), p2);
        for (qsizetype i = 0; i < got.size(); ++i)
            QVERIFY2(dist(got[i], want[i]) < 1e-9, qPrintable(QStringLiteral("point %1").arg(i)));
    }

    void cornerCutByHand()
    {
        // One level on the corner (0,0)-(4,0)-(4,4): the midpoints (2,0), (4,2) and their
        // midpoint (3,1), then one more level cuts each new corner.
        QCOMPARE(toonface::cornerCut({0, 0}, {4, 0}, {4, 4}, 1),
            (QVector<QPointF> {{0, 0}, {2, 0}, {3, 1}, {4, 2}, {4, 4}}));
        QCOMPARE(toonface::cornerCut({0, 0}, {4, 0}, {4, 4}, 2),
            (QVector<QPointF> {
                {0, 0}, {1, 0}, {1.75, 0.25}, {2.5, 0.5}, {3, 1}, {3.5, 1.5}, {3.75, 2.25}, {4, 3}, {4, 4}}));
        QCOMPARE(toonface::cornerCut({0, 0}, {4, 0}, {4, 4}, -1), (QVector<QPointF> {{0, 0}, {4, 0}, {4, 4}}));
    }

    void cornerCutPolyline_data()
    {
        QTest::addColumn<QVector<QPointF>>("points");
        QTest::addColumn<bool>("closed");
        QTest::addColumn<int>("depth");
        const QVector<QPointF> brow {{10, 60}, {30, 42}, {55, 40}, {80, 52}};
        const QVector<QPointF> zigzag {{0, 0}, {10, 10}, {20, 0}, {30, 10}, {40, 0}};
        const QVector<QPointF> square {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
        for (int depth = 0; depth <= 3; ++depth) {
            QTest::addRow("brow open %d", depth) << brow << false << depth;
            QTest::addRow("zigzag open %d", depth) << zigzag << false << depth;
            QTest::addRow("square closed %d", depth) << square << true << depth;
            QTest::addRow("zigzag closed %d", depth) << zigzag << true << depth;
        }
    }

    void cornerCutPolyline()
    {
        QFETCH(QVector<QPointF>, points);
        QFETCH(bool, closed);
        QFETCH(int, depth);
        const QVector<QPointF> got = toonface::cornerCutPolyline(points, depth, closed);
        if (depth == 0) {
            QCOMPARE(got, points);
            return;
        }
        const qsizetype n = points.size();
        auto mid = [&](qsizetype a, qsizetype b) { return (points[(a + n) % n] + points[(b + n) % n]) / 2.0; };
        // Every corner is the blossom polygon between the midpoints of its two segments;
        // neighbours share their midpoint, listed once.
        QVector<QPointF> want;
        if (!closed)
            want.append(points.first());
        const qsizetype first = closed ? 0 : 1;
        for (qsizetype i = first; i < (closed ? n : n - 1); ++i) {
            const QVector<QPointF> corner = expectedCornerCut(mid(i - 1, i), points[i], mid(i, i + 1), depth);
            want.append(i == first ? corner : corner.mid(1));
        }
        if (closed)
            want.removeLast();
        else
            want.append(points.last());
        const qsizetype perCorner = 1 << (depth + 1);
        QCOMPARE(got.size(), closed ? n * perCorner : (n - 2) * perCorner + 3);
        QCOMPARE(got.size(), want.size());
        for (qsizetype i = 0; i < got.size(); ++i)
            QVERIFY2(dist(got[i], want[i]) < 1e-9, qPrintable(QStringLiteral("point %1").arg(i)));
        if (!closed) {
            QCOMPARE(got.first(), points.first());
            QCOMPARE(got.last(), points.last());
        }
    }

    void cornerCutPolylineByHand()
    {
        QCOMPARE(toonface::cornerCutPolyline({{0, 0}, {4, 0}, {4, 4}}, 1, false),
            (QVector<QPointF> {{0, 0}, {2, 0}, {3, 0}, {3.5, 0.5}, {4, 1}, {4, 2}, {4, 4}}));
        QCOMPARE(toonface::cornerCutPolyline({{0, 0}, {4, 0}}, 3, false), (QVector<QPointF> {{0, 0}, {4, 0}}));
        QVERIFY(toonface::cornerCutPolyline({}, 2, true).isEmpty());
    }

    void r3IsTheMidpoint_data()
    {
        QTest::addColumn<CubicBezier>("b");
        QTest::newRow("arch") << CubicBezier {{0, 0}, {10, -20}, {40, -20}, {50, 0}};
        QTest::newRow("s-curve") << CubicBezier {{0, 0}, {30, -40}, {-10, 60}, {25, 5}};
        QTest::newRow("loop") << CubicBezier {{0, 0}, {100, 100}, {-100, 100}, {0, 0}};
        QTest::newRow("point") << CubicBezier {{7, 7}, {7, 7}, {7, 7}, {7, 7}};
    }

    void r3IsTheMidpoint()
    {
        // Eqs. 4.5-4.9 construct the point of eq. 4.4 at t = 1/2.
        QFETCH(CubicBezier, b);
        QVERIFY(dist(b.r3(), b.at(0.5)) < 1e-9);
        QCOMPARE(b.at(0), b.q0);
        QVERIFY(dist(b.at(1), b.q3) < 1e-9);
    }

    void fitBezierThrough_data()
    {
        QTest::addColumn<QPointF>("q0");
        QTest::addColumn<QPointF>("target");
        QTest::addColumn<QPointF>("q3");
        QTest::addColumn<double>("spread");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("jaw, lowest point") << QPointF(0, 0) << QPointF(50, 40) << QPointF(100, 0) << 1.0 << 0.5;
        QTest::newRow("thesis fig 4.6 size")
            << QPointF(120, 300) << QPointF(180, 359.75) << QPointF(240, 300) << 1.0 << 0.5;
        QTest::newRow("target on chord") << QPointF(0, 0) << QPointF(50, 0) << QPointF(100, 0) << 1.0 << 0.5;
        QTest::newRow("target off centre") << QPointF(0, 0) << QPointF(10, 30) << QPointF(100, 0) << 1.0 << 0.5;
        QTest::newRow("target at an end") << QPointF(0, 0) << QPointF(0, 0) << QPointF(100, 0) << 1.0 << 0.5;
        QTest::newRow("zero chord") << QPointF(20, 20) << QPointF(20, 60) << QPointF(20, 20) << 1.0 << 0.5;
        QTest::newRow("all coincident") << QPointF(5, 5) << QPointF(5, 5) << QPointF(5, 5) << 1.0 << 0.5;
        QTest::newRow("far target") << QPointF(0, 0) << QPointF(-3000, 9000) << QPointF(10, 0) << 1.0 << 0.5;
        QTest::newRow("large coordinates")
            << QPointF(1e5, 1e5) << QPointF(1.0005e5, 1.0003e5) << QPointF(1.001e5, 1e5) << 1.0 << 0.5;
        QTest::newRow("tight tolerance") << QPointF(0, 0) << QPointF(33.3, -21.7) << QPointF(91, 12) << 1.0 << 1e-6;
        QTest::newRow("sharp, spread 0") << QPointF(0, 0) << QPointF(50, 40) << QPointF(100, 0) << 0.0 << 0.5;
        QTest::newRow("flat, spread 3") << QPointF(0, 0) << QPointF(50, 40) << QPointF(100, 0) << 3.0 << 0.5;
        QTest::newRow("negative spread clamps") << QPointF(0, 0) << QPointF(50, 40) << QPointF(100, 0) << -2.0 << 0.5;
    }

    void fitBezierThrough()
    {
        QFETCH(QPointF, q0);
        QFETCH(QPointF, target);
        QFETCH(QPointF, q3);
        QFETCH(double, spread);
        QFETCH(double, tolerance);
        int iterations = -1;
        const CubicBezier b = toonface::fitBezierThrough(q0, target, q3, spread, tolerance, &iterations);
        QCOMPARE(b.q0, q0);
        QCOMPARE(b.q3, q3);
        QVERIFY2(dist(b.r3(), target) < tolerance, qPrintable(QStringLiteral("error %1").arg(dist(b.r3(), target))));
        QVERIFY(dist(b.at(0.5), target) < tolerance);
        // Method A: Q1 and Q2 moved together, so their offset stays what method B set.
        const double s = std::max(0.0, spread);
        QVERIFY(dist(b.q2 - b.q1, (q3 - q0) * (s / 3.0)) < 1e-6 * (1 + dist(q0, q3)));
        QVERIFY(iterations >= 0 && iterations <= 3);
    }

    void fitBezierThroughNonFiniteTerminates()
    {
        int iterations = 0;
        const CubicBezier b = toonface::fitBezierThrough({0, 0}, {qQNaN(), 0}, {10, 0}, 1.0, 0.5, &iterations);
        QCOMPARE(b.q0, QPointF(0, 0));
        QVERIFY(iterations < 100);
    }

    void spreadChangesSharpness()
    {
        // Method B: control points nearer each other give a sharper curve at the target, further
        // apart a flatter one; the curve still passes through the target.
        const QPointF q0(0, 0), target(50, 40), q3(100, 0);
        double previous = std::numeric_limits<double>::infinity();
        double previousGap = -1;
        for (double spread : {0.0, 0.5, 1.0, 1.5, 2.5}) {
            const CubicBezier b = toonface::fitBezierThrough(q0, target, q3, spread);
            QVERIFY(dist(b.r3(), target) < 0.5);
            const double k = curvatureAt(b, 0.5);
            const double gap = dist(b.q1, b.q2);
            QVERIFY2(k < previous, qPrintable(QStringLiteral("spread %1: curvature %2").arg(spread).arg(k)));
            QVERIFY(gap > previousGap);
            previous = k;
            previousGap = gap;
        }
    }

    void chain_data()
    {
        QTest::addColumn<QVector<QPointF>>("anchors");
        QTest::addColumn<QVector<QPointF>>("targets");
        QTest::addColumn<QPointF>("startTangent");
        QTest::addColumn<QPointF>("endTangent");
        QTest::addColumn<bool>("closed");
        // The face contour of the average face: 2.14 -> 11.2 -> 11.3 -> 2.13 through 5.2, 11.1, 5.1.
        QTest::newRow("face contour") << QVector<QPointF> {{21, 266}, {24, 36}, {276, 36}, {279, 266}}
                                      << QVector<QPointF> {{9, 137}, {150, -18}, {291, 137}} << QPointF(-0.28, -0.96)
                                      << QPointF(0.28, 0.96) << false;
        QTest::newRow("jaw free ends") << QVector<QPointF> {{21, 266}, {150, 367}, {279, 266}}
                                       << QVector<QPointF> {{66, 335}, {234, 335}} << QPointF() << QPointF() << false;
        QTest::newRow("one segment") << QVector<QPointF> {{0, 0}, {100, 0}} << QVector<QPointF> {{50, 30}}
                                     << QPointF(0, 1) << QPointF(0, -1) << false;
        QTest::newRow("straight run") << QVector<QPointF> {{0, 0}, {10, 0}, {20, 0}, {30, 0}}
                                      << QVector<QPointF> {{5, 0}, {15, 0}, {25, 0}} << QPointF() << QPointF() << false;
        QTest::newRow("closed ellipse") << QVector<QPointF> {{100, 0}, {0, 50}, {-100, 0}, {0, -50}, {100, 0}}
                                        << QVector<QPointF> {{70.7, 35.4}, {-70.7, 35.4}, {-70.7, -35.4}, {70.7, -35.4}}
                                        << QPointF() << QPointF() << true;
        QTest::newRow("zigzag") << QVector<QPointF> {{0, 0}, {20, 0}, {40, 0}} << QVector<QPointF> {{10, 15}, {30, -15}}
                                << QPointF() << QPointF() << false;
    }

    void chain()
    {
        QFETCH(QVector<QPointF>, anchors);
        QFETCH(QVector<QPointF>, targets);
        QFETCH(QPointF, startTangent);
        QFETCH(QPointF, endTangent);
        QFETCH(bool, closed);
        BezierChainEnds ends {startTangent, endTangent, closed};
        const QVector<CubicBezier> chain = fitBezierChain(anchors, targets, ends);
        QCOMPARE(chain.size(), targets.size());
        for (qsizetype i = 0; i < chain.size(); ++i) {
            QCOMPARE(chain[i].q0, anchors[i]);
            QCOMPARE(chain[i].q3, anchors[i + 1]);
            QVERIFY2(dist(chain[i].r3(), targets[i]) < 0.5, qPrintable(QStringLiteral("segment %1").arg(i)));
        }
        // G1: at every joint the incoming and outgoing handles point the same way.
        auto smoothAt = [](const CubicBezier &in, const CubicBezier &out) {
            const QPointF a = in.q3 - in.q2;
            const QPointF b = out.q1 - out.q0;
            const double la = std::hypot(a.x(), a.y()), lb = std::hypot(b.x(), b.y());
            return la > 0 && lb > 0 && std::abs(cross(a, b)) / (la * lb) < 1e-6 && dot(a, b) > 0;
        };
        for (qsizetype i = 0; i + 1 < chain.size(); ++i)
            QVERIFY2(smoothAt(chain[i], chain[i + 1]), qPrintable(QStringLiteral("joint %1").arg(i + 1)));
        if (closed)
            QVERIFY(smoothAt(chain.last(), chain.first()));
        auto along = [](QPointF handle, QPointF tangent) {
            const double lh = std::hypot(handle.x(), handle.y()), lt = std::hypot(tangent.x(), tangent.y());
            return std::abs(cross(handle, tangent)) / (lh * lt) < 1e-6 && dot(handle, tangent) > 0;
        };
        if (!startTangent.isNull())
            QVERIFY(along(chain.first().q1 - chain.first().q0, startTangent));
        if (!endTangent.isNull())
            QVERIFY(along(chain.last().q3 - chain.last().q2, endTangent));
    }

    void chainRejectsMismatchedInput()
    {
        QVERIFY(fitBezierChain({{0, 0}}, {}).isEmpty());
        QVERIFY(fitBezierChain({{0, 0}, {1, 1}, {2, 2}}, {{1, 0}}).isEmpty());
    }

    void chainDegenerateStillPassesThroughTargets()
    {
        // Every anchor and target in one spot, or targets that force a loop: no smoothness to
        // keep, but the segments still pass through their targets and stay finite.
        const QVector<CubicBezier> same = fitBezierChain({{5, 5}, {5, 5}, {5, 5}}, {{5, 5}, {5, 5}});
        QCOMPARE(same.size(), 2);
        for (const CubicBezier &b : same)
            QVERIFY(dist(b.r3(), {5, 5}) < 0.5);
        const QVector<CubicBezier> back = fitBezierChain({{0, 0}, {10, 0}}, {{-40, 5}}, {{1, 0}, {1, 0}, false});
        QCOMPARE(back.size(), 1);
        QVERIFY(dist(back[0].r3(), {-40, 5}) < 0.5);
        QVERIFY(std::isfinite(back[0].q1.x()) && std::isfinite(back[0].q2.y()));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestCurves)
#include "tst_curves.moc"
