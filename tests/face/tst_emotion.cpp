#include "face/averageface.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pose.h"
#include "testmain.h"

#include <QTest>

#include <tuple>

using namespace toonface;

namespace {

// How far a preset must move a feature at full intensity to read "from across the room", in ES0.
constexpr double kClear = 0.1;

FaceModel testFace()
{
    return averageFace(QRectF(100, 150, 200, 240), QSize(400, 500));
}

struct Posed
{
    std::array<QPointF, kPointCount> n, p;
    double es0;
    QPointF at(const char *id) const { return p[pt::idx(id)]; }
    QPointF at0(const char *id) const { return n[pt::idx(id)]; }
    // Displacement in ES0 units.
    QPointF d(const char *id) const { return (at(id) - at0(id)) / es0; }
    double eyeOpening(bool left) const { return left ? at("3.4").y() - at("3.2").y() : at("3.3").y() - at("3.1").y(); }
    double eyeOpening0(bool left) const
    {
        return left ? at0("3.4").y() - at0("3.2").y() : at0("3.3").y() - at0("3.1").y();
    }
    double mouthWidth() const { return at("8.3").x() - at("8.4").x(); }
    double mouthWidth0() const { return at0("8.3").x() - at0("8.4").x(); }
    double opening() const { return at("2.3").y() - at("2.2").y(); }
    // How far the brows' inner ends sit above (negative: below) their outer ends, in ES0.
    double innerAboveOuter(bool left) const
    {
        return left ? (at("4.6").y() - at("4.2").y()) / es0 : (at("4.5").y() - at("4.1").y()) / es0;
    }
    double innerAboveOuter0(bool left) const
    {
        return left ? (at0("4.6").y() - at0("4.2").y()) / es0 : (at0("4.5").y() - at0("4.1").y()) / es0;
    }
};

Posed posed(const FaceModel &face, const Pose &pose)
{
    return {face.points(), posedPoints(face, pose), face.fapu().es0};
}

} // namespace

