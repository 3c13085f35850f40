#include "anim/timeline.h"

#include "face/pointtable.h"
#include "i18n/coretext.h"

#include <QJsonArray>
#include <QJsonValue>

#include <cmath>
#include <functional>

namespace toonface {

namespace {

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

// Reads fields of one JSON object, remembering the first problem as "<path>.<field>: <problem>".
class FieldReader
{
public:
    FieldReader(const QJsonObject &object, QString path, QString *error)
        : m_object(object)
        , m_path(std::move(path))
        , m_error(error)
    { }

    bool ok() const { return m_ok; }
    QString pathOf(const char *field) const { return m_path.isEmpty() ? key(field) : m_path + u'.' + key(field); }

    bool fail(const char *field, const QString &problem)
    {
        if (m_ok && m_error)
            *m_error = withProblem(pathOf(field), problem);
        m_ok = false;
        return false;
    }

    // A finite number; absent fields keep *out (or fail when required). `valid` checks the
    // value and returns the problem, or an empty string.
    bool number(const char *field, double *out, bool required, const std::function<QString(double)> &valid = {})
    {
        const QJsonValue v = m_object.value(key(field));
        if (v.isUndefined())
            return required ? fail(field, QStringLiteral("missing")) : m_ok;
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return fail(field, ProjectText::tr("expected a number"));
        if (valid) {
            const QString problem = valid(v.toDouble());
            if (!problem.isEmpty())
                return fail(field, problem);
        }
        *out = v.toDouble();
        return m_ok;
    }

    // A time in seconds: a number within the timeline's longest span either way
    // (Timeline::kMaxSeconds), so a key at 1e308 s or ten hours away is named, not drawn.
    bool seconds(const char *field, double *out, bool required, const std::function<QString(double)> &valid = {})
    {
        return number(field, out, required, [&valid](double v) {
            if (std::abs(v) > Timeline::kMaxSeconds)
                return ProjectText::tr("%1 s is beyond the longest timeline Toonface keeps (%2 hours)")
                    .arg(v, 0, 'g', 6)
                    .arg(Timeline::kMaxSeconds / 3600);
            return valid ? valid(v) : QString();
        });
    }

    bool string(const char *field, QString *out, bool required)
    {
        const QJsonValue v = m_object.value(key(field));
        if (v.isUndefined())
            return required ? fail(field, QStringLiteral("missing")) : m_ok;
        if (!v.isString())
            return fail(field, ProjectText::tr("expected a string"));
        *out = v.toString();
        return m_ok;
    }

private:
    QJsonObject m_object;
    QString m_path;
    QString *m_error;
    bool m_ok = true;
};

QString nonNegative(double v)
{
    return v < 0 ? ProjectText::tr("must not be negative") : QString();
}

QString positive(double v)
{
    return v <= 0 ? ProjectText::tr("must be positive") : QString();
}

QString unitInterval(double v)
{
    return v < 0 || v > 1 ? ProjectText::tr("must be between 0 and 1") : QString();
}

// Reads the array `field` of `json`, calling read(object, path) for each element; returns false
// after setting *error on the first problem.
bool readArray(const QJsonObject &json, const char *field, QString *error,
    const std::function<bool(const QJsonObject &, const QString &)> &read)
{
    const QJsonValue v = json.value(key(field));
    if (v.isUndefined())
        return true;
    if (!v.isArray()) {
        if (error)
            *error = ProjectText::tr("%1: expected an array").arg(key(field));
        return false;
    }
    const QJsonArray array = v.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = key(field) + u'[' + QString::number(i) + u']';
        if (!array[i].isObject()) {
            if (error)
                *error = ProjectText::tr("%1: expected an object").arg(path);
            return false;
        }
        if (!read(array[i].toObject(), path))
            return false;
    }
    return true;
}

QJsonObject pointFields(QJsonObject o, QPointF p)
{
    o.insert(QStringLiteral("x"), p.x());
    o.insert(QStringLiteral("y"), p.y());
    return o;
}

} // namespace

