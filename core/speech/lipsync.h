#pragma once

#include "anim/timeline.h"
#include "speech/aligner.h"
#include "speech/audio.h"
#include "speech/progress.h"
#include "speech/script.h"
#include "speech/syllableshapes.h"
#include "speech/tts.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QVector>

namespace toonface {

// One spoken syllable (or English word) with its time and the mouth keys it makes.
struct LipsyncSyllable
{
    QString text;
    QString pinyin; // toneless; empty for English
    int tone = 0;
    double start = 0; // seconds
    double end = 0;
    double confidence = 1;
    QVector<ShapeKey> shapes; // Mandarin: face-model.md's fractions; English: phoneme times

    bool operator==(const LipsyncSyllable &) const = default;
};

struct LipsyncResult
{
    Language language = Language::Mandarin;
    double duration = 0; // seconds of audio
    QVector<LipsyncSyllable> syllables;
    QVector<MouthCue> mouthCues; // cover [0, duration] without gaps
};

// Silence longer than this returns the mouth to `m` (face-model.md: "a short hold").
inline constexpr double kSilenceHold = 0.15;

// The flat cues of `syllables` over [0, duration]: each key holds until the next one, a
// syllable's last key until the syllable ends; gaps up to kSilenceHold keep the last shape,
// longer ones (and the time before the first and after the last syllable) are `m`. Equal
// neighbours merge.
QVector<MouthCue> mouthCues(const QVector<LipsyncSyllable> &syllables, double duration);

// Timed syllables → the lip-sync result (shapes by language).
LipsyncResult lipsyncResult(const Script &script, const AlignResult &aligned, double duration);

// The result of synthesized speech, timed exactly by the synthesizer's events.
LipsyncResult lipsyncResult(const Script &script, const TtsResult &spoken);

enum class LipsyncStatus { Ok, BadInput, CannotAlign, Cancelled };

struct LipsyncOutcome
{
    LipsyncStatus status = LipsyncStatus::BadInput;
    QString error; // names the file and the problem when status != Ok
    LipsyncResult result;
    bool ok() const { return status == LipsyncStatus::Ok; }
};

// Reads `audioPath` and the UTF-8 script `scriptPath`, aligns them and turns the syllables
// into mouth shapes. Unreadable or invalid inputs are BadInput; audio and script that do not
// match, CannotAlign. Long work: progress from 0 to 1, cancel polled throughout.
LipsyncOutcome lipsyncFiles(const QString &audioPath, const QString &scriptPath, Language language = Language::Auto,
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// The same with the script already read: `scriptName` names it in errors (its file, or
// "the script"). Reads the sound of any file loadAudio() reads, a video's included.
LipsyncOutcome lipsyncRecording(const QString &audioPath, const Script &script, const QString &scriptName,
    const SpeechProgressFn &progress = {}, const std::atomic_bool *cancel = nullptr);

// JSON `toonface.lipsync/1`: {format, language, duration, syllables: [{text, pinyin, start,
// end, confidence, shapes: [{shape, start}]}], mouthCues: [{start, end, shape}]}, seconds
// rounded to the millisecond.
QJsonObject lipsyncToJson(const LipsyncResult &result);

// Rhubarb Lip Sync's TSV style: one "start<TAB>shape" line per cue.
QByteArray lipsyncToTsv(const LipsyncResult &result);

} // namespace toonface
