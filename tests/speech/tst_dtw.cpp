#include "speech/dtw.h"
#include "testmain.h"

#include <QTest>

#include <vector>

using namespace toonface;

namespace {

// A sequence of two-channel frames built from runs: `count` frames of (x, y), silent or not,
// a long pause or not.
struct Built
{
    std::vector<float> vectors, silence, pause, pauseAt;
    int frames = 0;
    void add(int count, float x, float y, bool silent = false, bool longPause = false)
    {
        for (int k = 0; k < count; ++k) {
            vectors.push_back(x);
            vectors.push_back(y);
            silence.push_back(silent ? 1.0f : 0.0f);
            pause.push_back(longPause ? 1.0f : 0.0f);
            pauseAt.push_back(0.0f);
            ++frames;
        }
    }
    DtwSequence sequence(bool withPauses) const
    {
        return {vectors.data(), silence.data(), frames, withPauses ? pause.data() : nullptr,
            withPauses ? pauseAt.data() : nullptr};
    }
};

// The reference: three units, the second beginning with a stop's closure (silent, no pause),
// and where a pause may go: the last frame of the first and of the second unit. The
// recording: the same with a long pause after the first unit.
void build(Built *reference, Built *recording)
{
    reference->add(20, 1, 0);
    reference->add(6, 0, 0, true);
    reference->add(14, 0, 1);
    reference->add(20, 1, 1);
    reference->pauseAt[19] = 1.0f;
    reference->pauseAt[39] = 1.0f;
    recording->add(20, 1, 0);
    recording->add(50, 0, 0, true, true);
    recording->add(6, 0, 0, true);
    recording->add(14, 0, 1);
    recording->add(20, 1, 1);
}

} // namespace

class TestDtw : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aPauseIsHeldAtABoundaryNotAtAClosure()
    {
        Built reference, recording;
        build(&reference, &recording);
        DtwOptions o;
        o.dim = 2;
        const auto path = dtwPath(recording.sequence(true), reference.sequence(true), o);
        QVERIFY(!path.empty());
        // The recording's pause at the end of the first unit (its last frames, silent like
        // the closure after them, may meet the reference's closure); its closure against the
        // reference's.
        int atBoundary = 0;
        for (const auto &[i, j] : path) {
            if (i >= 20 && i < 70) {
                QVERIFY2(j >= 19 && j < 26, qPrintable(QStringLiteral("pause frame %1 held at %2").arg(i).arg(j)));
                atBoundary += j == 19 ? 1 : 0;
            }
            if (i >= 70 && i < 76)
                QVERIFY2(j >= 20 && j < 26, qPrintable(QStringLiteral("closure frame %1 at %2").arg(i).arg(j)));
        }
        QVERIFY2(atBoundary >= 40, qPrintable(QStringLiteral("%1 of 50 pause frames at the boundary").arg(atBoundary)));
    }
    void withoutPausesTheClosureTakesThePause()
    {
        // What the warp did before pauses and boundaries were told apart: a long pause is
        // silence like a closure, and held there for next to nothing.
        Built reference, recording;
        build(&reference, &recording);
        DtwOptions o;
        o.dim = 2;
        const auto path = dtwPath(recording.sequence(false), reference.sequence(false), o);
        QVERIFY(!path.empty());
        int atClosure = 0;
        for (const auto &[i, j] : path)
            atClosure += i >= 20 && i < 70 && j >= 20 && j < 26 ? 1 : 0;
        QVERIFY(atClosure > 25);
    }
    void coarseToFineFindsTheSamePath()
    {
        // Through the levels (a coarse level that cannot hold the whole matrix) the pause
        // still goes to the boundary.
        Built reference, recording;
        for (int r = 0; r < 20; ++r)
            build(&reference, &recording);
        // build() marks the first round's boundaries; mark every round's.
        for (int r = 0; r < 20; ++r) {
            reference.pauseAt[size_t(r * 60 + 19)] = 1.0f;
            reference.pauseAt[size_t(r * 60 + 39)] = 1.0f;
        }
        DtwOptions o;
        o.dim = 2;
        o.maxFullCells = 20000; // 2400 x 1200 frames: three levels
        o.coarseRadius = 30;
        const auto path = dtwPath(recording.sequence(true), reference.sequence(true), o);
        QVERIFY(!path.empty());
        std::vector<int> atBoundary(20, 0);
        for (const auto &[i, j] : path) {
            const int r = i / 110, at = i % 110;
            if (at >= 20 && at < 70) {
                QVERIFY2(j >= r * 60 + 19 && j < r * 60 + 26,
                    qPrintable(QStringLiteral("pause frame %1 held at %2").arg(i).arg(j)));
                atBoundary[size_t(r)] += j == r * 60 + 19 ? 1 : 0;
            }
        }
        for (int r = 0; r < 20; ++r)
            QVERIFY2(atBoundary[size_t(r)] >= 40,
                qPrintable(QStringLiteral("round %1: %2 of 50 pause frames at the boundary")
                               .arg(r)
                               .arg(atBoundary[size_t(r)])));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestDtw)
#include "tst_dtw.moc"