QJsonObject Timeline::toJson() const
{
    QJsonObject json;
    json.insert(QStringLiteral("version"), kJsonVersion);
    json.insert(QStringLiteral("fps"), m_frameRate);

    QJsonObject smoothing;
    smoothing.insert(QStringLiteral("minHold"), m_smoothing.minHold);
    smoothing.insert(QStringLiteral("coarticulation"), m_smoothing.coarticulation);
    smoothing.insert(QStringLiteral("silenceHold"), m_smoothing.silenceHold);
    json.insert(QStringLiteral("smoothing"), smoothing);

    // Defaults are left out of the many mouth keys to keep long timelines small.
    QJsonArray mouth;
    for (const MouthKey &k : m_mouth) {
        QJsonObject o;
        o.insert(QStringLiteral("time"), k.time);
        o.insert(QStringLiteral("shape"), mouthShapeName(k.shape));
        if (k.weight != 1.0)
            o.insert(QStringLiteral("weight"), k.weight);
        if (k.duration)
            o.insert(QStringLiteral("duration"), *k.duration);
        mouth.append(o);
    }
    json.insert(QStringLiteral("mouth"), mouth);

    QJsonArray emotion;
    for (const EmotionClip &c : m_emotion) {
        QJsonObject o;
        o.insert(QStringLiteral("start"), c.start);
        o.insert(QStringLiteral("end"), c.end);
        o.insert(QStringLiteral("emotion"), emotionName(c.emotion));
        o.insert(QStringLiteral("intensity"), c.intensity);
        o.insert(QStringLiteral("fadeIn"), c.fadeIn);
        o.insert(QStringLiteral("fadeOut"), c.fadeOut);
        emotion.append(o);
    }
    json.insert(QStringLiteral("emotion"), emotion);

    QJsonArray blink;
    for (const BlinkEvent &b : m_blinks) {
        QJsonObject o;
        o.insert(QStringLiteral("time"), b.time);
        o.insert(QStringLiteral("duration"), b.duration);
        blink.append(o);
    }
    json.insert(QStringLiteral("blink"), blink);

    QJsonArray gaze;
    for (const GazeKey &g : m_gaze) {
        QJsonObject o;
        o.insert(QStringLiteral("time"), g.time);
        gaze.append(pointFields(o, g.offsetEs0));
    }
    json.insert(QStringLiteral("gaze"), gaze);

    QJsonArray head;
    for (const HeadKey &h : m_head) {
        QJsonObject o;
        o.insert(QStringLiteral("time"), h.time);
        o.insert(QStringLiteral("rotation"), h.rotationDeg);
        o = pointFields(o, h.translationEs0);
        o.insert(QStringLiteral("scale"), h.scale);
        head.append(o);
    }
    json.insert(QStringLiteral("head"), head);

    QJsonArray pose;
    for (const PoseKey &k : m_pose) {
        QJsonObject offsets;
        for (auto it = k.offsetsEs0.cbegin(); it != k.offsetsEs0.cend(); ++it)
            offsets.insert(it.key(), QJsonArray {it.value().x(), it.value().y()});
        QJsonObject o;
        o.insert(QStringLiteral("time"), k.time);
        o.insert(QStringLiteral("offsets"), offsets);
        pose.append(o);
    }
    json.insert(QStringLiteral("pose"), pose);

    if (!m_audio.isEmpty()) {
        QJsonArray audio;
        for (const AudioClip &clip : m_audio) {
            QJsonObject o;
            o.insert(QStringLiteral("path"), clip.path);
            o.insert(QStringLiteral("offset"), clip.offset);
            o.insert(QStringLiteral("duration"), clip.duration);
            o.insert(QStringLiteral("trimIn"), clip.trimIn);
            o.insert(QStringLiteral("trimOut"), clip.trimOut);
            o.insert(QStringLiteral("script"), clip.script);
            o.insert(QStringLiteral("language"), clip.language);
            audio.append(o);
        }
        json.insert(QStringLiteral("audio"), audio);
    }
    if (m_video) {
        QJsonObject video;
        video.insert(QStringLiteral("path"), m_video->path);
        video.insert(QStringLiteral("offset"), m_video->offset);
        video.insert(QStringLiteral("duration"), m_video->duration);
        video.insert(QStringLiteral("fps"), m_video->fps);
        json.insert(QStringLiteral("video"), video);
    }
    return json;
}

