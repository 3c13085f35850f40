#include "speech/audiomouth.h"
#include "testmain.h"
#include "track/trackaccuracy.h"

#include <QFileInfo>
#include <QRandomGenerator>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace toonface;

namespace {

constexpr int kRate = 16000;

void appendTone(QVector<float> &out, double seconds, double hz, double amplitude)
{
    const int n = int(seconds * kRate);
    const qsizetype start = out.size();
    for (int i = 0; i < n; ++i)
        out.append(float(amplitude * std::sin(2 * std::numbers::pi * hz * double(start + i) / kRate)));
}

void appendNoise(QVector<float> &out, double seconds, double amplitude, quint32 seed)
{
    QRandomGenerator random(seed);
    const int n = int(seconds * kRate);
    for (int i = 0; i < n; ++i)
        out.append(float(amplitude * (2 * random.generateDouble() - 1)));
}

void addNoise(QVector<float> &out, double amplitude, quint32 seed)
{
    QRandomGenerator random(seed);
    for (float &x : out)
        x += float(amplitude * (2 * random.generateDouble() - 1));
}

// Fraction of frames in [from, to) seconds for which `test` holds.
template<typename Test>
double fraction(const QVector<AudioMouthFrame> &frames, double from, double to, Test test)
{
    int n = 0, yes = 0;
    for (const AudioMouthFrame &f : frames) {
        if (f.time < from || f.time >= to)
            continue;
        ++n;
        yes += test(f) ? 1 : 0;
    }
    return n > 0 ? double(yes) / n : -1.0;
}

bool isOpen(const AudioMouthFrame &f)
{
    return f.shape != MouthShape::M && f.weight > 0;
}

// The pauses of a TextGrid (either of Praat's text formats): intervals labelled "[SIL]", "sil"
// or "sp" (an empty label is not a pause in every file: some leave speech unlabelled).
QVector<QPair<double, double>> silences(const QString &path)
{
    QVector<QPair<double, double>> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return out;
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
    static const QStringList pauses = {QStringLiteral("[SIL]"), QStringLiteral("sil"), QStringLiteral("sp")};
    auto value = [](const QString &line, bool *ok) {
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        return (eq >= 0 ? line.mid(eq + 1) : line).trimmed().toDouble(ok);
    };
    for (qsizetype i = 2; i < lines.size(); ++i) {
        QString text = lines[i].trimmed();
        const bool longFormat = text.startsWith(QLatin1String("text ="));
        if (longFormat)
            text = text.mid(6).trimmed();
        if (!text.startsWith(QLatin1Char('"')) || !text.endsWith(QLatin1Char('"')) || text.size() < 2)
            continue;
        bool okFrom = false, okTo = false;
        const double from = value(lines[i - 2], &okFrom);
        const double to = value(lines[i - 1], &okTo);
        if (okFrom && okTo && pauses.contains(text.mid(1, text.size() - 2)))
            out.append({from, to});
    }
    return out;
}

} // namespace

class TestAudioMouth : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void silenceKeepsTheMouthShut();
    void toneBurstOpensThenShuts();
    void colourPicksRoundedOrSpreadLips();
    void chunksGiveTheSameMouthAsTheWhole();
    void quietBackgroundSinksUnderTheFloor();
    void keysFollowTheShapes();
    void realSpeech_data();
    void realSpeech();
};

void TestAudioMouth::silenceKeepsTheMouthShut()
{
    const QVector<float> zeros(kRate, 0.0f);
    const QVector<AudioMouthFrame> frames = audioMouthTrack(Audio {zeros, kRate});
    QCOMPARE(frames.size(), 50); // 20 ms hops
    for (const AudioMouthFrame &f : frames) {
        QCOMPARE(f.shape, MouthShape::M);
        QCOMPARE(f.openness, 0.0);
    }
    QCOMPARE(frames.last().time, 1.0);
}

