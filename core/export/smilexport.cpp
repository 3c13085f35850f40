#include "export/smilexport.h"

#include "anim/timeline.h"
#include "anim/timelineevaluator.h"
#include "export/smilaudio.h"
#include "export/smilchannels.h"
#include "export/smilhidden.h"
#include "export/smilkeys.h"
#include "export/smilreduce.h"
#include "export/smilscale.h"
#include "export/smilutil.h"
#include "export/svgnumbers.h"
#include "export/svgxml.h"
#include "face/facemodel.h"
#include "face/pose.h"
#include "i18n/coretext.h"
#include "render/svgface.h"

#include <QHash>
#include <QMap>
#include <QSet>

#include <algorithm>
#include <functional>

namespace toonface {

using namespace smil;

namespace {

void appendTiming(QByteArray &out, const std::optional<Timing> &timing)
{
    if (!timing) {
        out += "0 0 1 1";
        return;
    }
    const qint64 y1 = quantize(timing->y1, 3);
    const qint64 y2 = quantize(timing->y2, 3);
    if (timing->thirds() && y1 == 333 && y2 == 667) {
        out += "0 0 1 1";
        return;
    }
    appendFixed(out, quantize(timing->x1, 3), 3);
    out += ' ';
    appendFixed(out, y1, 3);
    out += ' ';
    appendFixed(out, quantize(timing->x2, 3), 3);
    out += ' ';
    appendFixed(out, y2, 3);
}

bool moves(const ChannelKeys &k)
{
    return k.times.size() > 2 || (k.timings.size() == 1 && k.timings.first());
}

// The animation element of one channel's keys, or an empty array when it never moves.
QByteArray animationElement(const Channel &c, const ChannelKeys &k, const Grid &grid, const QByteArray &dur)
{
    QByteArray out;
    const bool head = c.part < 0;
    if (!moves(k) && !head)
        return out;
    if (head) {
        out += "<animateTransform attributeName=\"transform\" type=\"";
        out += c.kind == ChannelKind::Translate ? "translate\" additive=\"replace\""
            : c.kind == ChannelKind::Rotate     ? "rotate\" additive=\"sum\""
                                                : "scale\" additive=\"sum\"";
    } else {
        out += "<animate attributeName=\"" + c.attribute.toLatin1() + "\" additive=\"sum\"";
    }
    out += " dur=\"" + dur + "\" fill=\"freeze\"";
    if (!moves(k)) {
        out += " values=\"";
        appendValue(out, c, k.values.constData());
        out += "\"/>";
        return out;
    }
    out += " calcMode=\"spline\" keyTimes=\"";
    for (qsizetype i = 0; i < k.times.size(); ++i) {
        if (i)
            out += ';';
        appendFixed(out, k.times[i], grid.digits);
    }
    out += "\" keySplines=\"";
    for (qsizetype i = 0; i < k.timings.size(); ++i) {
        if (i)
            out += ';';
        appendTiming(out, k.timings[i]);
    }
    out += "\" values=\"";
    for (qsizetype i = 0; i < k.times.size(); ++i) {
        if (i)
            out += ';';
        appendValue(out, c, k.values.constData() + i * c.size);
    }
    out += "\"/>";
    return out;
}

// ---- putting it together ----

struct Drawing
{
    SvgFace svg;
    XmlNode document; // SvgFace::svg() at time 0
    QVector<FacePart> parts; // at time 0
    QVector<Channel> channels;
    QSet<int> inFifths; // parts drawn in fifths of a pixel where they move (smilscale.h)
};

bool prepareDrawing(const Timeline &timeline, const MouthShapeSet &shapes, const TimelineEvaluator &evaluator,
    const AnimationExportOptions &options, Drawing *d, QString *error)
{
    for (const QString &file : options.layerFiles) {
        if (!d->svg.addLayerFile(file, error))
            return false;
    }
    const Pose start = evaluator.evaluate(0);
    if (!parseXml(d->svg.svg(start), &d->document, error))
        return false;
    d->parts = d->svg.parts(start);
    QVector<double> neutralHead;
    if (!headNumbers(d->svg, HeadPose {}, &neutralHead)) {
        *error = ExportText::tr("unexpected head transform '%1'").arg(d->svg.headTransform(HeadPose {}));
        return false;
    }
    d->channels = makeChannels(d->parts, neutralHead, viewBoxOf(d->document));
    // Their values are whole fifths of a pixel: rounded so from the start (the keys' values in
    // tenths, every other one).
    d->inFifths = partsInFifths(d->document, d->parts, d->channels);
    for (Channel &c : d->channels) {
        if (d->inFifths.contains(c.part)) {
            Q_ASSERT(c.decimals == 1);
            c.grain = 10 / kUnitsPerPixel;
        }
    }
    findTracks(d->channels, d->svg, timeline, shapes);
    if (timeline.headKeys().isEmpty()) {
        for (Channel &c : d->channels) {
            if (c.part < 0)
                c.tracks = {};
        }
    }
    return true;
}

// The Smil-mode document. `standalone`: with XML declaration, metadata and player script.
bool smilDocument(const Drawing &d, const TimelineEvaluator &evaluator, const Timeline &timeline,
    const SmilAudio &audio, bool standalone, const AnimationExportOptions &options, QByteArray *out, QString *error)
{
    const double duration = evaluator.duration();
    const Grid grid(duration);
    const QByteArray dur = seconds(duration);
    const Sampler sampler(d.svg, evaluator, d.channels, d.parts);

    // Channels moved by the same tracks start from the same key times and share their samples.
    QVector<Tracks> groups;
    for (const Channel &c : d.channels) {
        if (c.tracks && !groups.contains(c.tracks))
            groups.append(c.tracks);
    }
    QVector<ChannelKeys> keys;
    if (duration > 0) {
        for (qsizetype g = 0; g < groups.size(); ++g) {
            QVector<int> which;
            for (qsizetype c = 0; c < d.channels.size(); ++c) {
                if (d.channels[c].tracks == groups[g])
                    which.append(int(c));
            }
            if (!buildGroup(which, d.channels, sampler, evaluator, grid, options, &keys, error))
                return false;
            report(options, 0.9 * double(g + 1) / double(groups.size()));
        }
        // The radii first: where a circle hides follows from its radius' keys as written; its
        // position's keys there go before the reduction, which then has fewer to look at.
        auto reduce = [&](bool radii) {
            forEachParallel(keys.size(), [&](qsizetype i) {
                if (isRadius(d.channels[keys[i].channel]) == radii)
                    reduceKeys(d.channels[keys[i].channel], options.reduction, &keys[i]);
            });
        };
        reduce(true);
        dropHiddenKeys(d.channels, keys);
        reduce(false);
    }

    // The moving parts drawn in fifths of a pixel, their values whole numbers (smilscale.h).
    XmlNode document = d.document;
    QSet<int> inFifths;
    for (const ChannelKeys &k : keys) {
        if (d.inFifths.contains(d.channels[k.channel].part) && moves(k))
            inFifths.insert(d.channels[k.channel].part);
    }
    writeInFifths(document, d.parts, d.channels, inFifths);

    QHash<QByteArray, QByteArray> animations; // element id -> its animation elements
    QByteArray head;
    bool headMoves = false;
    for (const ChannelKeys &k : keys) {
        const Channel &c = d.channels[k.channel];
        QByteArray element;
        if (inFifths.contains(c.part)) {
            // Tenths of a pixel, every other one: whole fifths.
            Channel fifths = c;
            fifths.decimals = 0;
            ChannelKeys whole = k;
            for (qint64 &v : whole.values)
                v /= c.grain;
            element = animationElement(fifths, whole, grid, dur);
        } else {
            element = animationElement(c, k, grid, dur);
        }
        if (c.part < 0) {
            head += element;
            headMoves = headMoves || moves(k);
        } else if (!element.isEmpty()) {
            animations[d.parts[c.part].id.toLatin1()] += element;
        }
    }
    if (headMoves) {
        QVector<double> neutral;
        headNumbers(d.svg, HeadPose {}, &neutral);
        head += "<animateTransform attributeName=\"transform\" type=\"translate\" additive=\"sum\" dur=\"" + dur
            + "\" fill=\"freeze\" values=\"";
        appendFixed(head, quantize(neutral[4], 2), 2);
        head += ',';
        appendFixed(head, quantize(neutral[5], 2), 2);
        head += "\"/>";
    } else {
        head.clear();
    }

    const QRectF canvas = viewBoxOf(d.document);
    const bool withPlayer = standalone && !audio.uri.isEmpty() && duration > 0;
    if (standalone)
        *out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    const XmlNode *root = &document;
    writeXml(*out, *root, [&](const XmlNode &n, QByteArray *first, QByteArray *last) {
        if (&n == root) {
            if (standalone)
                *first += metadata(audio, duration, timeline.frameRate());
            if (withPlayer)
                *last += playerScript(canvas);
            return;
        }
        const QByteArray id = n.attribute("id");
        if (id.isEmpty())
            return;
        if (id == "head") {
            *first += head;
            return;
        }
        if (const auto it = animations.constFind(id); it != animations.constEnd())
            *first += *it;
    });
    *out += '\n';
    return true;
}

// The Frames-mode document.
bool framesDocument(const Drawing &d, const TimelineEvaluator &evaluator, const Timeline &timeline,
    const SmilAudio &audio, const AnimationExportOptions &options, QByteArray *out, QString *error)
{
    const double fps = timeline.frameRate();
    const int frames = std::max(1, timeline.frameCount());
    const XmlNode *head = findById(d.document, "head");
    if (!head) {
        *error = ExportText::tr("the drawing has no head group");
        return false;
    }
    QHash<QByteArray, int> partOf;
    for (qsizetype i = 0; i < d.parts.size(); ++i)
        partOf.insert(d.parts[i].id.toLatin1(), int(i));
    QVector<bool> moving(d.parts.size(), false);
    bool headMoves = false;
    for (const Channel &c : d.channels) {
        if (c.tracks && c.part >= 0)
            moving[c.part] = true;
        headMoves = headMoves || (c.part < 0 && c.tracks);
    }
    auto isMoving = [&](const QByteArray &id) {
        const auto it = partOf.constFind(id);
        return it != partOf.constEnd() && moving[*it];
    };

    // Clip paths of moving parts are repeated in each frame (their ids suffixed); the others
    // stay in <defs>.
    QMap<QByteArray, QByteArray> clipTarget; // clip id -> the moving element it uses
    QByteArray defs;
    if (const XmlNode *original = [&]() -> const XmlNode * {
            for (const XmlNode &c : d.document.children) {
                if (c.name == "defs")
                    return &c;
            }
            return nullptr;
        }()) {
        for (const XmlNode &clip : original->children) {
            QByteArray target;
            for (const XmlNode &use : clip.children) {
                if (use.name == "use")
                    target = use.attribute("xlink:href").mid(1);
            }
            if (clip.name == "clipPath" && isMoving(target))
                clipTarget.insert(clip.attribute("id"), target);
            else
                writeXml(defs, clip, {});
        }
    }

    // The elements of the head group in drawing order; runs of parts that never move are
    // drawn once in <defs> and used by every frame.
    struct Item
    {
        const XmlNode *node; // a moving part, or null for a shared run
        int run = -1;
    };
    QVector<Item> items;
    int runs = 0;
    bool inRun = false;
    std::function<void(const XmlNode &)> collect = [&](const XmlNode &n) {
        for (const XmlNode &c : n.children) {
            if (c.name.isEmpty())
                continue;
            if (c.name == "g" && !partOf.contains(c.attribute("id"))) {
                collect(c);
                continue;
            }
            if (isMoving(c.attribute("id"))) {
                items.append({&c});
                inRun = false;
                continue;
            }
            if (!inRun) {
                defs += "<g id=\"tf-shared-" + QByteArray::number(runs) + "\">";
                items.append({nullptr, runs++});
                inRun = true;
            } else {
                defs.chop(4); // reopen the run's group
            }
            writeXml(defs, c, {});
            defs += "</g>";
        }
    };
    collect(*head);

    *out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    appendStartTag(*out, d.document, false);
    *out += metadata(audio, evaluator.duration(), fps);
    *out += "<defs>" + defs + "</defs>\n";
    // What lies under the head (neck and shoulders, the user's layers behind the face), as it was.
    for (const XmlNode &c : d.document.children) {
        if (&c == head)
            break;
        if (!c.name.isEmpty() && c.name != "defs")
            writeXml(*out, c, {});
    }
    XmlNode outer = *head;
    outer.children.clear();
    std::erase_if(
        outer.attributes, [&](const auto &a) { return a.first == "id" || (headMoves && a.first == "transform"); });
    appendStartTag(*out, outer, false);
    *out += '\n';

    const QByteArray frameDur = seconds(1.0 / fps);
    auto frameText = [&](int i) {
        const Pose pose = evaluator.evaluate(i / fps);
        const QVector<FacePart> parts = d.svg.parts(pose);
        const QByteArray suffix = "-f" + QByteArray::number(i);
        QByteArray f = "<g visibility=\"hidden\"><set attributeName=\"visibility\" to=\"visible\" begin=\"";
        f += seconds(i / fps) + "\" dur=\"" + frameDur + '"';
        if (i + 1 == frames)
            f += " fill=\"freeze\"";
        f += "/>";
        if (headMoves)
            f += "<g transform=\"" + d.svg.headTransform(pose.head).toLatin1() + "\">";
        for (auto it = clipTarget.cbegin(); it != clipTarget.cend(); ++it)
            f += "<clipPath id=\"" + it.key() + suffix + "\"><use xlink:href=\"#" + it.value() + suffix
                + "\"/></clipPath>";
        for (const Item &item : items) {
            if (!item.node) {
                f += "<use xlink:href=\"#tf-shared-" + QByteArray::number(item.run) + "\"/>";
                continue;
            }
            const int p = partOf.value(item.node->attribute("id"));
            XmlNode e = *item.node;
            for (auto &[k, v] : e.attributes) {
                if (k == "id") {
                    v += suffix;
                } else if (k == "clip-path") {
                    const QByteArray clip = v.mid(5, v.size() - 6); // url(#...)
                    if (clipTarget.contains(clip))
                        v = "url(#" + clip + suffix + ')';
                } else if (p < parts.size() && parts[p].geometry.contains(QString::fromLatin1(k))) {
                    const QByteArray text = parts[p].geometry.value(QString::fromLatin1(k)).toLatin1();
                    QVector<double> numbers;
                    QByteArray commands;
                    QVector<qint64> q;
                    if (k == "d" && parsePath(text, &numbers, &commands)) {
                        for (double x : numbers)
                            q.append(quantize(x, 1));
                        v.clear();
                        if (relativeWritable(commands))
                            appendRelativePath(v, commands, q.constData(), 1);
                        else
                            appendAbsolutePath(v, commands, q.constData(), 1);
                    } else if (k != "d") {
                        QByteArray letters;
                        parseNumbers(text, &numbers, &letters);
                        if (!letters.isEmpty() || numbers.isEmpty()) {
                            v = text;
                            continue;
                        }
                        Channel c;
                        c.kind = numbers.size() == 1 ? ChannelKind::Number : ChannelKind::Points;
                        c.size = int(numbers.size());
                        for (double x : numbers)
                            q.append(quantize(x, 1));
                        v.clear();
                        appendValue(v, c, q.constData());
                    } else {
                        v = text;
                    }
                }
            }
            writeXml(f, e, {});
        }
        if (headMoves)
            f += "</g>";
        f += "</g>\n";
        return f;
    };

    constexpr int kChunk = 256;
    for (int first = 0; first < frames; first += kChunk) {
        if (cancelled(options)) {
            *error = ExportText::tr("cancelled");
            return false;
        }
        const int count = std::min(kChunk, frames - first);
        QVector<QByteArray> texts(count);
        forEachParallel(count, [&](qsizetype i) { texts[i] = frameText(first + int(i)); });
        for (const QByteArray &t : texts)
            *out += t;
        report(options, double(first + count) / frames);
    }
    *out += "</g>\n";
    // The user's layers, and anything else after the head group, as they were.
    bool afterHead = false;
    for (const XmlNode &c : d.document.children) {
        if (&c == head) {
            afterHead = true;
            continue;
        }
        if (afterHead)
            writeXml(*out, c, {});
    }
    if (!audio.uri.isEmpty())
        *out += playerScript(viewBoxOf(d.document));
    *out += "</svg>\n";
    return true;
}

struct Prepared
{
    TimelineEvaluator evaluator;
    Drawing drawing;
    SmilAudio audio;
};

std::optional<Prepared> prepare(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    Prepared p {TimelineEvaluator(timeline, face, shapes), {SvgFace(face, style), {}, {}, {}, {}}, {}};
    // Browsers clip the eyeballs by the eye outline: the skin covers for renderers that cannot
    // (SvgFace) would only add two animated paths. The frame mode is for old players: it keeps them.
    p.drawing.svg.setEyeCovers(options.mode == AnimationExportOptions::Mode::Frames);
    p.drawing.svg.setFrame(options.frame);
    if (!prepareDrawing(timeline, shapes, p.evaluator, options, &p.drawing, error)
        || !resolveAudio(timeline, p.evaluator.duration(), options, &p.audio, error))
        return std::nullopt;
    report(options, 0.0);
    return p;
}

} // namespace

QByteArray exportSmilSvg(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    QString why;
    QByteArray out;
    const std::optional<Prepared> p = prepare(face, style, timeline, shapes, options, &why);
    const bool ok = p
        && (options.mode == AnimationExportOptions::Mode::Frames
                ? framesDocument(p->drawing, p->evaluator, timeline, p->audio, options, &out, &why)
                : smilDocument(p->drawing, p->evaluator, timeline, p->audio, true, options, &out, &why));
    if (!ok) {
        if (error)
            *error = why;
        return {};
    }
    report(options, 1.0);
    return out;
}

std::optional<SmilElement> exportSmilElement(const FaceModel &face, const Style &style, const Timeline &timeline,
    const MouthShapeSet &shapes, const AnimationExportOptions &options, QString *error)
{
    QString why;
    SmilElement e;
    const std::optional<Prepared> p = prepare(face, style, timeline, shapes, options, &why);
    if (!p || !smilDocument(p->drawing, p->evaluator, timeline, p->audio, false, options, &e.svg, &why)) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    e.audioUri = p->audio.uri;
    e.audioOffset = p->audio.offset;
    e.audioDuration = p->audio.duration;
    e.duration = p->evaluator.duration();
    report(options, 1.0);
    return e;
}

} // namespace toonface
