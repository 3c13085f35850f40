#include "benchmark.h"

#include "face/averageface.h"
#include "io/imageio.h"
#include "io/project.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <random>

using namespace toonface;

namespace {

// A synthetic but realistically dense 10-minute timeline: speech at about 12 mouth keys a
// second with pauses, a blink every ~4 s, a few emotion clips and a head key every ~2 s.
Timeline tenMinuteTimeline()
{
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double duration = 600.0;

    Timeline timeline;
    QVector<MouthKey> mouth;
    for (double t = 0; t < duration;) {
        const double hold = unit(rng) < 0.02 ? 0.4 + unit(rng) : 1.0 / 12.0 * (0.5 + 0.6 * unit(rng));
        mouth.append(MouthKey {t, kAllMouthShapes[rng() % kAllMouthShapes.size()], 1.0, hold});
        t += hold;
    }
    timeline.setMouthKeys(mouth);
    QVector<BlinkEvent> blinks;
    for (double t = 1.0 + 2.0 * unit(rng); t < duration; t += 2.5 + 3.0 * unit(rng))
        blinks.append(BlinkEvent {t, 0.12 + 0.08 * unit(rng)});
    timeline.setBlinks(blinks);
    const Emotion emotions[] = {Emotion::Smile, Emotion::Sad, Emotion::Angry, Emotion::Surprise};
    for (int i = 0; i < 8; ++i) {
        const double start = 20.0 + i * 70.0 + 10.0 * unit(rng);
        timeline.addEmotionClip(
            EmotionClip {start, start + 5.0 + 20.0 * unit(rng), emotions[i % 4], 0.4 + 0.6 * unit(rng), 0.3, 0.5});
    }
    QVector<HeadKey> head;
    for (double t = 0; t < duration; t += 1.5 + unit(rng))
        head.append(HeadKey {t, 3.0 * (unit(rng) - 0.5), QPointF(0.05 * (unit(rng) - 0.5), 0.05 * (unit(rng) - 0.5)),
            1.0 + 0.02 * (unit(rng) - 0.5)});
    timeline.setHeadKeys(head);
    return timeline;
}

Project benchProject(const QString &dir)
{
    Project p;
    p.photoPath = dir + QStringLiteral("/photo.jpg");
    p.face = averageFace(QRectF(180.5, 220.25, 400.75, 480.125), QSize(960, 1280));
    p.style.components.insert(QStringLiteral("face"), {QColor(242, 201, 160), QColor(90, 59, 34), 1.5, true});
    p.style.components.insert(QStringLiteral("hair"), {QColor(51, 34, 26), QColor(), 0, true});
    p.layerPaths = {dir + QStringLiteral("/layers/hat.svg")};
    p.timeline = tenMinuteTimeline();
    AudioClip voice {dir + QStringLiteral("/voice.wav"), 0.0, 600.0};
    voice.script = QString(3000, QChar(0x4f60));
    voice.language = QStringLiteral("cmn");
    p.timeline.setAudioClips({voice});
    return p;
}

} // namespace

TOONFACE_BENCHMARK("io.project10min", [] {
    QTemporaryDir tmp;
    const Project project = benchProject(tmp.path());
    const QString file = tmp.filePath(QStringLiteral("talk.toonface"));
    QString error;
    bool ok = true;
    const double saveMs = bench::medianMs([&] { ok = saveProject(project, file, &error) && ok; });
    const double loadMs = bench::medianMs([&] { ok = loadProject(file, &error).has_value() && ok; });
    // Where the time goes: building the JSON tree, and turning it into text.
    const double toJsonMs = bench::medianMs([&] { ok = !projectToJson(project, tmp.path()).isEmpty() && ok; });
    const QJsonObject json = projectToJson(project, tmp.path());
    const double fromJsonMs
        = bench::medianMs([&] { ok = projectFromJson(json, tmp.path(), &error).has_value() && ok; });
    const double textMs = bench::medianMs([&] { ok = !QJsonDocument(json).toJson().isEmpty() && ok; });
    // The same bytes through a plain QFile: what the atomic save (temporary file, flush to disk,
    // rename) costs on top.
    const QByteArray text = QJsonDocument(json).toJson();
    const QString plain = tmp.filePath(QStringLiteral("plain.json"));
    const double plainWriteMs = bench::medianMs([&] {
        QFile f(plain);
        ok = f.open(QIODevice::WriteOnly) && f.write(text) == text.size() && ok;
    });
    const QJsonObject tracks = project.timeline.toJson();
    QJsonObject r;
    r.insert(QStringLiteral("saveMs"), saveMs);
    r.insert(QStringLiteral("loadMs"), loadMs);
    r.insert(QStringLiteral("projectToJsonMs"), toJsonMs);
    r.insert(QStringLiteral("projectFromJsonMs"), fromJsonMs);
    r.insert(QStringLiteral("jsonToTextMs"), textMs);
    r.insert(QStringLiteral("plainWriteMs"), plainWriteMs);
    r.insert(QStringLiteral("fileKB"), double(QFileInfo(file).size()) / 1024.0);
    r.insert(QStringLiteral("mouthKeys"), int(project.timeline.mouthKeys().size()));
    r.insert(QStringLiteral("blinks"), int(project.timeline.blinks().size()));
    r.insert(QStringLiteral("headKeys"), int(project.timeline.headKeys().size()));
    r.insert(QStringLiteral("ok"), ok);
    if (!ok)
        r.insert(QStringLiteral("error"), error);
    return r;
});

TOONFACE_BENCHMARK("io.loadPhoto", [] {
    const QString path = QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg");
    QJsonObject r;
    if (!QFileInfo::exists(path)) {
        r.insert(QStringLiteral("skipped"), QStringLiteral("grace_hopper.jpg is absent"));
        return r;
    }
    QString error;
    QSize size;
    const double ms = bench::medianMs([&] { size = loadPhoto(path, &error).size(); });
    r.insert(QStringLiteral("ms"), ms);
    r.insert(QStringLiteral("width"), size.width());
    r.insert(QStringLiteral("height"), size.height());
    return r;
});
