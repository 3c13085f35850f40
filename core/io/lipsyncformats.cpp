#include "io/lipsyncformats.h"

#include "i18n/coretext.h"
#include "io/jsonfield.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSaveFile>

#include <algorithm>
#include <cmath>

namespace toonface {

namespace {

QString latin(const char *s)
{
    return QString::fromLatin1(s);
}

} // namespace

// ---- ShapeMapping

ShapeMapping ShapeMapping::rhubarb()
{
    ShapeMapping m;
    m.m_caseSensitive = true;
    const std::array<const char *, kMouthShapeCount> names = {"A", "G", "B", "D", "B", "F", "C", "E", "H"};
    for (MouthShape s : kAllMouthShapes) {
        m.m_export[int(s)] = latin(names[int(s)]);
        m.m_import.insert(mouthShapeName(s), s); // Toonface's own names
    }
    const std::array<std::pair<const char *, MouthShape>, 8> letters
        = {{{"A", MouthShape::M}, {"B", MouthShape::I}, {"C", MouthShape::E}, {"D", MouthShape::A},
            {"E", MouthShape::O}, {"F", MouthShape::U}, {"G", MouthShape::F}, {"H", MouthShape::N}}};
    for (const auto &[name, shape] : letters)
        m.m_import.insert(latin(name), shape);
    m.setRestName(QStringLiteral("X"));
    return m;
}

ShapeMapping ShapeMapping::prestonBlair()
{
    ShapeMapping m;
    m.m_caseSensitive = false;
    const std::array<const char *, kMouthShapeCount> names = {"MBP", "FV", "etc", "AI", "E", "U", "E", "O", "L"};
    for (MouthShape s : kAllMouthShapes)
        m.m_export[int(s)] = latin(names[int(s)]);
    const std::array<std::pair<const char *, MouthShape>, 9> phonemes = {{{"MBP", MouthShape::M}, {"FV", MouthShape::F},
        {"etc", MouthShape::H}, {"AI", MouthShape::A}, {"E", MouthShape::I}, {"U", MouthShape::U}, {"O", MouthShape::O},
        {"L", MouthShape::N}, {"WQ", MouthShape::U}}};
    for (const auto &[name, shape] : phonemes)
        m.m_import.insert(m.key(latin(name)), shape);
    m.setRestName(QStringLiteral("rest"));
    return m;
}

void ShapeMapping::setRestName(const QString &name)
{
    m_rest = name;
    m_import.insert(key(name), std::nullopt);
}

ShapeMapping::Match ShapeMapping::importName(const QString &name, MouthShape *shape) const
{
    const auto it = m_import.constFind(key(name));
    if (it == m_import.cend())
        return Match::Unknown;
    if (!it->has_value())
        return Match::Rest;
    *shape = **it;
    return Match::Shape;
}

void ShapeMapping::setImportShape(const QString &name, std::optional<MouthShape> shape)
{
    m_import.insert(key(name), shape);
}

QStringList ShapeMapping::importNames() const
{
    QStringList names = m_import.keys();
    names.sort();
    return names;
}

// ---- formats

std::optional<LipSyncFormat> lipSyncFormatForPath(const QString &path)
{
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext == u"tsv")
        return LipSyncFormat::RhubarbTsv;
    if (ext == u"json")
        return LipSyncFormat::RhubarbJson;
    if (ext == u"pgo")
        return LipSyncFormat::Papagayo;
    if (ext == u"dat")
        return LipSyncFormat::MohoSwitch;
    return std::nullopt;
}

QString lipSyncFormatName(LipSyncFormat format)
{
    switch (format) {
    case LipSyncFormat::RhubarbTsv: return QStringLiteral("Rhubarb TSV");
    case LipSyncFormat::RhubarbJson: return QStringLiteral("Rhubarb JSON");
    case LipSyncFormat::Papagayo: return QStringLiteral("Papagayo");
    case LipSyncFormat::MohoSwitch: return QStringLiteral("Moho switch");
    }
    return {};
}

