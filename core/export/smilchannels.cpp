#include "export/smilchannels.h"

#include "anim/timelineevaluator.h"
#include "export/svgnumbers.h"
#include "face/emotion.h"
#include "face/facemodel.h"
#include "face/fapu.h"
#include "face/mouthshape.h"
#include "face/pointtable.h"
#include "face/pose.h"

#include <QMap>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace toonface::smil {

bool readChannel(const Channel &c, const QVector<FacePart> &parts, const QVector<double> &head, double *out)
{
    switch (c.kind) {
    case ChannelKind::Translate:
        out[0] = head[0];
        out[1] = head[1];
        return true;
    case ChannelKind::Rotate: out[0] = head[2]; return true;
    case ChannelKind::Scale: out[0] = head[3]; return true;
    default: break;
    }
    return readChannelText(c, parts[c.part].geometry.value(c.attribute).toLatin1(), out);
}

bool readChannelText(const Channel &c, QByteArrayView text, double *out)
{
    // Scratch space kept per thread: the export reads hundreds of thousands of attributes.
    thread_local QVector<double> numbers;
    thread_local QByteArray commands;
    numbers.clear();
    if (c.kind == ChannelKind::Path) {
        commands.clear();
        if (!parsePath(text, &numbers, &commands) || commands != c.commands)
            return false;
    } else {
        parseNumbers(text, &numbers);
    }
    if (numbers.size() != c.size)
        return false;
    std::copy(numbers.cbegin(), numbers.cend(), out);
    return true;
}

bool headNumbers(const SvgFace &svg, const HeadPose &head, QVector<double> *out)
{
    out->clear();
    parseNumbers(svg.headTransform(head).toLatin1(), out);
    return out->size() == 6;
}

Sampler::Sampler(const SvgFace &svg, const TimelineEvaluator &evaluator, const QVector<Channel> &channels,
    const QVector<FacePart> &parts)
    : m_svg(svg)
    , m_evaluator(evaluator)
    , m_channels(channels)
    , m_parts(parts)
    , m_still(svg.stillPartCount())
    , m_attribute(channels.size(), -1)
{
    for (const FacePart &p : parts)
        m_ids.append(p.id.toLatin1());
    const std::vector<SvgFace::PartGeometry> posed = svg.posedGeometry(evaluator.evaluate(0));
    m_posed = qsizetype(posed.size());
    for (qsizetype i = 0; i < channels.size(); ++i) {
        const Channel &c = channels[i];
        const qsizetype p = c.part - m_still;
        if (c.part < 0 || p < 0 || p >= m_posed)
            continue;
        const auto &attributes = posed[size_t(p)].attributes;
        for (size_t a = 0; a < attributes.size(); ++a) {
            if (c.attribute == QLatin1StringView(attributes[a].first))
                m_attribute[i] = int(a);
        }
    }
}

bool Sampler::sample(double t, const QVector<int> &which, double *out) const
{
    if (m_still + m_posed != m_parts.size())
        return false;
    const Pose pose = m_evaluator.evaluate(t);
    bool needHead = false;
    // The moving parts these channels read: only they (and those drawn with them) are drawn.
    QVector<QByteArray> ids;
    for (int c : which) {
        const int part = m_channels[c].part;
        if (part < 0)
            needHead = true;
        else if (part >= m_still && !ids.contains(m_ids[part]))
            ids.append(m_ids[part]);
    }
    std::vector<SvgFace::PartGeometry> posed;
    if (!ids.isEmpty())
        posed = m_svg.posedGeometry(pose, ids);
    QVector<double> head;
    if (needHead && !headNumbers(m_svg, pose.head, &head))
        return false;
    for (int i : which) {
        const Channel &c = m_channels[i];
        if (c.part < 0 || c.part < m_still) {
            if (!readChannel(c, m_parts, head, out))
                return false;
        } else {
            const QByteArray &id = m_ids[c.part];
            const auto part = std::find_if(posed.cbegin(), posed.cend(),
                [&](const SvgFace::PartGeometry &p) { return id == QByteArrayView(p.id); });
            const int a = m_attribute[i];
            // The same part and attribute as at time 0, or the structure changed.
            if (part == posed.cend() || a < 0 || size_t(a) >= part->attributes.size()
                || c.attribute != QLatin1StringView(part->attributes[size_t(a)].first)
                || !readChannelText(c, part->attributes[size_t(a)].second, out))
                return false;
        }
        out += c.size;
    }
    return true;
}

QVector<Channel> makeChannels(const QVector<FacePart> &parts, const QVector<double> &neutralHead, QRectF canvas)
{
    QVector<Channel> channels;
    for (qsizetype i = 0; i < parts.size(); ++i) {
        const FacePart &part = parts[i];
        for (auto it = part.geometry.cbegin(); it != part.geometry.cend(); ++it) {
            const QByteArray text = it.value().toLatin1();
            Channel c;
            c.part = int(i);
            c.attribute = it.key();
            QVector<double> numbers;
            if (it.key() == QLatin1StringView("d")) {
                if (!parsePath(text, &numbers, &c.commands))
                    continue;
                c.kind = ChannelKind::Path;
            } else {
                QByteArray letters;
                parseNumbers(text, &numbers, &letters);
                if (!letters.isEmpty() || numbers.isEmpty())
                    continue; // not geometry that can move (fill-rule, ...)
                c.kind = numbers.size() == 1 ? ChannelKind::Number : ChannelKind::Points;
            }
            c.size = int(numbers.size());
            c.base = numbers;
            channels.append(c);
        }
    }
    // The head turns and scales about its centre: an angle or scale error moves points by
    // up to the farthest corner's distance from it.
    const QPointF centre(neutralHead[0], neutralHead[1]);
    double reach = 1;
    for (const QPointF corner : {canvas.topLeft(), canvas.topRight(), canvas.bottomLeft(), canvas.bottomRight()})
        reach = std::max(reach, std::hypot(corner.x() - centre.x(), corner.y() - centre.y()));
    auto decimalsFor = [](double weight) { return std::clamp(int(std::ceil(std::log10(weight / 0.1))), 1, 8); };
    Channel translate;
    translate.kind = ChannelKind::Translate;
    translate.size = 2;
    Channel rotate;
    rotate.kind = ChannelKind::Rotate;
    rotate.size = 1;
    rotate.weight = reach * std::numbers::pi / 180.0;
    rotate.decimals = decimalsFor(rotate.weight);
    Channel scale;
    scale.kind = ChannelKind::Scale;
    scale.size = 1;
    scale.weight = reach;
    scale.decimals = decimalsFor(scale.weight);
    for (Channel *c : {&translate, &rotate, &scale}) {
        c->tracks = Track::Head;
        channels.append(*c);
    }
    return channels;
}

