#pragma once

#include "export/animationexport.h"

#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <optional>

namespace toonface {

// A ready-made export for a place where talking faces are shared, with that place's limits.
struct ExportPreset
{
    QString name; // "telegram-sticker", "emoji", "slide-overlay"
    AnimationFormat format = AnimationFormat::WebM;
    int side = 512; // the frames' size in pixels (a square head frame)
    double maxSeconds = 0; // 0: any length
    qint64 maxBytes = 0; // 0: any size
    double maxFps = 0; // 0: any rate
    bool sound = true;
};

// The presets, in the order they are offered:
// - telegram-sticker: Telegram's video sticker: 512x512 WebM (VP9 with alpha), at most 3 s,
//   256 KB and 30 frames a second, no sound;
// - emoji: Telegram's custom emoji: 100x100 WebM with alpha, at most 3 s, 64 KB and 30 frames
//   a second, no sound;
// - slide-overlay: 1080x1080 WebM with alpha and sound, to lay over slides and video calls.
const QVector<ExportPreset> &exportPresets();
std::optional<ExportPreset> exportPresetNamed(const QString &name);
QStringList exportPresetNames();

// `request` made to follow `preset`: its format, size, head framing, frame rate (the
// timeline's, capped at the preset's), sound, and an Automatic background made transparent.
// The output path, start, duration and an explicit background stay as they are.
ExportRequest withPreset(ExportRequest request, const ExportPreset &preset);

// What stops `request` (already withPreset()) from meeting the preset before anything is
// drawn: a clip longer than it allows ("the clip is 5.20 s, the telegram-sticker preset allows
// 3 s: ..."), an output of another format, sound asked of a silent preset; empty when none.
QString presetProblem(const ExportRequest &request, const ExportPreset &preset);

// Exports `request` under `preset` (withPreset() applied here). With a size limit, lowers the
// quality (VP9's crf, step by step) until the file fits, and gives up with status OverLimit
// and a message saying by how much the smallest file is over. The frames are drawn once: the
// later tries encode the first one's kept frames again (the result's framesDrawn and
// encodings say so). The file appears only when it
// meets every limit; otherwise nothing is written (a file of the same name is kept as it was).
// Progress and cancel as exportAnimation().
ExportResult exportWithPreset(const ExportRequest &request, const ExportPreset &preset,
    const std::function<void(double)> &progress = {}, const std::atomic_bool *cancel = nullptr);

} // namespace toonface