namespace {

ShapeMapping mappingFor(LipSyncFormat format, const LipSyncOptions &options)
{
    if (options.mapping)
        return *options.mapping;
    const bool rhubarb = format == LipSyncFormat::RhubarbTsv || format == LipSyncFormat::RhubarbJson;
    return rhubarb ? ShapeMapping::rhubarb() : ShapeMapping::prestonBlair();
}

// A cue on a frame grid: sounded from frame `start` up to (not including) frame `end`.
struct FrameCue
{
    int start;
    int end;
    MouthShape shape;
};

QVector<FrameCue> toFrames(const QVector<MouthCue> &cues, double fps)
{
    QVector<FrameCue> frames;
    for (const MouthCue &c : cues) {
        const int start = int(std::lround(c.start * fps));
        const int end = int(std::lround(c.end * fps));
        if (end > start)
            frames.append({start, end, c.shape});
    }
    return frames;
}

// One line of a file: what the file says from `time` on (a shape, or rest when nullopt).
struct Event
{
    double time;
    std::optional<MouthShape> shape;
};

// Each shape event lasts until the next event; the last for `lastDuration`.
QVector<MouthCue> eventsToCues(const QVector<Event> &events, double lastDuration)
{
    QVector<MouthCue> cues;
    for (qsizetype i = 0; i < events.size(); ++i) {
        if (!events[i].shape)
            continue;
        const double start = events[i].time;
        const double end = i + 1 < events.size() ? events[i + 1].time : start + lastDuration;
        if (end > start)
            cues.append({start, end, *events[i].shape});
    }
    return cues;
}

QByteArray joinLines(const QStringList &lines)
{
    return (lines.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8();
}

// The lines of a text file with their 1-based numbers; CR LF and a UTF-8 BOM are accepted.
class LineReader
{
public:
    LineReader(const QByteArray &data, const QString &fileName)
        : m_fileName(fileName)
    {
        QString text = QString::fromUtf8(data);
        if (text.startsWith(QChar(0xfeff)))
            text.remove(0, 1);
        m_lines = text.split(QLatin1Char('\n'));
        if (!m_lines.isEmpty() && m_lines.last().isEmpty())
            m_lines.removeLast(); // the final newline ends a line, it does not start one
        for (QString &l : m_lines) {
            if (l.endsWith(QLatin1Char('\r')))
                l.chop(1);
        }
    }

    bool atEnd() const { return m_next >= m_lines.size(); }
    int lineNumber() const { return int(m_next); } // of the line last read
    // The next line with surrounding white space removed, or false at the end of the file
    // (setting the error "unexpected end of file, expected <what>").
    bool next(QString *line, const QString &what, QString *error)
    {
        if (atEnd())
            return failAt(
                int(m_lines.size()) + 1, LipSyncText::tr("unexpected end of file, expected %1").arg(what), error);
        *line = m_lines[m_next++].trimmed();
        return true;
    }
    bool nextInt(int min, int *out, const QString &what, QString *error)
    {
        QString line;
        if (!next(&line, what, error))
            return false;
        return toInt(line, min, out, what, error);
    }
    bool toInt(const QString &text, int min, int *out, const QString &what, QString *error) const
    {
        bool ok = false;
        const int v = text.toInt(&ok);
        if (!ok || v < min)
            return fail(
                LipSyncText::tr("expected %1 (an integer of at least %2), found '%3'").arg(what).arg(min).arg(text),
                error);
        *out = v;
        return true;
    }
    bool fail(const QString &problem, QString *error) const { return failAt(lineNumber(), problem, error); }
    bool failAt(int line, const QString &problem, QString *error) const
    {
        if (error)
            *error = LipSyncText::tr("%1: line %2: %3").arg(m_fileName, QString::number(line), problem);
        return false;
    }

private:
    QString m_fileName;
    QStringList m_lines;
    qsizetype m_next = 0;
};

QStringList splitFields(const QString &line)
{
    static const QRegularExpression space(QStringLiteral("\\s+"));
    return line.split(space, Qt::SkipEmptyParts);
}

// A name of a line: a shape, or rest; false (with a line-numbered error) when unknown.
bool lookUp(const ShapeMapping &mapping, const QString &name, const LineReader &reader, std::optional<MouthShape> *out,
    QString *error)
{
    MouthShape shape = MouthShape::M;
    switch (mapping.importName(name, &shape)) {
    case ShapeMapping::Match::Shape: *out = shape; return true;
    case ShapeMapping::Match::Rest: *out = std::nullopt; return true;
    case ShapeMapping::Match::Unknown: break;
    }
    return reader.fail(LipSyncText::tr("unknown mouth shape '%1' (known: %2)")
                           .arg(name, mapping.importNames().join(QStringLiteral(", "))),
        error);
}

// ---- Rhubarb TSV

QString tsvTime(double t)
{
    return QString::number(t, 'f', 3);
}

QByteArray writeTsv(const LipSyncTrack &track, const ShapeMapping &mapping)
{
    QStringList lines;
    const QString tab = QStringLiteral("\t");
    double reached = 0;
    for (qsizetype i = 0; i < track.cues.size(); ++i) {
        const MouthCue &c = track.cues[i];
        if (c.start > reached)
            lines.append(tsvTime(reached) + tab + mapping.restName());
        lines.append(tsvTime(c.start) + tab + mapping.exportName(c.shape));
        reached = c.end;
    }
    lines.append(tsvTime(reached) + tab + mapping.restName());
    return joinLines(lines);
}

std::optional<LipSyncTrack> parseTsv(
    const QByteArray &data, const QString &fileName, const ShapeMapping &mapping, double fps, QString *error)
{
    LineReader reader(data, fileName);
    QVector<Event> events;
    QString line;
    while (!reader.atEnd()) {
        reader.next(&line, {}, error);
        if (line.isEmpty())
            continue;
        const QStringList fields = splitFields(line);
        if (fields.size() != 2) {
            reader.fail(LipSyncText::tr("expected 'start<TAB>shape', found '%1'").arg(line), error);
            return std::nullopt;
        }
        bool ok = false;
        const double t = fields[0].toDouble(&ok);
        if (!ok || !std::isfinite(t) || t < 0) {
            reader.fail(
                LipSyncText::tr("expected a start time in seconds (a number of at least 0), found '%1'").arg(fields[0]),
                error);
            return std::nullopt;
        }
        if (!events.isEmpty() && t < events.last().time) {
            reader.fail(
                LipSyncText::tr("time %1 is before the previous line's %2").arg(fields[0]).arg(events.last().time),
                error);
            return std::nullopt;
        }
        std::optional<MouthShape> shape;
        if (!lookUp(mapping, fields[1], reader, &shape, error))
            return std::nullopt;
        events.append({t, shape});
    }
    LipSyncTrack track;
    track.cues = eventsToCues(events, 1.0 / fps);
    return track;
}

// ---- Rhubarb JSON

QByteArray writeJson(const LipSyncTrack &track, const ShapeMapping &mapping)
{
    const double lastEnd = track.cues.isEmpty() ? 0.0 : track.cues.last().end;
    const double duration = std::max(track.duration, lastEnd);
    QJsonArray cues;
    auto append = [&cues](double start, double end, const QString &value) {
        cues.append(QJsonObject {
            {QStringLiteral("start"), start}, {QStringLiteral("end"), end}, {QStringLiteral("value"), value}});
    };
    double reached = 0;
    for (const MouthCue &c : track.cues) {
        if (c.start > reached)
            append(reached, c.start, mapping.restName());
        append(c.start, c.end, mapping.exportName(c.shape));
        reached = c.end;
    }
    if (duration > reached)
        append(reached, duration, mapping.restName());
    const QJsonObject metadata {{QStringLiteral("soundFile"), track.soundFile}, {QStringLiteral("duration"), duration}};
    const QJsonObject root {{QStringLiteral("metadata"), metadata}, {QStringLiteral("mouthCues"), cues}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<LipSyncTrack> parseJson(
    const QByteArray &data, const QString &fileName, const ShapeMapping &mapping, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const QByteArray before = data.left(parseError.offset);
        const int line = int(before.count('\n')) + 1;
        if (error)
            *error = LipSyncText::tr("%1: line %2: not valid JSON: %3")
                         .arg(fileName)
                         .arg(line)
                         .arg(parseError.errorString());
        return std::nullopt;
    }
    auto failField = [&](const QString &problem) {
        if (error)
            *error = withProblem(fileName, problem);
        return std::nullopt;
    };
    if (!doc.isObject())
        return failField(LipSyncText::tr("expected a JSON object with mouthCues"));
    const JsonField root(doc.object(), {});
    QString problem;
    LipSyncTrack track;
    const JsonField metadata = root.member("metadata");
    if (!metadata.isMissing()) {
        QJsonObject unused;
        if (!metadata.toObject(&unused, &problem))
            return failField(problem);
        const JsonField sound = metadata.member("soundFile");
        if (!sound.isMissing() && !sound.toString(&track.soundFile, &problem))
            return failField(problem);
        const JsonField duration = metadata.member("duration");
        if (!duration.isMissing()) {
            if (!duration.toNumber(&track.duration, &problem))
                return failField(problem);
            if (track.duration < 0)
                return failField(LipSyncText::tr("%1: expected a duration of at least 0").arg(duration.path()));
        }
    }
    const JsonField cuesField = root.member("mouthCues");
    QJsonArray cues;
    if (!cuesField.toArray(&cues, &problem))
        return failField(problem);
    double previousEnd = 0;
    for (qsizetype i = 0; i < cues.size(); ++i) {
        const JsonField cue = cuesField.at(i);
        double start = 0;
        double end = 0;
        if (!cue.member("start").toNumber(&start, &problem) || !cue.member("end").toNumber(&end, &problem))
            return failField(problem);
        if (start < 0)
            return failField(LipSyncText::tr("%1: expected a time of at least 0").arg(cue.member("start").path()));
        if (end < start)
            return failField(LipSyncText::tr("%1: ends (%2) before it starts (%3)")
                                 .arg(cue.member("end").path(), QString::number(end), QString::number(start)));
        if (start < previousEnd - 1e-9)
            return failField(
                LipSyncText::tr("%1: starts (%2) before the previous cue ends (%3)")
                    .arg(cue.member("start").path(), QString::number(start), QString::number(previousEnd)));
        const JsonField valueField = cue.member("value").isMissing() ? cue.member("shape") : cue.member("value");
        QString value;
        if (!valueField.toString(&value, &problem))
            return failField(problem);
        MouthShape shape = MouthShape::M;
        switch (mapping.importName(value, &shape)) {
        case ShapeMapping::Match::Shape:
            if (end > start)
                track.cues.append({start, end, shape});
            break;
        case ShapeMapping::Match::Rest: break;
        case ShapeMapping::Match::Unknown:
            return failField(LipSyncText::tr("%1: unknown mouth shape '%2' (known: %3)")
                                 .arg(valueField.path(), value, mapping.importNames().join(QStringLiteral(", "))));
        }
        previousEnd = end;
    }
    return track;
}

// ---- Papagayo

QByteArray writePapagayo(const LipSyncTrack &track, const ShapeMapping &mapping, double fps)
{
    const int rate = std::max(1, int(std::lround(fps)));
    const QVector<FrameCue> frames = toFrames(track.cues, rate);
    const int lastEnd = frames.isEmpty() ? 0 : frames.last().end;
    const int durationFrames = std::max(lastEnd, int(std::ceil(track.duration * rate - 1e-6)));

    // Phrases: runs of cues with no silence between them.
    QVector<QVector<FrameCue>> phrases;
    for (const FrameCue &f : frames) {
        if (phrases.isEmpty() || phrases.last().last().end != f.start)
            phrases.append(QVector<FrameCue>());
        phrases.last().append(f);
    }
    auto phraseText = [](const QVector<FrameCue> &phrase) {
        QStringList words;
        for (const FrameCue &f : phrase)
            words.append(mouthShapeName(f.shape));
        return words.join(QLatin1Char(' '));
    };

    QStringList lines = {QStringLiteral("lipsync version 1"), track.soundFile, QString::number(rate),
        QString::number(durationFrames), QStringLiteral("1"), QStringLiteral("\tVoice 1")};
    QStringList texts;
    for (const auto &phrase : phrases)
        texts.append(phraseText(phrase));
    lines.append(QLatin1Char('\t') + texts.join(QLatin1Char('|')));
    lines.append(QLatin1Char('\t') + QString::number(phrases.size()));
    for (const auto &phrase : phrases) {
        lines.append(QStringLiteral("\t\t") + phraseText(phrase));
        lines.append(QStringLiteral("\t\t") + QString::number(phrase.first().start));
        lines.append(QStringLiteral("\t\t") + QString::number(phrase.last().end - 1));
        lines.append(QStringLiteral("\t\t") + QString::number(phrase.size()));
        for (const FrameCue &f : phrase) {
            lines.append(QStringLiteral("\t\t\t%1 %2 %3 1").arg(mouthShapeName(f.shape)).arg(f.start).arg(f.end - 1));
            lines.append(QStringLiteral("\t\t\t\t%1 %2").arg(f.start).arg(mapping.exportName(f.shape)));
        }
    }
    return joinLines(lines);
}

std::optional<LipSyncTrack> parsePapagayo(
    const QByteArray &data, const QString &fileName, const ShapeMapping &mapping, QString *error)
{
    LineReader reader(data, fileName);
    QString line;
    if (!reader.next(&line, LipSyncText::tr("the header 'lipsync version 1'"), error))
        return std::nullopt;
    if (line.compare(u"lipsync version 1", Qt::CaseInsensitive) != 0) {
        reader.fail(LipSyncText::tr("expected the header 'lipsync version 1', found '%1'").arg(line), error);
        return std::nullopt;
    }
    LipSyncTrack track;
    int fps = 0;
    int durationFrames = 0;
    int voices = 0;
    if (!reader.next(&track.soundFile, LipSyncText::tr("the sound file"), error)
        || !reader.nextInt(1, &fps, LipSyncText::tr("the frame rate"), error)
        || !reader.nextInt(0, &durationFrames, LipSyncText::tr("the duration in frames"), error)
        || !reader.nextInt(0, &voices, LipSyncText::tr("the number of voices"), error))
        return std::nullopt;
    track.duration = double(durationFrames) / fps;
    if (voices == 0)
        return track;

    QString voiceName;
    QString voiceText;
    int phrases = 0;
    if (!reader.next(&voiceName, LipSyncText::tr("the voice's name"), error)
        || !reader.next(&voiceText, LipSyncText::tr("the voice's text"), error)
        || !reader.nextInt(0, &phrases, LipSyncText::tr("the number of phrases"), error))
        return std::nullopt;
    QVector<MouthCue> cues;
    for (int p = 0; p < phrases; ++p) {
        QString text;
        int start = 0;
        int end = 0;
        int words = 0;
        if (!reader.next(&text, LipSyncText::tr("the text of phrase %1").arg(p + 1), error)
            || !reader.nextInt(0, &start, LipSyncText::tr("the start frame of phrase %1").arg(p + 1), error)
            || !reader.nextInt(0, &end, LipSyncText::tr("the end frame of phrase %1").arg(p + 1), error)
            || !reader.nextInt(0, &words, LipSyncText::tr("the number of words of phrase %1").arg(p + 1), error))
            return std::nullopt;
        for (int w = 0; w < words; ++w) {
            const QString what
                = LipSyncText::tr("word %1 of phrase %2 ('text start end phonemes')").arg(w + 1).arg(p + 1);
            if (!reader.next(&line, what, error))
                return std::nullopt;
            const QStringList fields = splitFields(line);
            if (fields.size() < 4) {
                reader.fail(LipSyncText::tr("expected %1, found '%2'").arg(what, line), error);
                return std::nullopt;
            }
            const QString wordText = fields.mid(0, fields.size() - 3).join(QLatin1Char(' '));
            int wordStart = 0;
            int wordEnd = 0;
            int phonemes = 0;
            const qsizetype n = fields.size();
            if (!reader.toInt(
                    fields[n - 3], 0, &wordStart, LipSyncText::tr("the start frame of '%1'").arg(wordText), error)
                || !reader.toInt(
                    fields[n - 2], 0, &wordEnd, LipSyncText::tr("the end frame of '%1'").arg(wordText), error)
                || !reader.toInt(
                    fields[n - 1], 0, &phonemes, LipSyncText::tr("the phoneme count of '%1'").arg(wordText), error))
                return std::nullopt;
            if (wordEnd < wordStart) {
                reader.fail(LipSyncText::tr("word '%1' ends (frame %2) before it starts (frame %3)")
                                .arg(wordText)
                                .arg(wordEnd)
                                .arg(wordStart),
                    error);
                return std::nullopt;
            }
            QVector<Event> events;
            for (int k = 0; k < phonemes; ++k) {
                const QString phonemeWhat
                    = LipSyncText::tr("phoneme %1 of '%2' ('frame name')").arg(k + 1).arg(wordText);
                if (!reader.next(&line, phonemeWhat, error))
                    return std::nullopt;
                const QStringList pf = splitFields(line);
                int frame = 0;
                if (pf.size() != 2) {
                    reader.fail(LipSyncText::tr("expected %1, found '%2'").arg(phonemeWhat, line), error);
                    return std::nullopt;
                }
                if (!reader.toInt(pf[0], 0, &frame, LipSyncText::tr("the frame of a phoneme"), error))
                    return std::nullopt;
                if (!events.isEmpty() && frame < events.last().time) {
                    reader.fail(LipSyncText::tr("phoneme frame %1 is before the previous phoneme's %2")
                                    .arg(frame)
                                    .arg(events.last().time),
                        error);
                    return std::nullopt;
                }
                std::optional<MouthShape> shape;
                if (!lookUp(mapping, pf[1], reader, &shape, error))
                    return std::nullopt;
                events.append({double(frame), shape});
            }
            // The word's last phoneme lasts to the end of the word's last frame.
            events.append({double(wordEnd + 1), std::nullopt});
            for (MouthCue c : eventsToCues(events, 0)) {
                c.start /= fps;
                c.end /= fps;
                cues.append(c);
            }
        }
    }
    std::stable_sort(cues.begin(), cues.end(), [](const MouthCue &a, const MouthCue &b) { return a.start < b.start; });
    // Papagayo keeps words apart; a hand-edited file may not.
    for (qsizetype i = 0; i + 1 < cues.size(); ++i)
        cues[i].end = std::min(cues[i].end, cues[i + 1].start);
    cues.removeIf([](const MouthCue &c) { return c.end <= c.start; });
    track.cues = cues;
    return track;
}

// ---- Moho switch

QByteArray writeMoho(const LipSyncTrack &track, const ShapeMapping &mapping, double fps)
{
    const QVector<FrameCue> frames = toFrames(track.cues, fps);
    QStringList lines = {QStringLiteral("MohoSwitch1")};
    auto line = [&](int frame, const QString &name) { lines.append(QStringLiteral("%1 %2").arg(frame + 1).arg(name)); };
    int reached = 0;
    for (const FrameCue &f : frames) {
        if (f.start > reached)
            line(reached, mapping.restName());
        line(f.start, mapping.exportName(f.shape));
        reached = f.end;
    }
    line(reached, mapping.restName());
    return joinLines(lines);
}

std::optional<LipSyncTrack> parseMoho(
    const QByteArray &data, const QString &fileName, const ShapeMapping &mapping, double fps, QString *error)
{
    LineReader reader(data, fileName);
    QString line;
    if (!reader.next(&line, LipSyncText::tr("the header 'MohoSwitch1'"), error))
        return std::nullopt;
    if (line.compare(u"MohoSwitch1", Qt::CaseInsensitive) != 0) {
        reader.fail(LipSyncText::tr("expected the header 'MohoSwitch1', found '%1'").arg(line), error);
        return std::nullopt;
    }
    QVector<Event> events;
    int previous = 0;
    while (!reader.atEnd()) {
        reader.next(&line, {}, error);
        if (line.isEmpty())
            continue;
        const QStringList fields = splitFields(line);
        if (fields.size() != 2) {
            reader.fail(LipSyncText::tr("expected 'frame shape', found '%1'").arg(line), error);
            return std::nullopt;
        }
        int frame = 0;
        if (!reader.toInt(fields[0], 0, &frame, LipSyncText::tr("a frame number"), error))
            return std::nullopt;
        if (frame < previous) {
            reader.fail(
                LipSyncText::tr("frame %1 is before the previous line's frame %2").arg(frame).arg(previous), error);
            return std::nullopt;
        }
        previous = frame;
        std::optional<MouthShape> shape;
        if (!lookUp(mapping, fields[1], reader, &shape, error))
            return std::nullopt;
        // Moho counts frames from 1 (frame 0 is the set-up frame, shown at the start too).
        events.append({std::max(0, frame - 1) / fps, shape});
    }
    LipSyncTrack track;
    track.cues = eventsToCues(events, 1.0 / fps);
    return track;
}

} // namespace

QByteArray writeLipSync(const LipSyncTrack &track, LipSyncFormat format, const LipSyncOptions &options)
{
    const ShapeMapping mapping = mappingFor(format, options);
    switch (format) {
    case LipSyncFormat::RhubarbTsv: return writeTsv(track, mapping);
    case LipSyncFormat::RhubarbJson: return writeJson(track, mapping);
    case LipSyncFormat::Papagayo: return writePapagayo(track, mapping, options.fps);
    case LipSyncFormat::MohoSwitch: return writeMoho(track, mapping, options.fps);
    }
    return {};
}

std::optional<LipSyncTrack> parseLipSync(const QByteArray &data, LipSyncFormat format, const QString &fileName,
    const LipSyncOptions &options, QString *error)
{
    if (!(options.fps > 0) || !std::isfinite(options.fps)) {
        if (error)
            *error = LipSyncText::tr("%1: cannot read at %2 frames per second").arg(fileName).arg(options.fps);
        return std::nullopt;
    }
    const ShapeMapping mapping = mappingFor(format, options);
    switch (format) {
    case LipSyncFormat::RhubarbTsv: return parseTsv(data, fileName, mapping, options.fps, error);
    case LipSyncFormat::RhubarbJson: return parseJson(data, fileName, mapping, error);
    case LipSyncFormat::Papagayo: return parsePapagayo(data, fileName, mapping, error);
    case LipSyncFormat::MohoSwitch: return parseMoho(data, fileName, mapping, options.fps, error);
    }
    return std::nullopt;
}

bool saveLipSync(
    const LipSyncTrack &track, const QString &path, LipSyncFormat format, const LipSyncOptions &options, QString *error)
{
    QSaveFile file(path);
    const QByteArray data = writeLipSync(track, format, options);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        if (error)
            *error = LipSyncText::tr("%1: not saved: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

std::optional<LipSyncTrack> loadLipSync(
    const QString &path, std::optional<LipSyncFormat> format, const LipSyncOptions &options, QString *error)
{
    if (!format)
        format = lipSyncFormatForPath(path);
    if (!format) {
        if (error)
            *error = LipSyncText::tr("%1: unknown lip-sync format (expected .tsv, .json, .pgo or .dat)").arg(path);
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = LipSyncText::tr("%1: cannot read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return parseLipSync(file.readAll(), *format, path, options, error);
}

} // namespace toonface