void TestAudioMouth::toneBurstOpensThenShuts()
{
    QVector<float> samples;
    appendNoise(samples, 0.6, 0.003, 1); // about -55 dBFS
    QVector<float> burst;
    appendTone(burst, 0.5, 220, 0.3); // about -13 dBFS
    addNoise(burst, 0.003, 2);
    samples += burst;
    appendNoise(samples, 0.8, 0.003, 3);
    const QVector<AudioMouthFrame> frames = audioMouthTrack(Audio {samples, kRate});

    QCOMPARE(fraction(frames, 0.0, 0.6, isOpen), 0.0);
    // Opens within the attack (25 ms) and stays open through the burst.
    QCOMPARE(fraction(frames, 0.7, 1.1, isOpen), 1.0);
    QVERIFY(fraction(frames, 0.7, 1.1, [](const AudioMouthFrame &f) { return f.openness > 0.8; }) > 0.9);
    // Shuts after the release.
    QCOMPARE(fraction(frames, 1.5, 1.9, isOpen), 0.0);
    // The level and the floor are what was played.
    const AudioMouthFrame &loud = frames[45];
    QVERIFY2(std::abs(loud.levelDb - 20 * std::log10(0.3 / std::sqrt(2.0))) < 1.0,
        qPrintable(QString::number(loud.levelDb)));
    QVERIFY(loud.floorDb < -45);
    // The brightness of a pure tone is its frequency.
    QVERIFY2(std::abs(loud.brightnessHz - 220) < 15, qPrintable(QString::number(loud.brightnessHz)));
}

void TestAudioMouth::colourPicksRoundedOrSpreadLips()
{
    // Low and high tones taking turns, with pauses: low ones round the lips, high ones spread them.
    QVector<float> samples;
    for (int k = 0; k < 4; ++k) {
        appendNoise(samples, 0.3, 0.002, 10 + k);
        appendTone(samples, 0.4, 250, 0.25);
        appendNoise(samples, 0.3, 0.002, 20 + k);
        appendTone(samples, 0.4, 2000, 0.25);
    }
    const QVector<AudioMouthFrame> frames = audioMouthTrack(Audio {samples, kRate});
    auto rounded = [](const AudioMouthFrame &f) { return f.shape == MouthShape::U || f.shape == MouthShape::O; };
    auto spread = [](const AudioMouthFrame &f) { return f.shape == MouthShape::I || f.shape == MouthShape::E; };
    // The last round: the average brightness has settled between the two tones.
    const double low = 3 * 1.4 + 0.3;
    const double high = low + 0.7;
    QVERIFY(fraction(frames, low + 0.1, low + 0.4, rounded) > 0.8);
    QVERIFY(fraction(frames, high + 0.1, high + 0.4, spread) > 0.8);
    // Loud tones open the large shape of their colour.
    QVERIFY(fraction(frames, low + 0.1, low + 0.4, [](const AudioMouthFrame &f) { return f.shape == MouthShape::O; })
        > 0.8);
}

void TestAudioMouth::chunksGiveTheSameMouthAsTheWhole()
{
    QVector<float> samples;
    appendNoise(samples, 0.3, 0.002, 4);
    appendTone(samples, 0.3, 400, 0.2);
    appendNoise(samples, 0.3, 0.1, 5);
    const QVector<AudioMouthFrame> whole = audioMouthTrack(Audio {samples, kRate});

    AudioMouth live(kRate);
    QVector<AudioMouthFrame> chunked;
    QRandomGenerator random(6);
    qsizetype at = 0;
    while (at < samples.size()) {
        const qsizetype n = std::min<qsizetype>(samples.size() - at, random.bounded(1, 900));
        chunked += live.push(samples.constData() + at, n);
        at += n;
    }
    QCOMPARE(chunked.size(), whole.size());
    for (qsizetype i = 0; i < whole.size(); ++i) {
        QCOMPARE(chunked[i].shape, whole[i].shape);
        QCOMPARE(chunked[i].openness, whole[i].openness);
    }
    QCOMPARE(live.current().time, whole.last().time);
    live.reset();
    QCOMPARE(live.current().shape, MouthShape::M);
    QCOMPARE(live.push(samples.constData(), 100).size(), 0); // a hop is 320 samples
}

void TestAudioMouth::quietBackgroundSinksUnderTheFloor()
{
    // A steady hum louder than the gate: the mouth stays shut however long it lasts.
    QVector<float> samples;
    appendTone(samples, 3.0, 100, 0.02); // about -37 dBFS
    const QVector<AudioMouthFrame> frames = audioMouthTrack(Audio {samples, kRate});
    QCOMPARE(fraction(frames, 0.0, 3.0, isOpen), 0.0);
}

