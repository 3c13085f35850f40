#include "export/bookvideo.h"

#include "i18n/coretext.h"
#include "media/audiofeed.h"
#include "speech/audio.h"

#include <QDir>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

// The pages' sound: speech keeps its sound below 12 kHz (the book's MP3 is at this rate too).
constexpr int kSoundRate = 24000;
// 320 pixels show the mouth's shapes clearly in a page's column; larger frames cost their
// area in drawing time on every frame of the book.
constexpr int kFrameSide = 320;

} // namespace

PageVideoWriter::PageVideoWriter(const BookRequest &request, const QString &folder)
    : m_request(request)
    , m_folder(folder)
{ }

PageVideoWriter::~PageVideoWriter() = default;

QSize PageVideoWriter::frameSize()
{
    return {kFrameSide, kFrameSide};
}

bool PageVideoWriter::openSound(const QString &soundPath, QString *error)
{
    m_feed = std::make_unique<av::AudioFeed>();
    m_soundPath = soundPath;
    m_at = 0;
    return m_feed->open(AudioSource::fromFile(soundPath), error) && m_feed->start(kSoundRate, error);
}

QString PageVideoWriter::write(const Timeline &timeline, qint64 beginMs, qint64 endMs, const std::atomic_bool *cancel,
    ExportStatus *status, QString *error)
{
    *status = ExportStatus::Failed;
    if (!m_feed) {
        *error = withProblem(m_request.outputPath, ExportText::tr("no sound to cut the page's video from"));
        return {};
    }
    // The page's stretch of the sound, read forward from where the last page ended.
    const qint64 begin = std::max(m_at, qint64(std::llround(double(beginMs) * kSoundRate / 1000.0)));
    const qint64 end = std::max(begin, qint64(std::llround(double(endMs) * kSoundRate / 1000.0)));
    Audio sound;
    sound.sampleRate = kSoundRate;
    QVector<float> skipped;
    while (m_at < begin) {
        skipped.resize(std::min<qint64>(begin - m_at, 1 << 16));
        if (!m_feed->read(skipped.data(), int(skipped.size()), error))
            return {};
        m_at += skipped.size();
    }
    sound.samples.resize(end - begin);
    if (!sound.samples.isEmpty() && !m_feed->read(sound.samples.data(), int(sound.samples.size()), error))
        return {};
    m_at = end;

    const QString wav = QDir(m_folder).filePath(QStringLiteral("page.wav"));
    if (!writeAudio(wav, sound, error))
        return {};
    ExportRequest r;
    r.format = AnimationFormat::Mp4;
    r.outputPath = QDir(m_folder).filePath(QStringLiteral("page.mp4"));
    r.size = kFrameSide;
    r.framing = ExportFraming::Head;
    r.face = m_request.face;
    r.style = m_request.style;
    r.mouthShapes = m_request.mouthShapes;
    r.layerFiles = m_request.layerFiles;
    r.timeline = timeline;
    // The sound sets the video's length: a page ending in a pause keeps it.
    r.timeline.setAudioClips({AudioClip {wav, 0.0, sound.duration()}});
    r.audioPath = wav;
    const ExportResult made = exportAnimation(r, {}, cancel);
    *status = made.status;
    if (!made.ok()) {
        *error = made.error;
        return {};
    }
    return r.outputPath;
}

} // namespace toonface
