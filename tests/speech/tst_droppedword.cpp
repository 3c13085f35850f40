#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"
#include "testmain.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace toonface;

namespace {

Script mandarin(const QString &text)
{
    return parseScript(text, Language::Mandarin).script;
}

// `text` spoken in another voice than the reference's, with silence around it.
Audio spoken(const QString &text, std::vector<double> *onsets)
{
    TtsOptions o;
    o.voice = QStringLiteral("cmn-latn-pinyin+m2");
    o.rate = 190;
    o.pitch = 40;
    const TtsResult r = synthesize(mandarin(text), o);
    Audio out;
    out.samples.fill(0.0f, qsizetype(0.4 * kSpeechSampleRate));
    out.samples += resampled(r.audio, kSpeechSampleRate).samples;
    out.samples += QVector<float>(qsizetype(0.4 * kSpeechSampleRate), 0.0f);
    onsets->clear();
    for (const TtsUnit &u : r.units)
        onsets->push_back(0.4 + u.start);
    return out;
}

} // namespace

class TestDroppedWord : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aDroppedWordIsReported()
    {
        // The speaker leaves out 今天 (syllables 1 and 2 of the script).
        std::vector<double> truth;
        const Audio rec = spoken(QStringLiteral("我很高兴见到你，我们去公园散步吧。"), &truth);
        const Script script = mandarin(QStringLiteral("我今天很高兴见到你，我们去公园散步吧。"));
        const AlignResult r = alignScript(rec, script);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QString heard;
        for (const AlignedSyllable &s : r.syllables)
            heard += QString::number(s.heard, 'f', 2) + QLatin1Char(' ');
        QVERIFY2(r.unspoken.contains(1) || r.unspoken.contains(2), qPrintable(heard));
        // Reported where it was dropped: the warp may run through the missing word's frames
        // over its neighbour's sound, flagging the syllable beside it instead of one of them.
        for (const int k : r.unspoken) {
            QVERIFY2(k >= 0 && k <= 3, qPrintable(heard));
            QCOMPARE(r.syllables[k].confidence, 0.0);
        }
        // The syllables spoken keep their places (the truth skips the dropped two).
        std::vector<double> errors;
        for (int k = 0; k < r.syllables.size(); ++k) {
            if (k == 1 || k == 2)
                continue;
            errors.push_back(std::abs(r.syllables[k].start - truth[size_t(k < 1 ? k : k - 2)]) * 1000);
        }
        std::sort(errors.begin(), errors.end());
        QVERIFY2(errors[errors.size() / 2] < 40, qPrintable(QString::number(errors[errors.size() / 2])));
    }

    void aCleanRecordingHasNothingUnspoken()
    {
        std::vector<double> truth;
        const QString text = QStringLiteral("我今天很高兴见到你，我们去公园散步吧。");
        const Audio rec = spoken(text, &truth);
        const AlignResult r = alignScript(rec, mandarin(text));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QString heard;
        for (const AlignedSyllable &s : r.syllables)
            heard += QString::number(s.heard, 'f', 2) + QLatin1Char(' ');
        QVERIFY2(r.unspoken.isEmpty(), qPrintable(heard));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestDroppedWord)
#include "tst_droppedword.moc"