std::optional<Timeline> Timeline::fromJson(const QJsonObject &json, QString *error)
{
    Timeline timeline;
    FieldReader top(json, QString(), error);
    double version = kJsonVersion;
    if (!top.number("version", &version, false))
        return std::nullopt;
    if (version != std::floor(version) || version < 1) {
        top.fail("version", ProjectText::tr("expected a positive integer"));
        return std::nullopt;
    }
    if (version > kJsonVersion) {
        top.fail(
            "version", ProjectText::tr("%1 is newer than this Toonface reads (%2)").arg(version).arg(kJsonVersion));
        return std::nullopt;
    }
    if (!top.number("fps", &timeline.m_frameRate, false, positive))
        return std::nullopt;

    const QJsonValue smoothingValue = json.value(QStringLiteral("smoothing"));
    if (!smoothingValue.isUndefined()) {
        if (!smoothingValue.isObject()) {
            if (error)
                *error = ProjectText::tr("smoothing: expected an object");
            return std::nullopt;
        }
        FieldReader r(smoothingValue.toObject(), QStringLiteral("smoothing"), error);
        MouthSmoothing &s = timeline.m_smoothing;
        if (!r.number("minHold", &s.minHold, false, nonNegative)
            || !r.number("coarticulation", &s.coarticulation, false, nonNegative)
            || !r.number("silenceHold", &s.silenceHold, false, nonNegative))
            return std::nullopt;
    }

    const bool tracksOk = readArray(json, "mouth", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        MouthKey k;
        QString shape;
        if (!r.seconds("time", &k.time, true) || !r.string("shape", &shape, true))
            return false;
        const auto parsed = mouthShapeFromName(shape);
        if (!parsed)
            return r.fail("shape", ProjectText::tr("unknown mouth shape '%1'").arg(shape));
        k.shape = *parsed;
        double duration = 0;
        const bool hasDuration = o.contains(QStringLiteral("duration"));
        if (!r.number("weight", &k.weight, false, nonNegative) || !r.seconds("duration", &duration, false, nonNegative))
            return false;
        if (hasDuration)
            k.duration = duration;
        timeline.m_mouth.append(k);
        return true;
    }) && readArray(json, "emotion", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        EmotionClip c;
        QString name;
        if (!r.seconds("start", &c.start, true) || !r.seconds("end", &c.end, true))
            return false;
        if (c.end < c.start)
            return r.fail("end", ProjectText::tr("must not be before start"));
        if (!r.string("emotion", &name, true))
            return false;
        const auto parsed = emotionFromName(name);
        if (!parsed)
            return r.fail("emotion", ProjectText::tr("unknown emotion '%1'").arg(name));
        c.emotion = *parsed;
        if (!r.number("intensity", &c.intensity, false, unitInterval)
            || !r.number("fadeIn", &c.fadeIn, false, nonNegative)
            || !r.number("fadeOut", &c.fadeOut, false, nonNegative))
            return false;
        timeline.m_emotion.append(c);
        return true;
    }) && readArray(json, "blink", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        BlinkEvent b;
        if (!r.seconds("time", &b.time, true) || !r.seconds("duration", &b.duration, false, positive))
            return false;
        timeline.m_blinks.append(b);
        return true;
    }) && readArray(json, "gaze", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        GazeKey g;
        double x = 0, y = 0;
        if (!r.seconds("time", &g.time, true) || !r.number("x", &x, false) || !r.number("y", &y, false))
            return false;
        g.offsetEs0 = {x, y};
        timeline.m_gaze.append(g);
        return true;
    }) && readArray(json, "head", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        HeadKey h;
        double x = 0, y = 0;
        if (!r.seconds("time", &h.time, true) || !r.number("rotation", &h.rotationDeg, false)
            || !r.number("x", &x, false) || !r.number("y", &y, false) || !r.number("scale", &h.scale, false, positive))
            return false;
        h.translationEs0 = {x, y};
        timeline.m_head.append(h);
        return true;
    }) && readArray(json, "pose", error, [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        PoseKey k;
        if (!r.seconds("time", &k.time, true))
            return false;
        const QJsonValue offsets = o.value(QStringLiteral("offsets"));
        if (offsets.isUndefined()) {
            timeline.m_pose.append(k);
            return true;
        }
        if (!offsets.isObject())
            return r.fail("offsets", ProjectText::tr("expected an object"));
        const QJsonObject map = offsets.toObject();
        for (auto it = map.constBegin(); it != map.constEnd(); ++it) {
            const QString where = r.pathOf("offsets") + u'.' + it.key();
            auto failWith = [&](const QString &problem) {
                if (error)
                    *error = withProblem(where, problem);
                return false;
            };
            if (pointIndex(it.key()) < 0)
                return failWith(ProjectText::tr("unknown point ID"));
            const QJsonArray xy = it.value().toArray();
            if (!it.value().isArray() || xy.size() != 2 || !xy[0].isDouble() || !xy[1].isDouble()
                || !std::isfinite(xy[0].toDouble()) || !std::isfinite(xy[1].toDouble()))
                return failWith(ProjectText::tr("expected [dx, dy], two numbers"));
            k.offsetsEs0.insert(it.key(), QPointF(xy[0].toDouble(), xy[1].toDouble()));
        }
        timeline.m_pose.append(k);
        return true;
    });
    if (!tracksOk)
        return std::nullopt;

    // Version 1 held one clip as an object; version 2 a track of clips.
    auto readClip = [&](const QJsonObject &o, const QString &path) {
        FieldReader r(o, path, error);
        AudioClip clip;
        if (!r.string("path", &clip.path, true) || !r.seconds("offset", &clip.offset, false)
            || !r.seconds("duration", &clip.duration, false, nonNegative)
            || !r.seconds("trimIn", &clip.trimIn, false, nonNegative)
            || !r.seconds("trimOut", &clip.trimOut, false, nonNegative) || !r.string("script", &clip.script, false)
            || !r.string("language", &clip.language, false))
            return false;
        if (clip.duration > 0 && clip.trimIn + clip.trimOut > clip.duration)
            return r.fail("trimOut", ProjectText::tr("the trims are longer than the recording"));
        if (std::abs(clip.offset + clip.duration) > Timeline::kMaxSeconds)
            return r.fail("duration",
                ProjectText::tr("the clip ends beyond the longest timeline Toonface keeps (%1 hours)")
                    .arg(Timeline::kMaxSeconds / 3600));
        if (!clip.language.isEmpty() && clip.language != QLatin1StringView("cmn")
            && clip.language != QLatin1StringView("en"))
            return r.fail("language", ProjectText::tr("expected \"cmn\", \"en\" or \"\""));
        timeline.m_audio.append(clip);
        return true;
    };
    const QJsonValue audioValue = json.value(QStringLiteral("audio"));
    if (audioValue.isObject()) {
        if (!readClip(audioValue.toObject(), QStringLiteral("audio")))
            return std::nullopt;
    } else if (audioValue.isArray()) {
        if (!readArray(json, "audio", error, readClip))
            return std::nullopt;
    } else if (!audioValue.isUndefined() && !audioValue.isNull()) {
        if (error)
            *error = ProjectText::tr("audio: expected an array of clips");
        return std::nullopt;
    }

    const QJsonValue videoValue = json.value(QStringLiteral("video"));
    if (!videoValue.isUndefined() && !videoValue.isNull()) {
        if (!videoValue.isObject()) {
            if (error)
                *error = ProjectText::tr("video: expected an object");
            return std::nullopt;
        }
        FieldReader r(videoValue.toObject(), QStringLiteral("video"), error);
        VideoClip clip;
        if (!r.string("path", &clip.path, true) || !r.seconds("offset", &clip.offset, false)
            || !r.seconds("duration", &clip.duration, false, nonNegative)
            || !r.number("fps", &clip.fps, false, nonNegative))
            return std::nullopt;
        timeline.m_video = clip;
    }

    // Files written by hand may list keys out of order; the tracks keep them sorted.
    timeline.setMouthKeys(timeline.m_mouth);
    timeline.setEmotionClips(timeline.m_emotion);
    timeline.setBlinks(timeline.m_blinks);
    timeline.setGazeKeys(timeline.m_gaze);
    timeline.setHeadKeys(timeline.m_head);
    timeline.setPoseKeys(timeline.m_pose);
    timeline.setAudioClips(timeline.m_audio);
    return timeline;
}

} // namespace toonface
