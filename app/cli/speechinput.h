#pragma once

#include "anim/timeline.h"
#include "speech/lipsync.h"

#include <QString>
#include <QVector>

namespace toonface::cli {

// Where the speech of an animation comes from: a recording with its script, or text to say.
struct SpeechRequest
{
    QString audioPath; // with scriptPath
    QString scriptPath;
    QString sayText; // or this, spoken by the built-in voice
    QString language; // "cmn", "en" or empty (detected from the script)
    QString workDir; // where a synthesized recording is written
    QString outputBase; // the file name (without folder and suffix) a synthesized recording takes
};

// The mouth track of the speech and the sound it goes with.
struct SpeechTrack
{
    QVector<MouthCue> cues;
    QVector<LipsyncSyllable> syllables;
    QString audioPath; // the recording, or the synthesized one
    double duration = 0;
    QString script;
    QString language;
};

// Reads or synthesizes the speech and times its mouth shapes. Returns ExitOk, or prints the
// error line and returns the contract's code (3 unreadable input, 5 cannot align).
int buildSpeechTrack(const SpeechRequest &request, SpeechTrack *out);

} // namespace toonface::cli
