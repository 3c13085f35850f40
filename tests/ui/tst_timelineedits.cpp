#include "testmain.h"
#include "timelinefixture.h"

#include "timeline/timelineedits.h"

#include <QTest>

#include <cmath>

using namespace toonface;

namespace {

constexpr double kFrame = 0.04;

bool near(double a, double b)
{
    return std::abs(a - b) < 1e-9;
}

QString spansText(const QVector<Span> &spans)
{
    QStringList parts;
    for (const Span &s : spans)
        parts << QStringLiteral("[%1,%2]").arg(s.start).arg(s.end);
    return parts.join(QLatin1Char(' '));
}

void compareSpans(const QVector<Span> &actual, const QVector<Span> &expected)
{
    bool same = actual.size() == expected.size();
    for (qsizetype i = 0; same && i < actual.size(); ++i)
        same = near(actual[i].start, expected[i].start) && near(actual[i].end, expected[i].end);
    QVERIFY2(same, qPrintable(spansText(actual) + QStringLiteral(" != ") + spansText(expected)));
}

} // namespace

class TestTimelineEdits : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void edgeMovesTheBoundaryBetweenTouchingSpans()
    {
        const QVector<Span> spans {{0, 1}, {1, 2}, {2, 3}};
        compareSpans(dragSpanEdge(spans, 0, SpanEdge::End, 1.3, kFrame), {{0, 1.3}, {1.3, 2}, {2, 3}});
        compareSpans(dragSpanEdge(spans, 0, SpanEdge::End, 0.7, kFrame), {{0, 0.7}, {0.7, 2}, {2, 3}});
        compareSpans(dragSpanEdge(spans, 2, SpanEdge::Start, 1.5, kFrame), {{0, 1}, {1, 1.5}, {1.5, 3}});
        // A span keeps at least minSpan.
        compareSpans(dragSpanEdge(spans, 1, SpanEdge::End, 0.5, kFrame), {{0, 1}, {1, 1 + kFrame}, {1 + kFrame, 3}});
    }

    void neighboursGiveWayAndArePushed()
    {
        const QVector<Span> spans {{0, 1}, {1.5, 2}, {2, 2.2}, {3, 4}};
        // Into the second span: it shrinks to a frame, then pushes the third (which touched it)
        // down to a frame; the fourth, apart, stays.
        compareSpans(dragSpanEdge(spans, 0, SpanEdge::End, 2.17, kFrame),
            {{0, 2.17}, {2.17, 2.17 + kFrame}, {2.17 + kFrame, 2.17 + 2 * kFrame}, {3, 4}});
        // Into a gap: nothing else moves.
        compareSpans(dragSpanEdge(spans, 0, SpanEdge::End, 1.2, kFrame), {{0, 1.2}, {1.5, 2}, {2, 2.2}, {3, 4}});
        // Backwards past 0: the pushed spans stop at 0.
        const QVector<Span> early {{0.1, 0.2}, {0.2, 1}};
        compareSpans(dragSpanEdge(early, 1, SpanEdge::Start, -0.5, kFrame), {{0, kFrame}, {kFrame, 1}});
    }

    void moveIsClampedByNeighbours()
    {
        QVector<Span> spans {{0, 1}, {1, 2}, {2.5, 3}};
        // The middle one moves right: its left neighbour follows (they touched), its right one
        // gives way down to a frame.
        double dt = moveSpans(spans, {1}, 10, kFrame);
        QVERIFY(near(dt, 3 - kFrame - 2));
        compareSpans(spans, {{0, 1 + dt}, {1 + dt, 2 + dt}, {2 + dt, 3}});
        QVector<Span> first {{0.5, 1}, {1, 2}};
        QVERIFY(near(moveSpans(first, {0}, -2, kFrame), -0.5)); // not before 0
        compareSpans(first, {{0, 0.5}, {0.5, 2}});
    }

    // Dragging a syllable's end re-times its shapes by face-model.md's fractions and moves the
    // mouth keys with them; the next syllable (touching it) gives way the same way.
    void syllableEdgeRetimesItsShapes()
    {
        const Animation before = fixture::talkingAnimation();
        const Animation after
            = dragItemEdge(before, {ItemKind::Syllable, 1}, SpanEdge::End, 0.9, kFrame); // hao ends at 0.9
        const LipsyncSyllable &hao = after.syllables[1];
        QVERIFY(near(hao.start, 0.5) && near(hao.end, 0.9));
        QCOMPARE(hao.shapes.size(), 2); // a u
        QVERIFY(near(hao.shapes[1].start, 0.5 + shapeStartFraction(2, 1) * 0.4));
        const LipsyncSyllable &ma = after.syllables[2];
        QVERIFY(near(ma.start, 0.9) && near(ma.end, 1.1));
        QVERIFY(near(ma.shapes[1].start, 0.9 + shapeStartFraction(2, 1) * 0.2));
        // A mouth key at every new shape start, holding the shape the syllable says.
        for (const LipsyncSyllable *syl : {&hao, &ma})
            for (const ShapeKey &k : syl->shapes) {
                const int i = fixture::mouthKeyAt(after, k.start);
                QVERIFY2(i >= 0, qPrintable(QStringLiteral("no key at %1").arg(k.start)));
                QCOMPARE(after.timeline.mouthKeys()[i].shape, k.shape);
            }
        // The old shape start of u is gone; syllables not reached keep their keys.
        QCOMPARE(fixture::mouthKeyAt(after, before.syllables[1].shapes[1].start), -1);
        QCOMPARE(after.syllables[0], before.syllables[0]);
        QCOMPARE(after.syllables[3], before.syllables[3]);
        for (const MouthKey &k : before.timeline.mouthKeys())
            if (k.time < 0.5 - 1e-9 || k.time > 1.1 + 1e-9)
                QVERIFY(fixture::mouthKeyAt(after, k.time) >= 0);
        QCOMPARE(after.timeline.emotionClips(), before.timeline.emotionClips());
    }

    void syllableMoveKeepsItsShapesInside()
    {
        const Animation before = fixture::talkingAnimation();
        const Animation after = moveItems(before, {{ItemKind::Syllable, 3}}, -0.2, kFrame); // ming into the pause
        QVERIFY(near(after.syllables[3].start, 1.4) && near(after.syllables[3].end, 1.8));
        QVERIFY(near(after.syllables[4].start, 1.8)); // tian touched it: its start follows
        for (const LipsyncSyllable &syl : after.syllables)
            for (const ShapeKey &k : syl.shapes)
                QCOMPARE(fixture::mouthShapeAt(after, k.start + 1e-6), std::optional(k.shape));
    }

    // Every shape of every syllable is where the mouth track says it is, after each edit.
    void shapesAndTrackAgree_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("index");
        QTest::addColumn<int>("edge");
        QTest::addColumn<double>("to");
        QTest::newRow("hao end later") << int(ItemKind::Syllable) << 1 << int(SpanEdge::End) << 0.93;
        QTest::newRow("hao start earlier") << int(ItemKind::Syllable) << 1 << int(SpanEdge::Start) << 0.31;
        QTest::newRow("ma end into the pause") << int(ItemKind::Syllable) << 2 << int(SpanEdge::End) << 1.45;
        QTest::newRow("ming start back") << int(ItemKind::Syllable) << 3 << int(SpanEdge::Start) << 1.2;
        QTest::newRow("tian end squeezed") << int(ItemKind::Syllable) << 4 << int(SpanEdge::End) << 2.0;
        QTest::newRow("ni end pushes two") << int(ItemKind::Syllable) << 0 << int(SpanEdge::End) << 1.05;
    }
    void shapesAndTrackAgree()
    {
        QFETCH(int, kind);
        QFETCH(int, index);
        QFETCH(int, edge);
        QFETCH(double, to);
        const Animation after
            = dragItemEdge(fixture::talkingAnimation(), {ItemKind(kind), index}, SpanEdge(edge), to, kFrame);
        for (qsizetype s = 0; s < after.syllables.size(); ++s) {
            const LipsyncSyllable &syl = after.syllables[s];
            QVERIFY(syl.end - syl.start >= kFrame - 1e-9);
            if (s > 0)
                QVERIFY(syl.start >= after.syllables[s - 1].end - 1e-9);
            for (const ShapeKey &k : syl.shapes)
                QCOMPARE(fixture::mouthShapeAt(after, k.start + 1e-6), std::optional(k.shape));
        }
    }

    void pinyinRederivesShapes()
    {
        const Animation before = fixture::talkingAnimation();
        QString error;
        const std::optional<Animation> after = setSyllablePinyin(before, 2, QStringLiteral("miao4"), &error);
        QVERIFY2(after, qPrintable(error));
        const LipsyncSyllable &syl = after->syllables[2];
        QCOMPARE(syl.pinyin, QStringLiteral("miao"));
        QCOMPARE(syl.tone, 4);
        QCOMPARE(shapeSpelling({syl.shapes[0].shape, syl.shapes[1].shape, syl.shapes[2].shape, syl.shapes[3].shape}),
            QStringLiteral("m i a u"));
        for (int k = 0; k < 4; ++k) {
            QVERIFY(near(syl.shapes[k].start, 0.8 + shapeStartFraction(4, k) * 0.3));
            const int i = fixture::mouthKeyAt(*after, syl.shapes[k].start);
            QVERIFY(i >= 0);
            QCOMPARE(after->timeline.mouthKeys()[i].shape, syl.shapes[k].shape);
        }
        // Nothing else moved.
        for (const MouthKey &k : before.timeline.mouthKeys())
            if (k.time < 0.8 - 1e-9 || k.time >= 1.1 - 1e-9)
                QVERIFY(fixture::mouthKeyAt(*after, k.time) >= 0);

        QVERIFY(!setSyllablePinyin(before, 2, QStringLiteral("xyzzy"), &error));
        QVERIFY(error.contains(QStringLiteral("xyzzy")));
        Animation english = before;
        english.syllables[0].pinyin.clear();
        QVERIFY(!setSyllablePinyin(english, 0, QStringLiteral("ni"), &error));
    }

    void deletedCueIsHeldByTheOneBefore()
    {
        const Animation before = fixture::talkingAnimation();
        const int u = fixture::mouthKeyAt(before, before.syllables[1].shapes[1].start); // hao's u
        const QVector<Span> spans = itemSpans(before, ItemKind::Mouth);
        const Animation after = deleteItems(before, {{ItemKind::Mouth, u}});
        QCOMPARE(after.timeline.mouthKeys().size(), before.timeline.mouthKeys().size() - 1);
        const QVector<Span> left = itemSpans(after, ItemKind::Mouth);
        QVERIFY(near(left[u - 1].end, spans[u].end));
        QCOMPARE(after.timeline.mouthKeys()[u - 1].shape, MouthShape::A);
    }

    void deletedSyllableIsSilence()
    {
        const Animation before = fixture::talkingAnimation();
        const Animation after = deleteItems(before, {{ItemKind::Syllable, 2}});
        QCOMPARE(after.syllables.size(), 4);
        const int i = fixture::mouthKeyAt(after, 0.8);
        QVERIFY(i >= 0);
        QCOMPARE(after.timeline.mouthKeys()[i].shape, MouthShape::M);
        for (const MouthKey &k : after.timeline.mouthKeys())
            QVERIFY(k.time <= 0.8 + 1e-9 || k.time >= 1.1 - 1e-9);
    }

    void insertSplitsTheCueUnderIt()
    {
        const Animation before = fixture::talkingAnimation();
        const QVector<Span> spans = itemSpans(before, ItemKind::Mouth);
        int index = -1;
        const Animation after = insertMouthKey(before, 2.7, MouthShape::O, kFrame, &index); // in the closing m
        QVERIFY(index >= 0);
        const MouthKey &k = after.timeline.mouthKeys()[index];
        QVERIFY(near(k.time, 2.7));
        QCOMPARE(k.shape, MouthShape::O);
        QVERIFY(near(k.time + *k.duration, spans.last().end));
        QVERIFY(near(itemSpans(after, ItemKind::Mouth)[index - 1].end, 2.7));
    }

    void replaceShapeAndWeight()
    {
        const Animation before = fixture::talkingAnimation();
        Animation after = setMouthShape(before, {1, 2}, MouthShape::E);
        QCOMPARE(after.timeline.mouthKeys()[1].shape, MouthShape::E);
        QCOMPARE(after.timeline.mouthKeys()[2].shape, MouthShape::E);
        QCOMPARE(after.timeline.mouthKeys()[3], before.timeline.mouthKeys()[3]);
        after = setMouthWeight(after, {1}, 0.4);
        QCOMPARE(after.timeline.mouthKeys()[1].weight, 0.4);
        QCOMPARE(setMouthWeight(after, {1}, 7).timeline.mouthKeys()[1].weight, 1.0);
    }

    void emotionInsertCutsOthers()
    {
        const Animation before = fixture::talkingAnimation(); // smile 0.3 .. 1.5
        int index = -1;
        const Animation after = insertEmotion(before, Emotion::Sad, 0.6, 1.0, 0.5, &index);
        const QVector<EmotionClip> &clips = after.timeline.emotionClips();
        QCOMPARE(clips.size(), 3);
        QCOMPARE(clips[index].emotion, Emotion::Sad);
        QVERIFY(near(clips[0].start, 0.3) && near(clips[0].end, 0.6));
        QVERIFY(near(clips[2].start, 1.0) && near(clips[2].end, 1.5));
        QCOMPARE(clips[2].emotion, Emotion::Smile);
        QVERIFY(clips[0].fadeIn + clips[0].fadeOut <= 0.3 + 1e-9);
    }

    void fadesAndIntensityAreClamped()
    {
        const Animation before = fixture::talkingAnimation(); // 1.2 s long
        const EmotionClip &c = setEmotionFades(before, 0, 0.9, 0.9).timeline.emotionClips()[0];
        QVERIFY(near(c.fadeIn, 0.9) && near(c.fadeOut, 1.2 - 0.9));
        QVERIFY(near(setEmotionFades(before, 0, -1, 0.1).timeline.emotionClips()[0].fadeIn, 0));
        QVERIFY(near(setEmotionIntensity(before, 0, 0.25).timeline.emotionClips()[0].intensity, 0.25));
        QVERIFY(near(setEmotionIntensity(before, 0, 3).timeline.emotionClips()[0].intensity, 1));
    }

    void keysKeepTheirOrder()
    {
        const Animation before = fixture::talkingAnimation(); // head keys at 0, 1, 2
        double applied = 0;
        const Animation after = moveItems(before, {{ItemKind::Head, 1}, {ItemKind::Blink, 0}}, 5, kFrame, &applied);
        QVERIFY(applied < 1.0 && applied > 0.9); // stops short of the key at 2
        QVERIFY(after.timeline.headKeys()[1].time < after.timeline.headKeys()[2].time);
        QVERIFY(near(after.timeline.blinks()[0].time, 0.9 + applied)); // moved with it
    }

    void poseKeysMoveDeleteAndPaste()
    {
        const Animation before = fixture::talkingAnimation(); // pose keys at 0.6 and 1.4
        Animation after = moveItems(before, {{ItemKind::Pose, 0}}, 0.3, kFrame);
        QVERIFY(near(after.timeline.poseKeys()[0].time, 0.9));
        QCOMPARE(after.timeline.poseKeys()[0].offsetsEs0, before.timeline.poseKeys()[0].offsetsEs0);
        double applied = 0;
        moveItems(before, {{ItemKind::Pose, 0}}, 5, kFrame, &applied);
        QVERIFY(applied < 0.8); // stays before the key at 1.4
        after = deleteItems(before, {{ItemKind::Pose, 1}});
        QCOMPARE(after.timeline.poseKeys().size(), 1);
        QString error;
        Selection pasted;
        const std::optional<Animation> copied
            = pasteItems(before, copyItems(before, {{ItemKind::Pose, 0}}), 2.0, &error, &pasted);
        QVERIFY2(copied, qPrintable(error));
        QCOMPARE(copied->timeline.poseKeys().size(), 3);
        QVERIFY(near(copied->timeline.poseKeys()[2].time, 2.0));
        QCOMPARE(copied->timeline.poseKeys()[2].offsetsEs0, before.timeline.poseKeys()[0].offsetsEs0);
        QCOMPARE(pasted, Selection({{ItemKind::Pose, 2}}));
    }

    void copyPasteRoundTrip()
    {
        const Animation before = fixture::talkingAnimation();
        const Selection copied {
            {ItemKind::Mouth, 1}, {ItemKind::Mouth, 2}, {ItemKind::Emotion, 0}, {ItemKind::Blink, 0}};
        const QJsonObject items = copyItems(before, copied);
        QVERIFY(!items.isEmpty());
        const double origin = selectionRange(before, copied)->start;
        QString error;
        Selection pasted;
        const std::optional<Animation> after = pasteItems(before, items, 2.5, &error, &pasted);
        QVERIFY2(after, qPrintable(error));
        QCOMPARE(pasted.size(), 4);
        for (int i : {1, 2}) {
            const MouthKey &k = before.timeline.mouthKeys()[i];
            const int j = fixture::mouthKeyAt(*after, k.time - origin + 2.5);
            QVERIFY(j >= 0);
            QCOMPARE(after->timeline.mouthKeys()[j].shape, k.shape);
            QVERIFY(pasted.contains({ItemKind::Mouth, j}));
        }
        QCOMPARE(after->timeline.emotionClips().size(), 2);
        QVERIFY(near(after->timeline.emotionClips()[1].start, 0.3 - origin + 2.5));
        QCOMPARE(after->timeline.blinks().size(), 3);
        QVERIFY(!pasteItems(before, QJsonObject {{QStringLiteral("format"), QStringLiteral("other")}}, 0, &error));
        QVERIFY(!error.isEmpty());
    }

    void blinksAndHeadMotion()
    {
        const Animation before = fixture::talkingAnimation();
        const Animation a = regenerateBlinks(before, 7), b = regenerateBlinks(before, 8);
        QCOMPARE(a, regenerateBlinks(before, 7));
        QVERIFY(a.timeline.blinks() != b.timeline.blinks());
        QVERIFY(!a.timeline.blinks().isEmpty());
        const Animation shaken = addShake(before, 0.5, 1.5);
        QVERIFY(shaken.timeline.headKeys().size() > before.timeline.headKeys().size());
        QVERIFY(addNod(before, 0.5, 1.5).timeline.headKeys() != shaken.timeline.headKeys());
        QCOMPARE(addShake(before, 1, 1), before);
    }

    void snapping()
    {
        const QVector<double> boundaries {0.5, 1.234};
        QVERIFY(near(snapTime(1.22, 25, boundaries, 0.02), 1.234)); // a syllable boundary wins
        QVERIFY(near(snapTime(1.17, 25, boundaries, 0.02), 1.16)); // else the nearest frame
        QVERIFY(near(snapTime(1.17, 0, boundaries, 0.02), 1.17));
        QCOMPARE(syllableBoundaries(fixture::talkingAnimation()).size(), 7);
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestTimelineEdits)
#include "tst_timelineedits.moc"
