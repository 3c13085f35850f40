// Copy and paste of timeline items (declared in timelineedits.h): the selected items as a
// Timeline of their own, shifted to start at 0, written by Timeline::toJson.
#include "timeline/timelineedits.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

const QString kFormat = QStringLiteral("toonface.timeline-items/1");

template<class T, class Time>
QVector<T> shifted(const QVector<T> &items, double dt, Time time)
{
    QVector<T> out = items;
    for (T &item : out)
        time(item) += dt;
    return out;
}

// The index of each of `added` in `all` (the first unclaimed equal entry).
template<class T>
QVector<int> indicesOf(const QVector<T> &all, const QVector<T> &added)
{
    QVector<int> out;
    QVector<bool> taken(all.size(), false);
    for (const T &a : added)
        for (qsizetype i = 0; i < all.size(); ++i)
            if (!taken[i] && all[i] == a) {
                taken[i] = true;
                out.append(int(i));
                break;
            }
    return out;
}

} // namespace

QJsonObject copyItems(const Animation &animation, const Selection &selection)
{
    const std::optional<Span> range = selectionRange(animation, selection);
    if (!range)
        return {};
    const double origin = range->start;
    const Timeline &tl = animation.timeline;
    Timeline copy;
    copy.setFrameRate(tl.frameRate());
    const QVector<Span> cues = itemSpans(animation, ItemKind::Mouth);
    for (int i : selection.indices(ItemKind::Mouth)) {
        MouthKey k = tl.mouthKeys()[i];
        k.time -= origin;
        k.duration = cues[i].end - cues[i].start; // held as long as it was, whatever follows
        copy.addMouthKey(k);
    }
    for (int i : selection.indices(ItemKind::Emotion)) {
        EmotionClip c = tl.emotionClips()[i];
        c.start -= origin;
        c.end -= origin;
        copy.addEmotionClip(c);
    }
    for (int i : selection.indices(ItemKind::Blink)) {
        BlinkEvent b = tl.blinks()[i];
        b.time -= origin;
        copy.addBlink(b);
    }
    for (int i : selection.indices(ItemKind::Head)) {
        HeadKey k = tl.headKeys()[i];
        k.time -= origin;
        copy.addHeadKey(k);
    }
    for (int i : selection.indices(ItemKind::Gaze)) {
        GazeKey k = tl.gazeKeys()[i];
        k.time -= origin;
        copy.addGazeKey(k);
    }
    for (int i : selection.indices(ItemKind::Pose)) {
        PoseKey k = tl.poseKeys()[i];
        k.time -= origin;
        copy.addPoseKey(k);
    }
    if (copy.mouthKeys().isEmpty() && copy.emotionClips().isEmpty() && copy.blinks().isEmpty()
        && copy.headKeys().isEmpty() && copy.gazeKeys().isEmpty() && copy.poseKeys().isEmpty())
        return {};
    return QJsonObject {{QStringLiteral("format"), kFormat}, {QStringLiteral("timeline"), copy.toJson()}};
}

std::optional<Animation> pasteItems(
    const Animation &animation, const QJsonObject &items, double time, QString *error, Selection *pasted)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (items.value(QStringLiteral("format")).toString() != kFormat)
        return fail(QCoreApplication::translate("toonface::TimelineEdits", "the clipboard holds no timeline items"));
    QString why;
    const std::optional<Timeline> copy = Timeline::fromJson(items.value(QStringLiteral("timeline")).toObject(), &why);
    if (!copy)
        return fail(
            QCoreApplication::translate("toonface::TimelineEdits", "the clipboard's timeline items are damaged: %1")
                .arg(why));
    time = std::max(0.0, time);

    Animation out = animation;
    Timeline &tl = out.timeline;
    const QVector<MouthKey> mouth = shifted(copy->mouthKeys(), time, [](MouthKey &k) -> double & { return k.time; });
    if (!mouth.isEmpty()) {
        const double from = mouth.first().time;
        double to = from;
        for (const MouthKey &k : mouth)
            to = std::max(to, k.time + k.duration.value_or(0.0));
        const QVector<Span> spans = itemSpans(animation, ItemKind::Mouth);
        QVector<MouthKey> keys;
        for (qsizetype i = 0; i < tl.mouthKeys().size(); ++i) {
            MouthKey k = tl.mouthKeys()[i];
            if (k.time >= from && k.time < to)
                continue;
            if (k.time < from && spans[i].end > from)
                k.duration = from - k.time;
            keys.append(k);
        }
        // The cue that held over the pasted range's end resumes there.
        for (qsizetype i = 0; i < spans.size(); ++i)
            if (tl.mouthKeys()[i].time < to && spans[i].end > to && tl.mouthKeys()[i].time >= from)
                keys.append({to, tl.mouthKeys()[i].shape, tl.mouthKeys()[i].weight, spans[i].end - to});
        keys += mouth;
        tl.setMouthKeys(keys);
    }
    QVector<EmotionClip> clips = copy->emotionClips();
    for (EmotionClip &c : clips) {
        c.start += time;
        c.end += time;
        tl.addEmotionClip(c);
    }
    const QVector<BlinkEvent> blinks = shifted(copy->blinks(), time, [](BlinkEvent &b) -> double & { return b.time; });
    for (const BlinkEvent &b : blinks)
        tl.addBlink(b);
    const QVector<HeadKey> head = shifted(copy->headKeys(), time, [](HeadKey &k) -> double & { return k.time; });
    for (const HeadKey &k : head)
        tl.addHeadKey(k);
    const QVector<GazeKey> gaze = shifted(copy->gazeKeys(), time, [](GazeKey &k) -> double & { return k.time; });
    for (const GazeKey &k : gaze)
        tl.addGazeKey(k);
    const QVector<PoseKey> pose = shifted(copy->poseKeys(), time, [](PoseKey &k) -> double & { return k.time; });
    for (const PoseKey &k : pose)
        tl.addPoseKey(k);

    if (pasted) {
        pasted->clear();
        for (int i : indicesOf(tl.mouthKeys(), mouth))
            pasted->insert({ItemKind::Mouth, i});
        for (int i : indicesOf(tl.emotionClips(), clips))
            pasted->insert({ItemKind::Emotion, i});
        for (int i : indicesOf(tl.blinks(), blinks))
            pasted->insert({ItemKind::Blink, i});
        for (int i : indicesOf(tl.headKeys(), head))
            pasted->insert({ItemKind::Head, i});
        for (int i : indicesOf(tl.gazeKeys(), gaze))
            pasted->insert({ItemKind::Gaze, i});
        for (int i : indicesOf(tl.poseKeys(), pose))
            pasted->insert({ItemKind::Pose, i});
    }
    return out;
}

} // namespace toonface