class TestEmotion : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void names()
    {
        for (Emotion e : kAllEmotions)
            QCOMPARE(emotionFromName(emotionName(e)), std::optional<Emotion>(e));
        QVERIFY(!emotionFromName(QStringLiteral("bored")));
    }

    void neutralMovesNothing()
    {
        const FaceModel face = testFace();
        QCOMPARE(emotionPose(face, Emotion::Neutral, 1.0), Pose());
    }

    // Each preset moves its features in the stated directions, clearly at full intensity and
    // the same way, three quarters as far (emotionWeight), at half intensity; both sides mirror
    // each other.
    void directions_data()
    {
        QTest::addColumn<double>("intensity");
        QTest::newRow("full") << 1.0;
        QTest::newRow("half") << 0.5;
    }

    void directions()
    {
        QFETCH(double, intensity);
        const FaceModel face = testFace();
        const double clear = kClear * emotionWeight(intensity);

        // Smile: corners up and back, the mouth open on the teeth, lower lids up, brows a little up.
        {
            const Posed s = posed(face, emotionPose(face, Emotion::Smile, intensity));
            QVERIFY(s.d("8.4").y() < -clear && s.d("8.3").y() < -clear);
            QVERIFY(s.d("8.4").x() < -clear / 2 && s.d("8.3").x() > clear / 2);
            QVERIFY(s.opening() > clear * s.es0);
            QVERIFY(s.d("3.4").y() < 0 && s.d("3.3").y() < 0);
            QVERIFY(s.d("4.4").y() < 0 && s.d("4.3").y() < 0);
            // The corners end above the upper lip's middle: the mouth curves up.
            QVERIFY(s.at("8.4").y() < s.at("8.1").y() || intensity < 1);
        }
        // Sad: inner brow ends raised above their outer ends, heavy lids, corners down.
        {
            const Posed s = posed(face, emotionPose(face, Emotion::Sad, intensity));
            for (bool left : {true, false}) {
                QVERIFY(s.innerAboveOuter(left) - s.innerAboveOuter0(left) > clear);
                QVERIFY(s.eyeOpening(left) < s.eyeOpening0(left) * (1 - 0.1 * emotionWeight(intensity)));
            }
            QVERIFY(s.d("4.2").y() < -clear && s.d("4.1").y() < -clear);
            QVERIFY(s.d("4.6").y() > 0 && s.d("4.5").y() > 0);
            QVERIFY(s.d("3.2").y() > 0 && s.d("3.1").y() > 0);
            QVERIFY(s.d("8.4").y() > clear && s.d("8.3").y() > clear);
            QVERIFY(s.d("8.2").y() < 0); // the lower lip pushed up under the frown
        }
        // Angry: inner brow ends down and together (a V), outer ends up, lids narrowed, the lips
        // bared on the teeth with their corners down.
        {
            const Posed s = posed(face, emotionPose(face, Emotion::Angry, intensity));
            for (bool left : {true, false})
                QVERIFY(s.innerAboveOuter(left) - s.innerAboveOuter0(left) < -clear);
            QVERIFY(s.d("4.2").y() > clear && s.d("4.1").y() > clear);
            QVERIFY(s.d("4.2").x() > clear / 3 && s.d("4.1").x() < -clear / 3);
            QVERIFY(s.eyeOpening(true) < s.eyeOpening0(true));
            QVERIFY(s.d("4.6").y() < 0 && s.d("4.5").y() < 0);
            QVERIFY(s.mouthWidth() <= s.mouthWidth0() + 1e-9); // bared, not a smile's widening
            QVERIFY(s.d("8.4").y() > clear / 2 && s.d("8.3").y() > clear / 2);
            QVERIFY(s.opening() > posed(face, Pose()).opening() + 0.5 * clear * s.es0); // bared teeth
            QVERIFY(s.d("8.9").y() < 0); // the upper lip raised off them
        }
        // Surprise: brows high, eyes wide, the jaw dropped under rounded lips.
        {
            const Posed s = posed(face, emotionPose(face, Emotion::Surprise, intensity));
            for (const char *id : {"4.6", "4.4a", "4.4", "4.2", "4.1", "4.3", "4.3a", "4.5"})
                QVERIFY(s.d(id).y() < -clear);
            QVERIFY(s.eyeOpening(true) > s.eyeOpening0(true) * (1 + 0.2 * emotionWeight(intensity)));
            QVERIFY(s.eyeOpening(false) > s.eyeOpening0(false) * (1 + 0.2 * emotionWeight(intensity)));
            QVERIFY(s.d("8.2").y() > 3 * clear);
            QVERIFY(s.d("2.1").y() > 3 * clear); // the chin drops with the lower lip
            QVERIFY(s.mouthWidth() < s.mouthWidth0());
        }
    }

    // A face photographed with a grin (corners above the lips' line, lips apart): sad and angry
    // take the grin out, sad shuts the lips; smile and surprise keep the photo's mouth as it is.
    void grinningPhoto()
    {
        FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        auto move = [&](const char *id, QPointF by) {
            face.setPoint(pt::idx(id), face.point(id) + by * es0, face.isHandPlaced(pt::idx(id)));
        };
        move("8.4", {-0.05, -0.2});
        move("8.3", {0.05, -0.2});
        move("8.2", {0, 0.16});
        move("2.3", {0, 0.16});
        move("2.1", {0, 0.16});
        const double lipLine = (face.point("2.2").y() + face.point("2.3").y()) / 2.0;
        for (Emotion e : {Emotion::Sad, Emotion::Angry}) {
            const Posed s = posed(face, emotionPose(face, e, 1.0));
            QVERIFY2(s.at("8.4").y() > lipLine + 0.05 * es0 && s.at("8.3").y() > lipLine + 0.05 * es0,
                qPrintable(emotionName(e)));
        }
        const Posed sad = posed(face, stillEmotionPose(face, Emotion::Sad, 1.0));
        QVERIFY(sad.opening() < 0.02 * es0);
        // Neutral is neutral and surprise an O: the photo's smile is taken out of both, and the
        // still drawing of neutral shuts the lips photographed apart (as the rest does).
        const Posed neutral = posed(face, stillEmotionPose(face, Emotion::Neutral, 1.0));
        // Its corners on the line where the shut lips meet: a straight mouth, neither up nor down.
        QVERIFY(neutral.opening() < 0.02 * es0);
        QVERIFY(std::abs(neutral.at("8.4").y() - neutral.at("2.2").y()) < 0.01 * es0);
        QVERIFY(std::abs(neutral.at("8.3").y() - neutral.at("2.2").y()) < 0.01 * es0);
        const Posed surprise = posed(face, emotionPose(face, Emotion::Surprise, 1.0));
        const double meet = neutral.at("2.2").y();
        QVERIFY(surprise.at("8.4").y() > meet && surprise.at("8.3").y() > meet);
        const Posed half = posed(face, emotionPose(face, Emotion::Sad, 0.5));
        QVERIFY(half.at("8.4").y() > face.point("8.4").y() + 0.1 * es0);
        const Posed smile = posed(face, emotionPose(face, Emotion::Smile, 1.0));
        QVERIFY(smile.at("8.4").y() < face.point("8.4").y());
    }

    // Half intensity still reads: every move is three quarters of the full one, the same way
    // (the pose is the full one times emotionWeight); a quarter draws less, and the weight rises
    // from 0 to 1 without a step or a turn back.
    void halfStillReads()
    {
        QCOMPARE(emotionWeight(0.0), 0.0);
        QCOMPARE(emotionWeight(1.0), 1.0);
        QCOMPARE(emotionWeight(0.5), 0.75);
        QCOMPARE(emotionWeight(-0.5), -0.75);
        for (double i = 0.0; i < 1.5; i += 0.05)
            QVERIFY(emotionWeight(i + 0.05) > emotionWeight(i));
        const FaceModel face = testFace();
        for (Emotion e : kAllEmotions) {
            const Pose full = emotionPose(face, e, 1.0), half = emotionPose(face, e, 0.5),
                       quarter = emotionPose(face, e, 0.25);
            for (int i = 0; i < kPointCount; ++i) {
                QVERIFY(std::abs(half.offset[i].x() - 0.75 * full.offset[i].x()) < 1e-9);
                QVERIFY(std::abs(half.offset[i].y() - 0.75 * full.offset[i].y()) < 1e-9);
                QVERIFY(QLineF(QPointF(), quarter.offset[i]).length() <= QLineF(QPointF(), half.offset[i]).length());
            }
            QVERIFY(std::abs((half.leftEyeOpen - 1.0) - 0.75 * (full.leftEyeOpen - 1.0)) < 1e-9);
        }
    }

    void sidesMirror()
    {
        const FaceModel face = testFace();
        for (Emotion e : kAllEmotions) {
            const Pose pose = emotionPose(face, e, 1.0);
            for (const char *id : {"4.6", "4.4a", "4.4", "4.2", "3.2", "3.4", "8.4"}) {
                const QPointF a = pose.offset[pt::idx(id)], b = pose.offset[pt::idx(mirrorPointId(id))];
                QCOMPARE(a.x(), -b.x());
                QCOMPARE(a.y(), b.y());
            }
        }
    }

    // The five presets are far apart from each other: no two read alike.
    void presetsDiffer()
    {
        const FaceModel face = testFace();
        const double es0 = face.fapu().es0;
        for (Emotion a : kAllEmotions) {
            for (Emotion b : kAllEmotions) {
                if (a >= b)
                    continue;
                const auto pa = posedPoints(face, emotionPose(face, a, 1.0));
                const auto pb = posedPoints(face, emotionPose(face, b, 1.0));
                double far = 0;
                for (int i = 0; i < kPointCount; ++i)
                    far = std::max(far, QLineF(pa[i], pb[i]).length() / es0);
                QVERIFY2(far > 0.15, qPrintable(emotionName(a) + QLatin1Char('/') + emotionName(b)));
            }
        }
    }

    // Lids move by the eye's own opening: narrow eyes (a smile in the photo, a squint, 0.07 ES0
    // as in the shared group photo) keep an open eye through sad and angry, lowered by the same
    // share of their opening as an average eye, and never turn inside out; the brows and mouth
    // move as much as on any face.
    void narrowEyesStayOpen_data()
    {
        QTest::addColumn<double>("opening");
        QTest::newRow("narrow") << 0.07;
        QTest::newRow("average") << 0.0;
        QTest::newRow("wide") << 0.2;
    }

    void narrowEyesStayOpen()
    {
        QFETCH(double, opening);
        const FaceModel average = testFace();
        FaceModel face = average;
        const double es0 = face.fapu().es0;
        if (opening > 0) {
            // Each lid moved toward the line between its eye's corners, keeping its side.
            for (const auto &[lid, a, b] : {std::tuple {"3.2", "3.12", "3.8"}, std::tuple {"3.4", "3.12", "3.8"},
                     std::tuple {"3.1", "3.11", "3.7"}, std::tuple {"3.3", "3.11", "3.7"}}) {
                const double line = (face.point(a).y() + face.point(b).y()) / 2.0;
                const double side = face.point(lid).y() < line ? -1.0 : 1.0;
                face.setPoint(pt::idx(lid), QPointF(face.point(lid).x(), line + side * opening * es0 / 2.0),
                    face.isHandPlaced(pt::idx(lid)));
            }
        }
        for (Emotion e : kAllEmotions) {
            for (double intensity : {0.5, 1.0}) {
                const Posed p = posed(face, emotionPose(face, e, intensity));
                const Posed a = posed(average, emotionPose(average, e, intensity));
                const QByteArray what = (emotionName(e) + QStringLiteral(" at %1").arg(intensity)).toLatin1();
                for (bool left : {true, false}) {
                    const double share = p.eyeOpening(left) / p.eyeOpening0(left);
                    const double averageShare = a.eyeOpening(left) / a.eyeOpening0(left);
                    QVERIFY2(p.eyeOpening(left) > 0, what.constData());
                    QVERIFY2(std::abs(share - averageShare) < 0.02, what.constData());
                }
                QVERIFY2(QLineF(p.d("4.2"), a.d("4.2")).length() < 1e-9, what.constData());
                QVERIFY2(QLineF(p.d("8.4"), a.d("8.4")).length() < 1e-9, what.constData());
            }
        }
    }

    // A sad face still speaks: with an open mouth shape the corners stay down and the brows
    // slanted, and the mouth opens.
    void combinesWithSpeech()
    {
        const FaceModel face = testFace();
        const MouthShapeSet shapes;
        const Pose speech = mouthPose(face, shapes, MouthShape::A);
        const Posed talk = posed(face, speech);
        const Posed sad = posed(face, speech + emotionPose(face, Emotion::Sad, 1.0));
        QVERIFY(sad.opening() > 0.5 * talk.opening());
        QVERIFY(sad.at("8.4").y() > talk.at("8.4").y() + kClear * sad.es0);
        QVERIFY(sad.innerAboveOuter(true) > sad.innerAboveOuter0(true) + kClear);
        const Posed smile = posed(face, speech + emotionPose(face, Emotion::Smile, 1.0));
        QVERIFY(smile.at("8.4").y() < talk.at("8.4").y() - kClear * smile.es0);
        QVERIFY(smile.opening() > talk.opening());
    }
};

TOONFACE_TEST_APPLESS_MAIN(TestEmotion)
#include "tst_emotion.moc"