void TestAudioMouth::keysFollowTheShapes()
{
    QVector<float> samples;
    appendNoise(samples, 0.4, 0.002, 7);
    appendTone(samples, 0.4, 300, 0.25);
    appendNoise(samples, 0.6, 0.002, 8);
    const QVector<AudioMouthFrame> frames = audioMouthTrack(Audio {samples, kRate});
    const QVector<MouthKey> keys = audioMouthKeys(frames, 2.0);
    QVERIFY(keys.size() >= 3);
    QCOMPARE(keys.first().time, 2.0);
    QCOMPARE(keys.first().shape, MouthShape::M);
    QCOMPARE(keys.last().shape, MouthShape::M);
    double end = 2.0;
    for (qsizetype i = 0; i < keys.size(); ++i) {
        QVERIFY(keys[i].duration);
        QCOMPARE(keys[i].time, end); // each key sounds until the next
        end = keys[i].time + *keys[i].duration;
        if (i > 0)
            QVERIFY(keys[i].shape != keys[i - 1].shape);
    }
    QVERIFY(std::abs(end - (2.0 + frames.last().time)) < 1e-9);
    // The open key holds the largest weight its run reached.
    double most = 0;
    for (const MouthKey &k : keys)
        most = std::max(most, k.shape == MouthShape::M ? 0.0 : k.weight);
    QVERIFY(most > 0.9);
}

void TestAudioMouth::realSpeech_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("SSB00050015") << QStringLiteral("SSB00050015");
    QTest::newRow("p2fa_test1") << QStringLiteral("p2fa_test1");
    QTest::newRow("beijing_f3_50_a") << QStringLiteral("beijing_f3_50_a");
}

void TestAudioMouth::realSpeech()
{
    QFETCH(QString, name);
    const QString dir = QStringLiteral(TOONFACE_SHARED_DATA "/speech/");
    QString wav = dir + name + QStringLiteral("_16k.wav");
    if (!QFileInfo::exists(wav))
        wav = dir + name + QStringLiteral(".wav");
    if (!QFileInfo::exists(wav))
        QSKIP("the shared speech recordings are absent");
    const AudioResult loaded = loadAudio(wav);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    const QVector<AudioMouthFrame> frames = audioMouthTrack(loaded.audio);
    QVERIFY(!frames.isEmpty());

    // The pauses the transcription marks (a margin for the release) are mostly shut (a lip
    // smack or a breath may part the lips a little); speech opens.
    const QVector<QPair<double, double>> pauses = silences(dir + name + QStringLiteral(".TextGrid"));
    double speechFrom = 0, speechTo = loaded.audio.duration();
    for (const auto &[from, to] : pauses) {
        if (to - from < 0.3)
            continue;
        const double open = fraction(frames, from + 0.15, to - 0.05, isOpen);
        double sum = 0;
        int n = 0;
        for (const AudioMouthFrame &f : frames) {
            if (f.time >= from + 0.15 && f.time < to - 0.05) {
                sum += f.openness;
                ++n;
            }
        }
        qInfo("pause %.2f-%.2f: %.0f %% of hops open, mean openness %.2f", from, to, 100 * open, sum / n);
        QVERIFY2(open >= 0 && open <= 1.0 / 3,
            qPrintable(QStringLiteral("open in the pause %1-%2: %3").arg(from).arg(to).arg(open)));
        QVERIFY(sum / n < 0.15);
        if (from < 0.1)
            speechFrom = to;
        else if (to > loaded.audio.duration() - 0.1)
            speechTo = from;
    }
    const double open = fraction(frames, speechFrom, speechTo, isOpen);
    QVERIFY2(open > 0.5, qPrintable(QString::number(open)));
    QSet<MouthShape> shapes;
    for (const AudioMouthFrame &f : frames)
        shapes.insert(f.shape);
    QVERIFY2(shapes.size() >= 4, "speech uses several shapes");

    // Openness follows the speech envelope: RMS in 20 ms windows smoothed over 60 ms, computed
    // here independently of the analyser.
    const QVector<float> &s = loaded.audio.samples;
    const int window = kRate / 50;
    QVector<double> envelope;
    for (qsizetype at = 0; at + window <= s.size(); at += window) {
        double sum = 0;
        for (int i = 0; i < window; ++i)
            sum += double(s[at + i]) * s[at + i];
        envelope.append(std::sqrt(sum / window));
    }
    QVector<double> smooth(envelope.size());
    for (qsizetype i = 0; i < envelope.size(); ++i) {
        double sum = 0;
        int n = 0;
        for (qsizetype j = std::max<qsizetype>(0, i - 1); j <= std::min(envelope.size() - 1, i + 1); ++j, ++n)
            sum += envelope[j];
        smooth[i] = sum / n;
    }
    QVector<double> openness;
    for (const AudioMouthFrame &f : frames)
        openness.append(f.openness);
    const double r = pearson(openness, smooth);
    qInfo("%s: open %.2f of speech, %lld shapes, openness/envelope correlation %.3f", qPrintable(name), open,
        qlonglong(shapes.size()), r);
    QVERIFY2(r > 0.7, qPrintable(QString::number(r)));
}

TOONFACE_TEST_GUILESS_MAIN(TestAudioMouth)
#include "tst_audiomouth.moc"
