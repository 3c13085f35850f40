#include "speech/lipsync.h"

#include "i18n/coretext.h"
#include "speech/englishshapes.h"
#include "speech/stagetimes.h"

#include <QJsonArray>

#include <cmath>

namespace toonface {

namespace {

double ms(double seconds)
{
    return std::round(seconds * 1000.0) / 1000.0;
}

QVector<ShapeKey> keysOf(const Script &script, int k, double start, double end, const QVector<TtsPhoneme> &phonemes)
{
    if (script.language == Language::English)
        return englishWordKeys(phonemes, start, end);
    return syllableShapeKeys(syllableShapes(script.syllables[k].pinyin), start, end - start);
}

} // namespace

QVector<MouthCue> mouthCues(const QVector<LipsyncSyllable> &syllables, double duration)
{
    QVector<MouthCue> cues;
    auto push = [&](double start, double end, MouthShape shape) {
        if (end <= start + 1e-9)
            return;
        if (!cues.isEmpty() && cues.back().shape == shape && std::abs(cues.back().end - start) < 1e-9) {
            cues.back().end = end;
            return;
        }
        cues.append({start, end, shape});
    };
    double t = 0;
    for (int s = 0; s < syllables.size(); ++s) {
        const LipsyncSyllable &syl = syllables[s];
        if (syl.shapes.isEmpty())
            continue;
        const double start = std::max(syl.start, t);
        if (start - t > kSilenceHold || cues.isEmpty())
            push(t, start, MouthShape::M);
        else if (!cues.isEmpty())
            cues.back().end = start; // a short gap holds the last shape
        for (int k = 0; k < syl.shapes.size(); ++k) {
            const double from = std::max(syl.shapes[k].start, start);
            const double to
                = k + 1 < syl.shapes.size() ? std::max(syl.shapes[k + 1].start, from) : std::max(syl.end, from);
            push(from, to, syl.shapes[k].shape);
        }
        t = std::max(t, std::max(syl.end, start));
    }
    push(t, std::max(duration, t), MouthShape::M);
    return cues;
}

LipsyncResult lipsyncResult(const Script &script, const AlignResult &aligned, double duration)
{
    LipsyncResult r;
    r.language = script.language;
    r.duration = duration;
    for (int k = 0; k < script.syllables.size() && k < aligned.syllables.size(); ++k) {
        const ScriptSyllable &s = script.syllables[k];
        const AlignedSyllable &a = aligned.syllables[k];
        r.syllables.append(
            {s.text, s.pinyin, s.tone, a.start, a.end, a.confidence, keysOf(script, k, a.start, a.end, a.phonemes)});
    }
    r.mouthCues = mouthCues(r.syllables, duration);
    return r;
}

LipsyncResult lipsyncResult(const Script &script, const TtsResult &spoken)
{
    LipsyncResult r;
    r.language = script.language;
    r.duration = spoken.audio.duration();
    for (int k = 0; k < script.syllables.size() && k < spoken.units.size(); ++k) {
        const ScriptSyllable &s = script.syllables[k];
        const TtsUnit &u = spoken.units[k];
        r.syllables.append(
            {s.text, s.pinyin, s.tone, u.start, u.end, 1.0, keysOf(script, k, u.start, u.end, u.phonemes)});
    }
    r.mouthCues = mouthCues(r.syllables, r.duration);
    return r;
}

LipsyncOutcome lipsyncFiles(const QString &audioPath, const QString &scriptPath, Language language,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    const ScriptParse script = readScriptFile(scriptPath, language);
    markStage("script");
    if (!script.ok()) {
        LipsyncOutcome out;
        out.error = script.error;
        return out;
    }
    return lipsyncRecording(audioPath, script.script, scriptPath, progress, cancel);
}

LipsyncOutcome lipsyncRecording(const QString &audioPath, const Script &script, const QString &scriptName,
    const SpeechProgressFn &progress, const std::atomic_bool *cancel)
{
    LipsyncOutcome out;
    // The reference's first rendering does not depend on the recording: it is made on the
    // other core while the recording is decoded.
    const AlignOptions options;
    PaceProbe probe(script, options.reference);
    // The recording's features are computed while it is decoded: its samples are never held.
    SpeechFeatureStream features(cancel);
    features.useSecondCore();
    const AudioResult audio = streamAudio(
        audioPath, [&](const float *s, qsizetype n) { features.push(s, n); },
        [&](double f, const QString &stage) {
            if (progress)
                progress(0.2 * f, stage);
        },
        cancel);
    markStage("decoded");
    if (audio.status == AudioStatus::Cancelled) {
        out.status = LipsyncStatus::Cancelled;
        out.error = ScriptText::tr("cancelled");
        return out;
    }
    if (!audio.ok()) {
        out.error = audio.error;
        return out;
    }
    const AlignResult aligned = alignScript(
        features.finish(), probe, script, options,
        [&](double f, const QString &stage) {
            if (progress)
                progress(0.2 + 0.8 * f, stage);
        },
        cancel);
    markStage("aligned");
    switch (aligned.status) {
    case AlignStatus::Ok: break;
    case AlignStatus::Cancelled:
        out.status = LipsyncStatus::Cancelled;
        out.error = ScriptText::tr("cancelled");
        return out;
    case AlignStatus::CannotAlign:
        out.status = LipsyncStatus::CannotAlign;
        out.error = ScriptText::tr("%1 and %2 could not be aligned: %3").arg(audioPath, scriptName, aligned.error);
        return out;
    case AlignStatus::BadInput: out.error = withProblem(audioPath, aligned.error); return out;
    }
    out.status = LipsyncStatus::Ok;
    out.result = lipsyncResult(script, aligned, double(audio.sampleCount) / kSpeechSampleRate);
    return out;
}

QJsonObject lipsyncToJson(const LipsyncResult &result)
{
    QJsonArray syllables;
    for (const LipsyncSyllable &s : result.syllables) {
        QJsonArray shapes;
        for (const ShapeKey &k : s.shapes)
            shapes.append(QJsonObject {
                {QStringLiteral("shape"), mouthShapeName(k.shape)}, {QStringLiteral("start"), ms(k.start)}});
        QJsonObject o {{QStringLiteral("text"), s.text}, {QStringLiteral("pinyin"), s.pinyin},
            {QStringLiteral("start"), ms(s.start)}, {QStringLiteral("end"), ms(s.end)},
            {QStringLiteral("confidence"), std::round(s.confidence * 100) / 100}, {QStringLiteral("shapes"), shapes}};
        if (!s.pinyin.isEmpty())
            o.insert(QStringLiteral("tone"), s.tone);
        syllables.append(o);
    }
    QJsonArray cues;
    for (const MouthCue &c : result.mouthCues)
        cues.append(QJsonObject {{QStringLiteral("start"), ms(c.start)}, {QStringLiteral("end"), ms(c.end)},
            {QStringLiteral("shape"), mouthShapeName(c.shape)}});
    return QJsonObject {{QStringLiteral("format"), QStringLiteral("toonface.lipsync/1")},
        {QStringLiteral("language"), languageCode(result.language)}, {QStringLiteral("duration"), ms(result.duration)},
        {QStringLiteral("syllables"), syllables}, {QStringLiteral("mouthCues"), cues}};
}

QByteArray lipsyncToTsv(const LipsyncResult &result)
{
    QByteArray out;
    for (const MouthCue &c : result.mouthCues)
        out += QByteArray::number(ms(c.start), 'f', 3) + '\t' + mouthShapeName(c.shape).toLatin1() + '\n';
    return out;
}

} // namespace toonface