void findTracks(QVector<Channel> &channels, const SvgFace &svg, const Timeline &timeline, const MouthShapeSet &shapes)
{
    const FaceModel &face = svg.face();
    struct Probe
    {
        Track track;
        Pose pose;
    };
    QVector<Probe> probes;
    if (!timeline.mouthKeys().isEmpty()) {
        for (MouthShape s : kAllMouthShapes)
            probes.append({Track::Mouth, mouthPose(face, shapes, s)});
    }
    QVector<Emotion> emotions;
    for (const EmotionClip &clip : timeline.emotionClips()) {
        if (!emotions.contains(clip.emotion))
            emotions.append(clip.emotion);
    }
    for (Emotion e : emotions)
        probes.append({Track::Emotion, emotionPose(face, e, 1.0)});
    if (!timeline.blinks().isEmpty()) {
        for (double open : {0.0, 0.5}) {
            Pose p;
            p.leftEyeOpen = p.rightEyeOpen = open;
            probes.append({Track::Blink, p});
        }
    }
    if (!timeline.gazeKeys().isEmpty()) {
        const double es0 = face.fapu().es0;
        const auto &keys = timeline.gazeKeys();
        auto extreme = [&](auto less) { return std::min_element(keys.cbegin(), keys.cend(), less)->offsetEs0; };
        const QPointF offsets[] = {extreme([](auto &a, auto &b) { return a.offsetEs0.x() < b.offsetEs0.x(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.x() > b.offsetEs0.x(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.y() < b.offsetEs0.y(); }),
            extreme([](auto &a, auto &b) { return a.offsetEs0.y() > b.offsetEs0.y(); })};
        for (const QPointF &g : offsets) {
            Pose p;
            p.offset[pt::idx("3.6")] = g * es0;
            p.offset[pt::idx("3.5")] = g * es0;
            probes.append({Track::Gaze, p});
        }
    }
    if (!timeline.poseKeys().isEmpty()) {
        // Pose key frames: every point they displace at its extremes over the keys, left, right,
        // up and down (four probes however many keys there are).
        const double es0 = face.fapu().es0;
        QMap<int, std::array<double, 4>> extremes; // min x, max x, min y, max y in ES0
        for (const PoseKey &key : timeline.poseKeys()) {
            for (auto it = key.offsetsEs0.cbegin(); it != key.offsetsEs0.cend(); ++it) {
                const int index = pointIndex(it.key());
                if (index < 0)
                    continue;
                auto found = extremes.find(index);
                if (found == extremes.end())
                    found = extremes.insert(index, std::array<double, 4> {});
                std::array<double, 4> &e = found.value();
                e[0] = std::min(e[0], it.value().x());
                e[1] = std::max(e[1], it.value().x());
                e[2] = std::min(e[2], it.value().y());
                e[3] = std::max(e[3], it.value().y());
            }
        }
        for (int k = 0; k < 4; ++k) {
            Pose p;
            for (auto it = extremes.cbegin(); it != extremes.cend(); ++it)
                p.offset[it.key()] = (k < 2 ? QPointF(it.value()[k], 0) : QPointF(0, it.value()[k])) * es0;
            probes.append({Track::Pose, p});
        }
    }

    QVector<std::pair<Track, Pose>> bases {{Track(0), Pose {}}};
    for (const Probe &p : probes) {
        if (std::none_of(bases.cbegin(), bases.cend(), [&](const auto &b) { return b.first == p.track; }))
            bases.append({p.track, p.pose});
    }
    for (const auto &[baseTrack, base] : bases) {
        const QVector<FacePart> before = svg.parts(base);
        for (const Probe &probe : probes) {
            if (probe.track == baseTrack)
                continue;
            const QVector<FacePart> after = svg.parts(base + probe.pose);
            if (after.size() != before.size())
                continue;
            for (Channel &c : channels) {
                if (c.part >= 0
                    && after[c.part].geometry.value(c.attribute) != before[c.part].geometry.value(c.attribute))
                    c.tracks |= probe.track;
            }
        }
    }
}

void appendValue(QByteArray &out, const Channel &c, const qint64 *v)
{
    switch (c.kind) {
    case ChannelKind::Path: appendAbsolutePath(out, c.commands, v, c.decimals); break;
    case ChannelKind::Points:
    case ChannelKind::Translate:
        for (int j = 0; j < c.size; ++j) {
            if (j)
                out += j % 2 ? ',' : ' ';
            appendFixed(out, v[j], c.decimals);
        }
        break;
    default: appendFixed(out, v[0], c.decimals); break;
    }
}

} // namespace toonface::smil
